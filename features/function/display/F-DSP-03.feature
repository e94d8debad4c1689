@item:F-DSP-03 @profile:crh2
Feature: F-DSP-03 Both cab monitors display the same values
  Requirements: PRO-02 (primary), ILK-07, TST-04.
  Both monitors take their values from the same status data, so the monitor of the cab without the key
  shows what the commanding cab ordered and what the train does, value for value. Orders given on the
  other cab's monitor are void (ILK-07), even with a second key in that cab: neither monitor shows them.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:PRO-02 @req:TST-04
  Scenario: F-DSP-03 The cab 8 monitor displays what was ordered on the cab 1 monitor
    When the driver orders "car4.air conditioning" to "off" on the cab 1 monitor
    And 300 ms pass
    Then the cab 1 monitor changes "car4.air conditioning" to "off" within 300 ms
    And the cab 8 monitor changes "car4.air conditioning" to "off" within 300 ms
    When the driver orders "passenger information" to "next station" on the cab 1 monitor
    And 300 ms pass
    Then the cab 8 monitor changes "passenger information" to "next station" within 300 ms
    And the cab 1 and cab 8 monitors display the same values

  @req:PRO-02 @req:TST-04
  Scenario: F-DSP-03 Both monitors show the same running and vehicle state
    Given the train runs at 160 km/h
    And the main air pipe pressure is 720 kPa
    When the driver moves the traction notch of cab 1 to 6
    And 300 ms pass
    Then the cab 1 monitor changes "traction notch" to "6" within 200 ms
    And the cab 8 monitor changes "traction notch" to "6" within 200 ms
    And the cab 8 monitor displays "speed" between 159.5 and 160.5
    And the cab 8 monitor displays "main pipe pressure" between 719 and 721
    And the cab 1 and cab 8 monitors display the same values

  @req:ILK-07 @req:TST-04
  Scenario: F-DSP-03 An order given on the other cab's monitor is shown on neither monitor
    Given the driver has inserted the key in cab 8
    When the driver orders "car5.lighting" to "off" on the cab 8 monitor
    And 300 ms pass
    Then the "car5.lighting" stays on
    And the cab 1 monitor never displayed "car5.lighting" as "off"
    And the cab 8 monitor never displayed "car5.lighting" as "off"
    And the cab 1 and cab 8 monitors display the same values
