# language: zh-CN
@item:R-DIA-03 @profile:crh2
功能: R-DIA-03 DI/DO诊断
  例行试验,诊断。需求:FS-02(主)、FS-01、FS-03、TST-03。
  指令板检查其数字输入输出:CPU组间不一致时切断输出并显示在司机室监视器上;司机台输入失电按安全状态读取。

  背景:
    假如一列8辆编组的CRH2动车组
    而且司机已在1号司机室插入钥匙
    而且1号司机室的方向开关在前进位
    而且1号司机室的牵引手柄在2级
    而且列车已上电1000 ms

  @req:FS-02 @req:TST-03
  场景: R-DIA-03 CPU组读入不同输入的TXC显示为故障
    当板卡"car1.CCU.sys1.TXC.group2"故障
    而且经过500 ms
    那么1号司机室监视器显示"car1.CCU.sys1.TXC故障"

  @req:FS-01 @req:TST-03
  场景: R-DIA-03 CPU组不一致的RXC显示为故障
    当板卡"car4.LCU.RXC.group2"故障
    而且经过500 ms
    那么1号司机室监视器显示"car4.LCU.RXC故障"

  @req:FS-03 @req:TST-03
  场景: R-DIA-03 输入电源失电的司机台发出制动而非牵引
    当电源"car1.desk"被关断
    而且经过200 ms
    那么20 ms起每条命令都带牵引级位0和制动级位7
