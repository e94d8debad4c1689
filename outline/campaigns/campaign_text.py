"""What the single- and double-fault campaigns (outline/campaigns/campaign.py, outline/campaigns/double_campaign.py) write alike:
the command and its bounds, the sentences a fault is told in, the Background, the invariants every scenario
checks, and an aligned Examples table."""
from __future__ import annotations

from contextlib import contextmanager
from typing import Iterator

NOTCH = 6
STEP = "B"                     # notch 6 on the digital outputs of paths 2 and 3 (CMD-03/04)

# Bounds (ms) from the articles: a command leaves the TXC at most 10 ms after the desk changed (PRO-01's
# interval), crosses the ring in at most 15 ms (PRO-01, collisions included) and reaches CI and BCU with the
# next 10 ms HDLC poll (NET-09): 40 ms with a margin. A takeover adds system 2's 50 ms of silence (RED-02);
# a fallback to path 3 the RXC's wait for the ring before it trusts the self-diagnostic line (CMD-04): the
# hand-written features give both 100 ms.
RIDE, TAKEOVER = 40, 100
# What is watched after the fault: the slowest delivery (a takeover, path 3) and as long again on the new path.
WINDOW = 2 * TAKEOVER
# A fault record reaches the master (PRO-06) once the node's request has ridden its next status data and the
# master's grant the master's next: two rounds of the token, each node holding it 10 ms (PRO-02, PRO-04), then
# the block, 10 ms after the last (PRO-06); a takeover may come first. Rounds of the composition's ring.
TOKEN_HOLD, BLOCK_GAP = 10, 10


def record_bound(ring_nodes: int) -> int:
    """ms from a fault to its record at the master, for a ring of `ring_nodes` nodes."""
    return 2 * ring_nodes * TOKEN_HOLD + TAKEOVER + BLOCK_GAP


# Under two faults the token itself may be lost (a cut while it crossed that span, a segment of a split ring
# left without it): it comes back 500 ms after it was last seen (PRO-05), formed after the initialisation at
# node number x 20 ms (PRO-03). The ring may be a line, round which the token goes out and back (PRO-04: the
# node at the fault returns it), each node holding it twice a round. The master grants one node at a time
# (PRO-06): each node with records costs its request and its grant, and the release of the grant before it.
TOKEN_LOSS, TOKEN_FORMING = 500, 20


def regenerated_record_bound(ring_nodes: int, nodes_recording: int) -> int:
    """ms from two faults to the records of `nodes_recording` nodes at the master."""
    line_round = 2 * ring_nodes * TOKEN_HOLD
    return (TOKEN_LOSS + ring_nodes * TOKEN_FORMING + nodes_recording * (2 * line_round + BLOCK_GAP)
            + TAKEOVER)

KIND_ORDER = ("span", "board", "supply")
# Per kind of fault: the hand-written features' sentence, its Examples columns, how a title names it; {n}
# numbers the placeholders where a scenario has two faults of one kind.
SENTENCES = {
    "span": ('the ring link between "<a{n}>" and "<b{n}>" is cut', ("a{n}", "b{n}"), "the ring link <a{n}>~<b{n}> cut"),
    "board": ('board "<board{n}>" fails', ("board{n}",), "board <board{n}> failed"),
    "supply": ('the supply "<supply{n}>" is switched off', ("supply{n}",), "supply <supply{n}> off"),
}


def numbered(kind: str, n: str = "") -> tuple[str, tuple[str, ...], str]:
    """A kind's sentence, columns and title phrase, its placeholders numbered n ("" for one fault of a kind)."""
    when, columns, named = SENTENCES[kind]
    return when.format(n=n), tuple(c.format(n=n) for c in columns), named.format(n=n)


def background(given: str) -> list[str]:
    return [
        "  Background:",
        f"    {given}",
        "    And the driver has inserted the key in cab 1",
        "    And the direction switch of cab 1 is at forward",
        "    And the train has been powered up for 1000 ms",
    ]


# Fail-safety over the whole trace, whatever path a car is on.
INVARIANTS = [
    f"    And no CI or BCU ever receives a traction notch other than 0 or {NOTCH}",
    "    And no command over path 2 or 3 ever carried more than the traction and brake steps A and B",
]


def examples(table: list[list[str]]) -> list[str]:
    """An Examples block, the header row first, its columns aligned."""
    widths = [max(len(row[i]) for row in table) for i in range(len(table[0]))]
    return ["    Examples:",
            *["      | " + " | ".join(cell.ljust(w) for cell, w in zip(row, widths)) + " |" for row in table]]


def example_rows(text: str) -> list[dict[str, str]]:
    """The Examples rows of a campaign feature, each as {column: value}: one per fault (or pair) it runs
    through. The inverse of `examples`, for the campaigns' --check counts and the project's tests."""
    rows, header = [], None
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("Examples:"):
            header = []
        elif header is not None and stripped.startswith("|"):
            cells = [cell.strip() for cell in stripped.strip("|").split("|")]
            if header:
                rows.append(dict(zip(header, cells)))
            else:
                header = cells
        elif stripped:
            header = None
    return rows


@contextmanager
def powered(spec: str, profile: str, sets: int, cars_per_set: int) -> Iterator:
    """The SUT `spec` opened on `profile`, composed and powered up, for reading its fault space; shut down
    afterwards."""
    from sut.backends import open_backend

    sut = open_backend(spec, profile)
    try:
        sut.configure(sets=sets, cars_per_set=cars_per_set)
        sut.power_on()
        yield sut
    finally:
        sut.shutdown()
