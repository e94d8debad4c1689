@item:F-NET-24 @profile:metro-tcn @req:TST-04
Feature: F-NET-24 MVB frames and data classes on the wire
  Requirements: TCN-05 (primary), TCN-06, TCN-10, TST-04.
  A bus analyser decodes every frame on an MVB with the suite's own IEC 61375-3-1 codec: master frames of
  F_code, address and check sequence; slave frames of the size the F_code asks, a check sequence after
  16, 32 or 64 bits and after every 64 bits beyond. A frame that does not decode fails the item, so a SUT
  with its own check-sequence layout is rejected even if it understands itself; so does a master frame with
  a reserved F_code (5-7, 10-11), or a slave frame answering one (docs/decisions.md).

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And an analyser is attached to "unit1.MVB"
    And an analyser is attached to "unit2.MVB"
    And the driver has inserted the key in cab 1
    And the train has been powered up for 100 ms

  @req:TCN-05 @req:TCN-10
  Scenario Outline: F-NET-24 Every frame on "<bus>" decodes with the standard check sequences
    When 100 ms pass
    Then every frame on "<bus>" decodes as an IEC 61375-3-1 MVB frame of the size its F_code asks
    And every master frame on "<bus>" carries the address of the port or device that answers it, one address each

    Examples:
      | bus       |
      | unit1.MVB |
      | unit2.MVB |

  @req:TCN-06
  Scenario: F-NET-24 Process data is polled cyclically, device status as supervisory data
    When 200 ms pass
    Then the master frames on "unit1.MVB" ask for process data and supervisory data
    And every process-data port on "unit1.MVB" is polled at one fixed period of at most 16 ms
