# language: zh-CN
@item:H-WSV-01 @profile:crh2
功能: H-WSV-01 各类单元的绝缘电阻
  硬件/软件试验,耐压(TST-02)。
  EN 50155绝缘试验:在电路与机壳之间施加500 V DC测量,单元的绝缘电阻在耐压试验前后均不小于20 MOhm。

  背景:
    假如一列8辆编组的CRH2动车组
    而且列车已上电

  @req:TST-02
  场景: H-WSV-01 每个CCU系统和每个LCU的绝缘电阻都不小于20 MOhm
    那么"car1.CCU.sys1"的绝缘电阻不小于20 MOhm
    而且"car1.CCU.sys2"的绝缘电阻不小于20 MOhm
    而且"car8.CCU.sys1"的绝缘电阻不小于20 MOhm
    而且"car1.LCU"的绝缘电阻不小于20 MOhm
    而且"car3.LCU"的绝缘电阻不小于20 MOhm
    而且"car8.LCU"的绝缘电阻不小于20 MOhm

  @req:TST-02
  场景: H-WSV-01 经过额定耐压试验后绝缘电阻仍不小于20 MOhm
    当对"car5.LCU"进行1500 V rms、60 s的耐压试验
    而且经过61 s
    那么"car5.LCU"的绝缘电阻不小于20 MOhm
