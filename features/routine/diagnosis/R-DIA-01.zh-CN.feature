# language: zh-CN
@item:R-DIA-01 @profile:crh2
功能: R-DIA-01 光传输诊断
  例行试验,诊断。需求:NET-03(主)、TST-03。
  光纤链路断开由其两侧节点的状态数据报告,并显示在司机室监视器上。

  背景:
    假如一列8辆编组的CRH2动车组
    而且司机已在1号司机室插入钥匙
    而且列车已上电1000 ms

  @req:NET-03 @req:TST-03
  场景: R-DIA-01 司机室监视器在500 ms内指出断开的光纤链路
    当"car3.LCU"与"car4.LCU"之间的环网链路断开
    而且经过500 ms
    那么1号司机室监视器显示"optical transmission fault between car3.LCU and car4.LCU"

  @req:NET-03 @req:TST-03
  场景: R-DIA-01 完好的环网不显示光传输故障
    当经过500 ms
    那么1号司机室监视器不显示任何故障
