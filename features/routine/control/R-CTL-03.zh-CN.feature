# language: zh-CN
@item:R-CTL-03 @profile:crh2
功能: R-CTL-03 运行控制指令的备份传输
  例行试验,控制。需求:CMD-03、CMD-04、RED-01、RED-02、TST-03。
  首选路径故障时,牵引、制动指令仍能送达CI和BCU。

  背景:
    假如一列8辆编组的CRH2动车组
    而且司机已在1号司机室插入钥匙
    而且1号司机室的方向开关在前进位
    而且1号司机室的牵引手柄在4级
    而且列车已上电1000 ms

  @req:CMD-03 @req:TST-03 @tentative
  场景: R-CTL-03 MDM9故障的车改走路径2,其他车仍走路径1
    当板卡"car3.LCU.MDM9"故障
    而且经过200 ms
    那么3号车的CI和BCU在30 ms内经路径2收到牵引级位"A"
    而且40 ms起3号车以外的每个CI和BCU经路径1收到牵引级位4

  @req:CMD-04 @req:TST-03
  场景: R-CTL-03 环网中断时每辆车走路径3
    当所有环网链路断开
    而且经过300 ms
    那么每个CI和BCU在100 ms内经路径3收到牵引级位"A"

  @req:RED-01 @req:RED-02 @req:TST-03
  场景: R-CTL-03 CCU系统1失电后指令继续
    当电源"car1.CCU.sys1"被关断
    而且经过500 ms
    那么系统2的第一条命令比系统1的最后一条晚50 ms至52 ms加一个命令周期
    而且每个LCU在每条命令发出后15 ms内收到该命令
    而且没有CI或BCU超过75 ms收不到命令
