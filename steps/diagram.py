"""A timing diagram of a scenario (WaveJSON, rendered to SVG offline by `wavedrom`) for the report.

One lane per thing that changed: vehicle outputs (metro: what each VVVF and BECU applies, who masters each bus), the CCU systems putting commands on the ring (high while
they send), each RXC's command source, and an events lane for injected faults, takeovers, fail-safe cuts
and token formation. Time is cut into at most ~48 equal slots so a 50 ms takeover and a 20 s pressure
ramp both fit one picture; the header says the slot length.
"""
from __future__ import annotations

import functools
import json
from dataclasses import dataclass

from sut.trace import Trace, TraceEvent

MAX_SLOTS = 48
NICE_MS = (1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10_000, 20_000, 60_000, 120_000, 300_000,
           600_000, 1_200_000, 3_600_000, 7_200_000, 18_000_000, 36_000_000)   # up to 10 h: 72 h runs
EVENT_KINDS = ("fault.", "env.", "supply.", "ccu.takeover", "txc.failsafe", "rxc.failsafe", "token.form", "token.init", "in.set",
               "in.ramp", "desk.", "time.skip", "master.take", "line.switch", "mode.change", "io.select", "train.stop",
               "selftest.postpone", "fs.")
MAX_LANES = 14
# The kinds a diagram draws (wavejson's walk); every other kind is passed over, so only these are read.
DRAWN_KINDS = frozenset({"out.change", "cmd.tx", "wtb.msg", "mvb.msg", "loop.change", "relay.change", "pd.change",
                         "rxc.source"})


def _drawn(kind: str) -> bool:
    return kind in DRAWN_KINDS or kind.startswith(EVENT_KINDS)


def _slot_ms(duration_ms: float) -> int:
    for nice in NICE_MS:
        if duration_ms / nice <= MAX_SLOTS:
            return nice
    return NICE_MS[-1]


def _runs(wave: list[str]) -> str:
    """WaveJSON draws every repeated level as a new cycle; '.' continues the one before."""
    out = []
    for i, ch in enumerate(wave):
        out.append("." if i and ch == wave[i - 1] and ch in "01x" else ch)
    return "".join(out)


def _data_lane(name: str, changes: list[tuple[int, str]], slots: int) -> dict:
    wave, data, current = [], [], None
    by_slot = dict(changes)                        # last change in a slot wins
    for i in range(slots):
        if i in by_slot and by_slot[i] != current:
            current = by_slot[i]
            wave.append("=")
            data.append(str(current))
        else:
            wave.append("." if current is not None else "x")
    return {"name": name, "wave": "".join(wave), "data": data}


def _label(ev: TraceEvent) -> str:
    if ev.kind == "time.skip":
        return f"{(ev['to'] - ev['frm']) / 3.6e9:.3g} h skipped"
    short = ev.source.replace(".MDM8", "").replace(".CPU3", "")
    if ev.kind.startswith("in."):
        return f"{ev['name']}={ev.get('value', ev.get('to'))}"
    if ev.kind == "mode.change":
        return f"{ev.source} {ev['mode']}"
    if ev.kind == "master.take":
        return f"{ev.source} takes {ev['bus']}"
    if ev.kind == "line.switch":
        return f"{ev.source} {ev['frm']}->{ev['to']}"
    if ev.kind.startswith("desk."):
        return f"{short} {ev.kind[5:]}"
    return f"{short} {ev.kind.split('.', 1)[-1]}"


@dataclass(frozen=True)
class Bound:
    """A timing requirement a Then step checked: `text` had to happen in [start_us, end_us]."""
    text: str
    start_us: int
    end_us: int


def _bound_lane(bound: Bound, start_us: int, slot_us: int, slots: int) -> dict:
    first = max(0, (bound.start_us - start_us) // slot_us)
    last = min(slots - 1, max(first, (bound.end_us - start_us - 1) // slot_us))
    wave = ["1" if first <= i <= last else "0" for i in range(slots)]
    ms = (bound.end_us - bound.start_us) / 1000
    short = bound.text if len(bound.text) <= 40 else bound.text[:39] + "…"
    return {"name": f"bound {ms:g} ms: {short}", "wave": _runs(wave)}


def wavejson(trace: Trace, start_us: int, end_us: int, bounds: tuple[Bound, ...] = ()) -> dict | None:
    """The diagram of [start_us, end_us], or None when nothing worth drawing happened. Each bound a Then step
    checked is a lane of its own, high over the window in which the step required its event."""
    duration_ms = max(1.0, (end_us - start_us) / 1000)
    slot_ms = _slot_ms(duration_ms)
    slot_us = slot_ms * 1000
    slots = int(duration_ms // slot_ms) + 1

    def slot(ev: TraceEvent) -> int:
        return min(slots - 1, (ev.t - start_us) // slot_us)

    lanes: list[dict] = []
    outputs: dict[str, list[tuple[int, str]]] = {}
    senders: dict[str, set[int]] = {}
    rxc: dict[str, list[tuple[int, str]]] = {}
    buses: dict[str, dict[int, str]] = {}
    events: list[tuple[int, str]] = []
    for ev in trace.select(kind="out.change", until=start_us):
        outputs.setdefault(ev.source, [(0, ev["value"])])[0] = (0, ev["value"])   # the state at the start
    for ev in trace.select(kind="pd.change", until=start_us):
        outputs.setdefault(ev.source, [(0, "")])[0] = (0, f"{ev['value']:g} %")
    for ev in trace.of_kinds(_drawn, since=start_us, until=end_us):
        if ev.kind == "out.change":
            outputs.setdefault(ev.source, []).append((slot(ev), ev["value"]))
        elif ev.kind == "cmd.tx":
            senders.setdefault(ev.source.rsplit(".", 1)[0], set()).add(slot(ev))
        elif ev.kind in ("wtb.msg", "mvb.msg"):       # metro: who masters each bus, or that it lost a poll
            per_slot = buses.setdefault(ev.source, {})
            if per_slot.get(slot(ev)) != "lost":
                per_slot[slot(ev)] = "lost" if ev["lost"] else ev["master"]
        elif ev.kind == "loop.change":                  # VDX: the emergency-brake loop and its relays
            outputs.setdefault("EB loop", []).append((slot(ev), ev["state"]))
        elif ev.kind == "relay.change":
            outputs.setdefault(ev.source, []).append((slot(ev), "energised" if ev["energised"] else "released"))
        elif ev.kind == "pd.change":                    # metro: traction/brake a VVVF or BECU applies
            outputs.setdefault(ev.source, []).append((slot(ev), f"{ev['value']:g} %"))
        elif ev.kind == "rxc.source":
            rxc.setdefault(ev.source, []).append((slot(ev), ev["source"]))
        elif ev.kind.startswith(EVENT_KINDS):
            events.append((slot(ev), _label(ev)))
    if events:
        wave, data, seen = [], [], {}
        for s, label in events:
            seen.setdefault(s, label)
        for i in range(slots):
            if i in seen:
                wave.append("=")
                data.append(seen[i])
            else:
                wave.append("0")
        lanes.append({"name": "events", "wave": _runs(wave), "data": data})
    # a slot the backend skipped (time.skip) shows traffic as unknown, not as silence
    skipped = {i for ev in trace.select(kind="time.skip", since=start_us, until=end_us)
               for i in range(slots) if ev["frm"] <= start_us + i * slot_us and start_us + (i + 1) * slot_us <= ev["to"]}
    for node, hits in sorted(senders.items()):
        if len(hits) + len(skipped - hits) < slots:    # a sender that never paused says nothing
            wave = ["1" if i in hits else "x" if i in skipped else "0" for i in range(slots)]
            lanes.append({"name": f"cmd {node}", "wave": _runs(wave)})
    for name, per_slot in sorted(buses.items()):
        values = [per_slot.get(i, "silent") for i in range(slots)]
        if len(set(values)) > 1:                             # a bus whose master never changed says nothing
            lanes.append(_data_lane(f"{name} master", list(enumerate(values)), slots))
    for name, changes in sorted(outputs.items()):
        if len({value for _, value in changes}) > 1:          # an output that never changed says nothing
            lanes.append(_data_lane(name, changes, slots))
    for name, changes in sorted(rxc.items()):
        if any(value != "idle" for _, value in changes):      # an RXC that stayed idle says nothing
            lanes.append(_data_lane(f"{name} source", changes, slots))
    # Bounds first after the events lane: they are what the reviewer checks the other lanes against.
    at = 1 if lanes and lanes[0]["name"] == "events" else 0
    lanes[at:at] = [_bound_lane(b, start_us, slot_us, slots) for b in bounds]
    if not lanes or (len(lanes) == 1 and lanes[0]["name"] == "events"):
        return None
    return {"signal": lanes[:MAX_LANES],
            "head": {"text": f"from {start_us / 1000:.0f} ms, one slot = {_duration(slot_ms)}"},
            "config": {"hscale": 1}}


def _duration(ms: int) -> str:
    for unit, size in (("h", 3_600_000), ("min", 60_000), ("s", 1000)):
        if ms >= size and ms % size == 0:
            return f"{ms // size} {unit}"
    return f"{ms} ms"


def render_svg(diagram: dict, renderer: type | None = None) -> str:
    """WaveDrom's SVG carries its whole skin (~800 shapes) in <defs>; keep only the shapes the diagram
    uses, which makes each picture a few kilobytes instead of ~50 in a single-file report. Pruned before
    the SVG is written out: writing the whole skin was most of the time a report run spent on diagrams."""
    # wavedrom.render(text) parses the text with YAML first (to mend hand-written quotes), a sixth of its
    # time; a diagram made here is already plain JSON data, so it goes straight to the renderer.
    drawing = (renderer or _quiet_wavedrom())().render_waveform(0, json.loads(json.dumps(diagram)))
    used: set[str] = set()
    for element in drawing.elements:
        if element is not drawing.defs:
            _hrefs(element, used)
    drawing.defs.elements[:] = [e for e in drawing.defs.elements
                                if not (type(e).__name__ == "Group" and e.attribs.get("id") not in used)]
    return drawing.tostring()


@functools.cache
def _quiet_wavedrom() -> type:
    """WaveDrom as it draws, less two costs a report run paid per picture (15 ms -> 4.5 ms, measured on 25
    of the suite's diagrams, the same SVG byte for byte; tests/test_diagram.py holds it to WaveDrom's own):
    svgwrite's validation of every attribute of every shape (its `debug`, on by default; the shapes here
    are WaveDrom's own), and the skin's ~800 shapes built again for every picture: built once, shared by
    every picture's <defs>, which render_svg prunes in a list of its own."""
    import svgwrite
    from wavedrom import WaveDrom, waveskin
    from wavedrom.attrdict import AttrDict

    class QuietWaveDrom(WaveDrom):
        container = AttrDict({k: functools.partial(v, debug=False) for k, v in WaveDrom.container.items()})
        element = AttrDict({k: v if k == "title" else functools.partial(v, debug=False) for k, v in WaveDrom.element.items()})
        skins: dict = {}

        def another_template(self, index, source):
            if index != 0:
                return super().another_template(index, source)
            name = source.get("config", {"skin": "default"}).get("skin", "default")
            made = self.skins.get(name)
            if made is None:
                made = self.skins[name] = super().another_template(index, source)
            lane = waveskin.WaveSkin.get(name, waveskin.WaveSkin["default"])[3][1][2][1]
            self.lane.xs, self.lane.ys = int(lane["width"]), int(lane["height"])
            self.lane.xlabel, self.lane.ym = int(lane["x"]), int(lane["y"])
            template = svgwrite.Drawing(id="svgcontent_0", debug=False)
            template.elements[:] = [template.defs if e is made.defs else e for e in made.elements]
            template.defs.elements[:] = made.defs.elements
            template["class"] = "WaveDrom"
            template["overflow"] = "hidden"
            return template

    return QuietWaveDrom


def _hrefs(element, found: set[str]) -> None:
    for name in ("xlink:href", "href"):
        ref = element.attribs.get(name)
        if isinstance(ref, str) and ref.startswith("#"):
            found.add(ref[1:])
    for child in getattr(element, "elements", ()):
        _hrefs(child, found)
