@item:F-NET-01
Feature: F-NET-01 Ring survives link faults

  @req:NET-03
  Scenario Outline: F-NET-01 One cut link leaves every node reachable
    Given a train of <cars> cars
    When the link between car <a> and car <b> is cut
    Then every car receives traction notch 0

    Examples:
      | cars | a | b |
      | 8    | 3 | 4 |
      | 8    | 8 | 1 |

  @req:NET-05 @pending
  Scenario: F-NET-01 A frame with a bad checksum is discarded
    Given a train of 8 cars
    When a frame with a bad checksum arrives at car 2
    Then car 2 discards it
