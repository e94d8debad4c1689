# language: zh-CN
@item:F-ILK-05 @profile:crh2 @req:TST-04
功能: F-ILK-05 车门:速度30 km/h以上压紧气密,低于5 km/h才能开门
  功能试验,安全联锁。需求:ILK-05(主)、TST-04。
  速度区间(docs/decisions.md):押紧电磁阀在30 km/h以上、最迟32 km/h时励磁;开门安全继电器在低于5 km/h、
  最迟4 km/h时动作,5 km/h及以上绝不动作。

  背景:
    假如一列8辆编组的CRH2动车组
    而且司机已在1号司机室插入钥匙
    而且列车已上电1000 ms

  @req:ILK-05
  场景: F-ILK-05 车门关闭时押紧电磁阀在30至32 km/h之间励磁
    当列车速度以每秒2 km/h从0 km/h变化到40 km/h
    而且经过21 s
    那么"press-seal valve"在速度处于30至32 km/h之间时变为得电

  @req:ILK-05
  场景: F-ILK-05 减速时开门安全继电器在5至4 km/h之间动作
    假如列车以20 km/h运行
    当列车速度以每秒2 km/h从20 km/h变化到0 km/h
    而且经过11 s
    那么"door-open relay"在速度处于4至5 km/h之间时变为动作

  @req:ILK-05
  场景: F-ILK-05 10 km/h时发出开门指令,车门保持关闭直到速度低于5 km/h
    假如列车以10 km/h运行
    当司机发出车门打开指令
    而且经过200 ms
    那么"doors"保持关闭
    而且"door-open relay"为释放
    当列车速度变为3 km/h
    而且经过100 ms
    那么"doors"在100 ms内变为打开

  @req:ILK-05
  场景: F-ILK-05 速度为30 km/h时押紧电磁阀保持失电
    当列车速度变为30 km/h
    而且经过1000 ms
    那么"press-seal valve"保持失电
