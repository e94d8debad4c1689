"""The report's timing diagram: what it draws from a trace, and a pruned SVG that still has every shape."""
from __future__ import annotations

import re

from steps.diagram import render_svg, wavejson
from sut.trace import Trace, TraceEvent


def ev(t_ms: float, source: str, kind: str, **fields) -> TraceEvent:
    return TraceEvent(round(t_ms * 1000), source, kind, fields)


def test_nothing_changed_draws_nothing() -> None:
    trace = Trace([ev(0, "EB valve", "out.change", value="energised")])
    assert wavejson(trace, 0, 1_000_000) is None


def test_outputs_senders_and_events_become_lanes() -> None:
    trace = Trace([
        ev(0, "EB valve", "out.change", value="energised"),
        ev(100, "car1.CCU.sys1.MDM8", "cmd.tx", seq=1, system=1),
        ev(400, "main pipe pressure", "fault.board", failed=True),
        ev(500, "EB valve", "out.change", value="de-energised"),
    ])
    diagram = wavejson(trace, 0, 1_000_000)
    lanes = {lane["name"]: lane for lane in diagram["signal"]}
    assert set(lanes) == {"events", "cmd car1.CCU.sys1", "EB valve"}
    assert lanes["EB valve"]["data"] == ["energised", "de-energised"]
    assert len(lanes["EB valve"]["wave"]) <= 49 and "one slot = 50 ms" in diagram["head"]["text"]


def test_pruned_svg_keeps_every_shape_it_uses() -> None:
    diagram = {"signal": [{"name": "a", "wave": "x=.=", "data": ["on", "off"]}, {"name": "b", "wave": "1.0."}]}
    svg = render_svg(diagram)
    defined = set(re.findall(r'<g id="([^"]+)"', svg))
    used = set(re.findall(r'href="#([^"]+)"', svg))
    assert used <= defined
    assert len(svg) < 20_000


def test_the_quiet_renderer_draws_what_wavedrom_draws() -> None:
    """render_svg's renderer (svgwrite's validation off, the skin built once and shared) gives WaveDrom's own
    SVG byte for byte, picture after picture (a shared skin shape changed by one picture would show in the next)."""
    from wavedrom import WaveDrom

    diagrams = [
        {"signal": [{"name": "a", "wave": "x=.=", "data": ["on", "off"]}, {"name": "b", "wave": "1.0."}]},
        {"signal": [{"name": "events", "wave": "x2.3x", "data": ["power.on", "token.init"]},
                    {"name": "EB valve", "wave": "=.=.", "data": ["energised", "de-energised"]},
                    {"name": "bound", "wave": "0.1.0", "node": ".a.b"}],
         "edge": ["a<->b 50 ms"], "head": {"text": "one slot = 50 ms"}, "foot": {"text": "t in ms"}},
        {"signal": [{"name": "clk", "wave": "p......"}, ["group", {"name": "x", "wave": "01.zx=.", "data": "d"}]],
         "config": {"hscale": 2}},
    ]
    for diagram in diagrams + diagrams:
        assert render_svg(diagram) == render_svg(diagram, renderer=WaveDrom)


def test_a_long_run_is_drawn_in_hours_and_skipped_stretches_are_unknown_not_silent() -> None:
    hour = 3_600_000.0                                  # ms
    trace = Trace([
        ev(1000, "car1.CCU.sys1.MDM8", "cmd.tx", seq=1, system=1),
        ev(3 * hour, "train", "time.skip", frm=round(1 * hour * 1000), to=round(3 * hour * 1000)),
        ev(3 * hour + 10, "car1.CCU.sys1.MDM8", "cmd.tx", seq=2, system=1),
        ev(5 * hour, "car4.LCU.MDM9", "fault.board", failed=True),
    ])
    diagram = wavejson(trace, 0, round(6 * hour * 1000))
    lanes = {lane["name"]: lane for lane in diagram["signal"]}
    assert "one slot = 10 min" in diagram["head"]["text"]
    assert "2 h skipped" in lanes["events"]["data"]
    wave = lanes["cmd car1.CCU.sys1"]["wave"]
    assert wave[0] == "1" and wave[6] == "x" and "x" not in wave[18:]    # 1 h .. 3 h: 10-min slots 6..17


def test_a_checked_bound_is_a_lane_high_over_its_window():
    from steps.diagram import Bound, wavejson

    events = [TraceEvent(0, "car1.desk", "desk.key", {"inserted": True}),
              TraceEvent(100_000, "car1.CCU.sys1", "fault.fail", {})]
    diagram = wavejson(Trace(events), 0, 480_000, (Bound("system 2 takes over within 50 ms", 100_000, 150_000),))
    lane = next(lane for lane in diagram["signal"] if lane["name"].startswith("bound"))
    assert lane["name"] == "bound 50 ms: system 2 takes over within 50 ms"
    # 10 ms slots: high from slot 10 (100 ms) to slot 14 (up to 150 ms), low elsewhere
    assert lane["wave"] == "0" + "." * 9 + "1" + "." * 4 + "0" + "." * (len(lane["wave"]) - 16)
