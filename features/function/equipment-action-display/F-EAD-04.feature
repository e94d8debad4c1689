@item:F-EAD-04 @profile:crh2
Feature: F-EAD-04 Air compressor on the cab monitor
  Requirements: TST-04 (primary).
  The compressor governor starts the air compressor below 780 kPa main air pipe pressure and stops it at
  880 kPa (docs/decisions.md, hence tentative). The monitor shows the compressor running or stopped within the
  display bound of 150 ms of the change, and shows no start while the pressure stays in the band.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the main air pipe pressure is 800 kPa
    And the train has been powered up for 1000 ms

  @req:TST-04 @tentative
  Scenario: F-EAD-04 A pressure below 780 kPa is displayed as the compressor running within 150 ms
    Then the cab 1 monitor displays "compressor" as "stopped"
    When the main air pipe pressure changes to 760 kPa
    And 150 ms pass
    Then the "compressor" is running
    And the cab 1 monitor changes "compressor" to "running" within 150 ms
    And the cab 8 monitor changes "compressor" to "running" within 150 ms

  @req:TST-04 @tentative
  Scenario: F-EAD-04 Pumping up to 880 kPa: the monitor follows the compressor stop within 150 ms
    Given the main air pipe pressure is 760 kPa
    When 300 ms pass
    And the main air pipe pressure goes from 760 kPa to 900 kPa at 100 kPa per second
    And 1500 ms pass
    Then the "compressor" is stopped
    And the cab 1 monitor follows "compressor" to "stopped" within 150 ms

  @req:TST-04 @tentative
  Scenario: F-EAD-04 Above 780 kPa the compressor is never displayed running
    When the main air pipe pressure goes from 800 kPa to 785 kPa at 50 kPa per second
    And 500 ms pass
    Then the cab 1 monitor never displayed "compressor" as "running"
    And the cab 1 monitor displays "main pipe pressure" between 784 and 786
