# language: zh-CN
@item:R-DIA-02 @profile:crh2
功能: R-DIA-02 设备传输诊断
  例行试验,诊断。需求:NET-09(主)、NET-02、TST-03。
  传输板故障或单元无响应显示在司机室监视器上。

  背景:
    假如一列8辆编组的CRH2动车组
    而且司机已在1号司机室插入钥匙
    而且列车已上电1000 ms

  @req:NET-09 @req:NET-02 @req:TST-03
  场景: R-DIA-02 MDM9(CI/BCU链路)故障显示在司机室监视器上
    当板卡"car5.LCU.MDM9"故障
    而且经过500 ms
    那么1号司机室监视器显示"car5.LCU.MDM9故障"

  @req:NET-02 @req:TST-03
  场景: R-DIA-02 失电的LCU显示为无状态数据
    当电源"car6.LCU"被关断
    而且经过1000 ms
    那么1号司机室监视器显示"car6.LCU无状态数据"
