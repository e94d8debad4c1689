"""The token protocol (PRO-03..05), status and block data (PRO-02, PRO-06), the ring itself (NET-03..09)."""
from __future__ import annotations

from pytest_bdd import parsers, then

from sut.codecs import arcnet
from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps import messages, zh
from steps import analysis
from steps.analysis import ms, us


def _node(source: str) -> str:
    return source.rsplit(".", 1)[0]


# -- token ------------------------------------------------------------------------------------------
@then(parsers.parse("令牌初始化仅在上电后{lo:g}至{hi:g} ms发送"))
@then(parsers.parse("token initialisations are sent {lo:g} to {hi:g} ms after power-up and at no other time"))
def _(sut: TrainDriver, lo: float, hi: float) -> None:
    """PRO-03: nodes that heard no status data for 500 ms send a token initialisation. A node that has
    already heard another's initialisation may stay quiet (it is no longer waiting on silence), so the
    check is that the initialisation comes, and that no node sends one outside the window."""
    inits = {}
    for ev in sut.trace.select(kind="token.init"):
        inits.setdefault(_node(ev.source), ev.t)
    assert inits, "no node sent a token initialisation"
    for node, t in inits.items():
        assert us(lo) <= t <= us(hi), f"{node} sent it at {ms(t)}, outside {lo}..{hi} ms"


@then(parsers.parse('首次令牌初始化后{lo:g}至{hi:g} ms由"{node}"生成令牌'))
@then(parsers.parse('the token is formed by "{node}" {lo:g} to {hi:g} ms after the first token initialisation'))
def _(sut: TrainDriver, t_action: int, node: str, lo: float, hi: float) -> None:
    init = sut.trace.first(kind="token.init", since=t_action)
    assert init is not None, "nobody sent a token initialisation"
    forms = sut.trace.select(kind="token.form", since=init.t)
    assert forms, "no token was formed"
    first = forms[0]
    assert _node(first.source) == node, f"the token was formed by {_node(first.source)}, expected {node}"
    delay = first.t - init.t
    assert us(lo) <= delay <= us(hi), f"formed {ms(delay)} after the initialisation, outside {lo}..{hi} ms"
    others = [ev for ev in forms[1:] if _node(ev.source) != node]
    assert not others, f"other nodes formed tokens too: {analysis.describe(others)}"


@then(parsers.parse("令牌到达每个下一节点的时间比到达上一节点晚{lo:g}至{hi:g} ms"))
@then(parsers.parse("the token arrives at each next node {lo:g} to {hi:g} ms after the one before"))
def _(sut: TrainDriver, t_action: int, lo: float, hi: float) -> None:
    arrivals = sut.trace.select(kind="token.rx", since=t_action)
    assert len(arrivals) >= len(sut.ring_nodes()), f"only {len(arrivals)} token arrivals since {ms(t_action)}"
    for a, b in zip(arrivals, arrivals[1:]):
        gap = b.t - a.t
        assert us(lo) <= gap <= us(hi), (f"{_node(a.source)} held the token {ms(gap)} before "
                                           f"{_node(b.source)} had it, outside {lo}..{hi} ms")


@then("令牌按环网顺序依次经过各节点")
@then("the token visits the nodes in ring order")
def _(sut: TrainDriver, t_action: int) -> None:
    """PRO-04: passed to the neighbour in sequence. Either way round is a sequence: the direction is the
    SUT's, taken from its first pass, and must then hold for every pass."""
    nodes = sut.ring_nodes()
    visits = [_node(ev.source) for ev in sut.trace.select(kind="token.rx", since=t_action)]
    assert len(visits) > len(nodes), f"only {len(visits)} token visits"
    step = (nodes.index(visits[1]) - nodes.index(visits[0])) % len(nodes)
    assert step in (1, len(nodes) - 1), f"the token went from {visits[0]} to {visits[1]}, not to a neighbour"
    for a, b in zip(visits, visits[1:]):
        ia = nodes.index(a)
        assert nodes[(ia + step) % len(nodes)] == b, f"the token went from {a} to {b}, not to the next node"


@then(parsers.parse('"{node}"收到令牌后{lo:g}至{hi:g} ms将令牌沿原路送回'))
@then(parsers.parse('"{node}" sends the token back the way it came {lo:g} to {hi:g} ms after receiving it'))
def _(sut: TrainDriver, t_action: int, node: str, lo: float, hi: float) -> None:
    trace = sut.trace
    rx = trace.select(kind="token.rx", source=f"{node}.MDM8", since=t_action)
    assert rx, f"{node} never received the token after {ms(t_action)}"
    for arrival in rx[:-1]:
        sent = trace.first(kind="token.pass", source=f"{node}.MDM8", since=arrival.t)
        assert sent is not None, f"{node} never passed on the token it got at {ms(arrival.t)}"
        # Back the way it came: to the neighbour it came from, travelling the other way (what the ring shows,
        # not the node's own word for it).
        assert sent["to"] == arrival["frm"] and sent["dir"] != arrival["dir"], (
            f"{node} passed the token it got from {arrival['frm']} ({arrival['dir']}) on to {sent['to']} "
            f"({sent['dir']}), into the fault, not back")
        arrived = trace.first(kind="token.rx", source=f"{sent['to']}.MDM8", since=sent.t)
        assert arrived is not None, f"the token {node} sent back never reached {sent['to']}"
        held = arrived.t - arrival.t
        assert us(lo) <= held <= us(hi), (f"{node} held the token {ms(held)} before {sent['to']} had it, "
                                            f"outside {lo}..{hi} ms")


@then(parsers.parse("每个节点至少每{bound:g} ms收到一次令牌"))
@then(parsers.parse("every node receives the token at least every {bound:g} ms"))
def _(sut: TrainDriver, t_action: int, bound: float) -> None:
    for node in sut.ring_nodes():
        times = [t_action] + [ev.t for ev in sut.trace.select(kind="token.rx", source=f"{node}.MDM8",
                                                                since=t_action)] + [sut.now_us]
        worst = max(analysis.intervals(times))
        assert worst <= us(bound), f"{node} went {ms(worst)} without the token (limit {bound} ms)"


@then("没有节点发送令牌初始化")
@then("no node sends a token initialisation")
def _(sut: TrainDriver, t_action: int) -> None:
    inits = sut.trace.select(kind="token.init", since=t_action)
    assert not inits, f"token initialisations: {analysis.describe(inits)}"


@then(parsers.parse("此后{after:g} ms起没有节点发送令牌初始化"))
@then(parsers.parse("no node sends a token initialisation from {after:g} ms after that on"))
def _(sut: TrainDriver, t_action: int, after: float) -> None:
    """PRO-05: a token is initialised only after 500 ms without one; once the ring has settled (however the SUT
    settles a ring that grew back, docs/decisions.md "Link restored"), none follows while the token goes round."""
    inits = sut.trace.select(kind="token.init", since=t_action + us(after))
    assert not inits, f"token initialisations {after:g} ms and more after the action: {analysis.describe(inits)}"


@then(parsers.parse("最后一次令牌传递后{lo:g}至{hi:g} ms发生令牌初始化"))
@then(parsers.parse("a token initialisation follows the last token pass by {lo:g} to {hi:g} ms"))
def _(sut: TrainDriver, t_action: int, lo: float, hi: float) -> None:
    trace = sut.trace
    init = trace.first(kind="token.init", since=t_action)
    assert init is not None, "no node sent a token initialisation"
    seen = trace.last(kind="token.rx", until=init.t)
    assert seen is not None, "no token was ever seen"
    gap = init.t - seen.t
    assert us(lo) <= gap <= us(hi), f"token initialisation {ms(gap)} after the token was last seen, outside {lo}..{hi} ms"


@then(parsers.parse("{bound:g} ms内重新有且只有一个令牌在所有节点间循环"))
@then(parsers.parse("within {bound:g} ms one token circulates again through every node"))
def _(sut: TrainDriver, t_action: int, bound: float) -> None:
    trace = sut.trace
    form = trace.first(kind="token.form", since=t_action)
    assert form is not None, "no token was formed again"
    nodes = sut.ring_nodes()
    for node in nodes:
        got = trace.first(kind="token.rx", source=f"{node}.MDM8", since=form.t)
        assert got is not None and got.t <= t_action + us(bound), f"{node} had no token within {bound} ms"
    assert len(sut.token_holder()) <= 1, f"several tokens: {sut.token_holder()}"


# -- status data ------------------------------------------------------------------------------------
def _monitor_rx(sut: TrainDriver, cab: int, since: int) -> dict[str, list[int]]:
    by_node: dict[str, list[int]] = {}
    for ev in sut.trace.select(kind="status.rx", source=f"car{cab}.monitor", since=since):
        by_node.setdefault(ev["frm"], []).append(ev.t)
    return by_node


@then(parsers.parse("{cab:d}号司机室监视器每{lo:g}至{hi:g} ms收到其他每个节点的状态数据"))
@then(parsers.parse("the cab {cab:d} monitor receives status data from every other node every {lo:g} to {hi:g} ms"))
def _(sut: TrainDriver, t_action: int, cab: int, lo: float, hi: float) -> None:
    by_node = _monitor_rx(sut, cab, t_action)
    fed_by = sut.monitor(cab)["fed_by"]
    for node in sut.ring_nodes():
        if node == fed_by:
            continue
        analysis.expect_period(by_node.get(node, []), lo, hi, f"status data from {node} at the cab {cab} monitor")


@then(parsers.parse("{cab:d}号司机室监视器至少每{bound:g} ms收到一次其他每个节点的状态数据"))
@then(parsers.parse("the cab {cab:d} monitor receives status data from every other node at least every {bound:g} ms"))
def _(sut: TrainDriver, t_action: int, cab: int, bound: float) -> None:
    by_node = _monitor_rx(sut, cab, t_action)
    fed_by = sut.monitor(cab)["fed_by"]
    for node in sut.ring_nodes():
        if node == fed_by:
            continue
        times = [t_action] + by_node.get(node, []) + [sut.now_us]
        worst = max(analysis.intervals(times))
        assert worst <= us(bound), f"no status data from {node} for {ms(worst)} (limit {bound} ms)"


@then(parsers.parse("{after:g} ms后{cab:d}号司机室监视器不再收到其他节点的状态数据"))
@then(parsers.parse("the cab {cab:d} monitor receives no status data from other nodes after {after:g} ms"))
def _(sut: TrainDriver, t_action: int, cab: int, after: float) -> None:
    got = sut.trace.select(kind="status.rx", source=f"car{cab}.monitor", since=t_action + us(after))
    assert not got, f"status data still arrived: {analysis.describe(got)}"


# The monitor's fault texts are read in the SUT's own words: the feature names a message of the form
# (sut/contract/form.yaml, crh2 texts, view faults) and the SUT's declaration words it (steps/messages.py).
@then(parsers.parse('{cab:d}号司机室监视器显示"{text}"'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor shows "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, said = messages.message(declaration, text, "faults")
    faults = sut.monitor(cab)["faults"]
    assert any(pattern.fullmatch(f) for f in faults), f"the cab {cab} monitor shows {faults or 'no faults'}, not {said}"


@then(parsers.parse("{cab:d}号司机室监视器不显示任何故障"))
@then(parsers.parse("the cab {cab:d} monitor shows no faults"))
def _(sut: TrainDriver, cab: int) -> None:
    faults = sut.monitor(cab)["faults"]
    assert not faults, f"the cab {cab} monitor shows {faults}"


@then(parsers.parse('"{node}"最后收到"{other}"的状态数据距今不超过{bound:g} ms'))
@then(parsers.parse('"{node}" has status data from "{other}" no older than {bound:g} ms'))
def _(sut: TrainDriver, node: str, other: str, bound: float) -> None:
    age = sut.status_table(node)[other]
    assert age is not None and age <= us(bound), (
        f"{node} last heard {other} {'never' if age is None else ms(age) + ' ago'} (limit {bound} ms)")


@then(parsers.parse('"{node}"已至少{bound:g} ms未收到"{other}"的状态数据'))
@then(parsers.parse('"{node}" has had no status data from "{other}" for at least {bound:g} ms'))
def _(sut: TrainDriver, node: str, other: str, bound: float) -> None:
    age = sut.status_table(node)[other]
    assert age is None or age >= us(bound), f"{node} heard {other} only {ms(age)} ago"


# -- frames on an analysed link ---------------------------------------------------------------------
def _tapped(sut: TrainDriver, t_action: int, frame: str | None = None):
    found = sut.trace.select(kind="link.tx", since=t_action)
    if frame is not None:
        found = [ev for ev in found if ev["frame"] == frame]
    assert found, f"the analyser saw no {frame or ''} frames"
    return found


@then(parsers.parse("被分析链路上的每个{frame}帧携带{size:d}字节数据"), converters={"frame": zh.frame})
@then(parsers.parse("every {frame} frame on the analysed link carries {size:d} bytes of data"))
def _(sut: TrainDriver, t_action: int, frame: str, size: int) -> None:
    odd = [ev for ev in _tapped(sut, t_action, frame) if ev["data_bytes"] != size]
    assert not odd, f"{frame} frames of another size: {analysis.describe(odd)}"


@then(parsers.parse("被分析链路的传输速率为{rate:g} Mbit/s且误差不超过{tol:g} %"))
@then(parsers.parse("the analysed link carries {rate:g} Mbit/s within {tol:g} %"))
def _(sut: TrainDriver, t_action: int, rate: float, tol: float) -> None:
    for ev in _tapped(sut, t_action):
        bits = ev["bytes"] * 11 + 6        # ARCNET: 11-bit symbol per byte, 6-bit alert burst
        want_us = bits / rate              # Mbit/s = bits per us
        took_us = ev["end_us"] - ev["start_us"]
        slack = max(1.0, want_us * tol / 100)   # the trace has whole microseconds
        assert abs(took_us - want_us) <= slack, (f"a {ev['bytes']}-byte {ev['frame']} frame took {took_us} us, "
                                                 f"{want_us:.1f} us at {rate} Mbit/s")


@then(parsers.parse("被分析链路的传输介质为{medium}"), converters={"medium": zh.core_medium})
@then(parsers.parse("the analysed link is {medium}"))
def _(sut: TrainDriver, t_action: int, medium: str) -> None:
    media = {ev["medium"] for ev in _tapped(sut, t_action)}
    assert media == {medium}, f"the analysed link is {sorted(media)}, expected {medium}"


@then(parsers.parse('被分析链路上"{node}"的状态帧和数据块帧都不会抢在等待发送的命令帧之前发送'))
@then(parsers.parse('on the analysed link no status or block frame of "{node}" goes ahead of a waiting command'))
def _(sut: TrainDriver, t_action: int, node: str) -> None:
    """NET-06 at one node: between a command reaching the node's MDM8 (handed over by its TXC, `cmd.tx`, or
    arriving from the ring, `cmd.rx`) and the moment it leaves on the analysed fibre, no lower-priority
    frame of that node may start (one already on the fibre finishes: frames are not pre-empted)."""
    sent = _tapped(sut, t_action)
    mine = [ev for ev in sent if ev["frm"] == node]
    commands = [ev for ev in mine if ev["frame"] == "command"]
    lower = [ev for ev in mine if ev["frame"] in ("status", "block")]
    assert commands and lower, f"the analyser saw {len(commands)} commands and {len(lower)} status/block frames of {node}"
    handovers = [ev for ev in sut.trace.select(kind="cmd.*", source=f"{node}.MDM8", since=t_action)
                 if ev.kind in ("cmd.tx", "cmd.rx")]
    assert handovers, f"no command reached {node}"
    for handed in handovers:
        start = next((ev["start_us"] for ev in commands if ev["start_us"] >= handed.t), None)
        if start is None:
            continue
        ahead = [ev for ev in lower if handed.t < ev["start_us"] < start]
        assert not ahead, (f"command seq {handed['seq']} handed over at {ms(handed.t)} waited until {ms(start)} "
                           f"behind {analysis.describe(ahead)}")


@then("被分析链路上每个节点一次只发送一帧")
@then("on the analysed links one frame at a time leaves each node")
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int) -> None:
    """NET-07, NET-06: a node's transmitter puts one frame at a time on a fibre (frames are not pre-empted,
    and two at once garble each other): on each analysed span and direction a frame starts no earlier than
    the one before it ended (to the declared timing resolution)."""
    tick = declaration.parameter("timing_resolution_us")
    by_way: dict[tuple[str, str], list] = {}
    for ev in _tapped(sut, t_action):
        by_way.setdefault((ev.source, ev["frm"]), []).append(ev)
    for (span, frm), frames in by_way.items():
        frames.sort(key=lambda ev: ev["start_us"])
        for before, after in zip(frames, frames[1:]):
            assert after["start_us"] >= before["end_us"] - tick, (
                f"on {span} {frm} started a {after['frame']} frame at {ms(after['start_us'])} while its "
                f"{before['frame']} frame of {ms(before['start_us'])} lasted until {ms(before['end_us'])}")


@then(parsers.parse('被分析链路上"{node}"发往"{to}"的状态帧和数据块帧都不会抢在到达已超过{bound:g} ms的命令帧之前发送'))
@then(parsers.parse('on the analysed links no status or block frame leaves "{node}" for "{to}" ahead of a command '
                    'that reached it more than {bound:g} ms before'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, node: str, to: str, bound: float) -> None:
    """NET-06 for the commands a node passes on: a command seen arriving on an analysed span into `node`
    must be on its way within PRO-01's pass-through (`bound`, + the declared timing resolution), or, if the
    span toward `to` is busy then, be the next frame to start on it: no status or block frame may start on that
    span between the moment the command was due to leave and the moment it leaves. The same command is known
    on both spans by its bytes (a node passes a packet on unchanged); one already on the fibre finishes."""
    tick = declaration.parameter("timing_resolution_us")
    sent = _tapped(sut, t_action)
    out = [ev for ev in sent if ev["frm"] == node and ev["to"] == to]
    lower = [ev for ev in out if ev["frame"] in ("status", "block")]
    leaving: dict[str, list[int]] = {}
    for ev in out:
        if ev["frame"] == "command":
            leaving.setdefault(ev["hex"], []).append(ev["start_us"])
    arriving = [ev for ev in sent if ev["to"] == node and ev["frm"] != to and ev["frame"] == "command"]
    passed = 0
    for came in arriving:
        left = next((t for t in leaving.get(came["hex"], ()) if t > came["start_us"]), None)
        if left is None:
            continue
        passed += 1
        due = came["start_us"] + us(bound) + tick
        ahead = [ev for ev in lower if due < ev["start_us"] < left]
        assert not ahead, (f"a command that reached {node} at {ms(came['start_us'])} left for {to} only at "
                           f"{ms(left)}, behind {analysis.describe(ahead)}")
    assert passed and lower, (f"the analysers saw {passed} commands pass through {node} to {to} and {len(lower)} "
                              f"status/block frames leave for it")


@then(parsers.parse('"{node}"丢弃被损坏的{frame}帧'), converters={"frame": zh.frame})
@then(parsers.parse('"{node}" discards the corrupted {frame} frame'))
def _(sut: TrainDriver, t_action: int, node: str, frame: str) -> None:
    found = sut.trace.select(kind="frame.discard", source=f"{node}.MDM8", since=t_action, frame=frame)
    assert found, f"{node} discarded no {frame} frame"


# -- block data -------------------------------------------------------------------------------------
@then(parsers.parse('"{master}"在其状态数据中准许"{node}"进行数据块传输'))
@then(parsers.parse('"{master}" grants "{node}" the block transfer in its status data'))
def _(sut: TrainDriver, t_action: int, master: str, node: str) -> None:
    grant = sut.trace.first(kind="block.grant", source=f"{master}.CPU3", since=t_action, node=node)
    assert grant is not None, f"{master} never granted {node} a block transfer"
    announced = sut.trace.first(kind="status.tx", source=f"{master}.CPU3", since=grant.t)
    number = _node_number(sut, node)
    assert announced is not None and announced["grant"] == number, (
        f"{master}'s status data did not carry the grant of {node} (node {number}): "
        f"{'no status data since' if announced is None else 'grant ' + str(announced['grant'])}")


def _node_number(sut: TrainDriver, node: str) -> int:
    """The contract's numbering: a node's number is its position in ring_nodes() plus one (PRO-06's grant)."""
    nodes = sut.ring_nodes()
    assert node in nodes, f"{node} is not a node of the ring ({', '.join(nodes)})"
    return nodes.index(node) + 1


@then(parsers.parse('"{master}"的状态数据只准许{nodes}进行数据块传输'))
@then(parsers.parse('the status data of "{master}" grant a block transfer to none but {nodes}'))
def _(sut: TrainDriver, t_action: int, master: str, nodes: str) -> None:
    """PRO-06: the master announces the node it granted; a grant is for a node that asked for one. A grant
    left standing for a node that never asked holds back every node queued behind it."""
    asked = {_node_number(sut, n): n for n in analysis.quoted_names(nodes)}
    for status in sut.trace.select(kind="status.tx", source=f"{master}.CPU3", since=t_action):
        assert status["grant"] == 0 or status["grant"] in asked, (
            f"{master}'s status data at {ms(status.t)} grant node {status['grant']}, which did not ask "
            f"(asked: {', '.join(f'{n} = node {k}' for k, n in asked.items())})")


@then(parsers.parse('"{node}"在获准之前不发送数据块'))
@then(parsers.parse('"{node}" sends no block before it is granted'))
def _(sut: TrainDriver, t_action: int, node: str) -> None:
    first = sut.trace.first(kind="block.tx", source=f"{node}.CPU3", since=t_action)
    assert first is not None, f"{node} sent no block"
    grant = sut.trace.first(kind="block.grant", since=t_action, node=node, until=first.t)
    assert grant is not None, f"{node} sent block 0 at {ms(first.t)} without a grant"


@then(parsers.parse('"{master}"分{count:d}个{size:d}字节的数据块收到"{node}"的记录且每块比前一块至少晚{gap:g} ms'))
@then(parsers.parse('"{master}" receives the record of "{node}" in {count:d} blocks of {size:d} bytes, '
                    'each at least {gap:g} ms after the one before'))
def _(sut: TrainDriver, t_action: int, master: str, node: str, count: int, size: int, gap: float) -> None:
    rx = sut.trace.select(kind="block.rx", source=f"{master}.CPU3", since=t_action, owner=node)
    assert [ev["index"] for ev in rx] == list(range(count)), f"blocks received: {[ev['index'] for ev in rx]}"
    assert all(ev["bytes"] == size for ev in rx), f"block sizes {[ev['bytes'] for ev in rx]}"
    sent = [ev.t for ev in sut.trace.select(kind="block.tx", source=f"{node}.CPU3", since=t_action)]
    gaps = analysis.intervals(sent)
    assert gaps and min(gaps) >= us(gap), f"blocks sent {ms(min(gaps))} apart, less than {gap} ms"


@then(parsers.parse('"{first}"与"{second}"的数据块传输互不重叠'))
@then(parsers.parse('the block transfers of "{first}" and "{second}" do not overlap'))
def _(sut: TrainDriver, t_action: int, first: str, second: str) -> None:
    """PRO-06: the master grants one node at a time; the next only once the last has sent all it asked."""
    spans = {}
    for node in (first, second):
        sent = sut.trace.select(kind="block.tx", source=f"{node}.CPU3", since=t_action)
        assert sent, f"{node} sent no block"
        spans[node] = (sent[0].t, sent[-1].t)
    (a0, a1), (b0, b1) = spans[first], spans[second]
    assert a1 < b0 or b1 < a0, (f"{first} sent blocks from {ms(a0)} to {ms(a1)}, {second} from {ms(b0)} to "
                                f"{ms(b1)}: both at once")


@then(parsers.parse('"{master}"保存有"{node}"的{size:d}字节记录'))
@then(parsers.parse('"{master}" holds the {size:d}-byte record of "{node}"'))
def _(sut: TrainDriver, master: str, size: int, node: str) -> None:
    records = sut.block_store(master).get(node, [])
    assert any(r[:size] == analysis.record(size) for r in records), (
        f"{master} holds {len(records)} records of {node} ({[len(r) for r in records]} bytes), not this one")


@then(parsers.parse('"{master}"没有保存"{node}"的任何记录'))
@then(parsers.parse('"{master}" holds no record of "{node}"'))
def _(sut: TrainDriver, master: str, node: str) -> None:
    got = sut.block_store(master).get(node, [])
    assert not got, f"{master} holds {len(got)} records from {node}"


# -- vehicle level ----------------------------------------------------------------------------------
@then(parsers.parse('"{device}"每{lo:g}至{hi:g} ms被轮询一次'))
@then(parsers.parse('"{device}" is polled every {lo:g} to {hi:g} ms'))
def _(sut: TrainDriver, t_action: int, device: str, lo: float, hi: float) -> None:
    kind = "cmd.in" if device.endswith((".CI", ".BCU")) else "loop.poll"
    times = [ev.t for ev in sut.trace.select(kind=kind, source=device, since=t_action)]
    analysis.expect_period(times, lo, hi, f"{device} polled")


@then(parsers.parse('"{device}"为单向连接且从不应答'))
@then(parsers.parse('"{device}" is connected one way and never answers'))
def _(sut: TrainDriver, t_action: int, device: str) -> None:
    events = sut.trace.select(kind="loop.*", source=device, since=t_action)
    assert events, f"nothing went over {device}'s current loop"
    answered = [ev for ev in events if ev["reply"] or ev.kind == "loop.poll"]
    assert not answered, f"{device} is polled or answers: {analysis.describe(answered)}"


@then(parsers.parse("分析仪看到的每一帧都能解码为ARCNET令牌或数据包且数据包不少于{packets:d}个"))
@then(parsers.parse("every frame the analyser saw decodes as an ARCNET token or packet, {packets:d} packets at least"))
def _(sut: TrainDriver, t_action: int, packets: int) -> None:
    """NET-10 with the suite's own codec (sut/codecs/arcnet.py): ITT = 04 + destination twice; PAC = 01,
    source, destination twice, length, data, CRC-16/ARC; at most 508 data bytes."""
    count = 0
    for _, sid, _, data in _analysed(sut, t_action):
        if sid is not None:
            assert len(data) <= arcnet.MAX_DATA, f"{len(data)} data bytes in one packet"
            count += 1
    assert count >= packets, f"only {count} packets decoded"


def _analysed(sut: TrainDriver, t_action: int):
    """Every frame the analyser saw since the action, decoded: (event, sid, did, data), sid None for a token;
    a frame that does not decode fails the step, named by its time and span."""
    seen = sut.trace.select(kind="link.tx", since=t_action)
    assert seen, "the analyser saw no frame"
    for ev in seen:
        wire = bytes.fromhex(ev["hex"])
        try:
            if wire[:1] == bytes([arcnet.EOT]):
                yield ev, None, arcnet.decode_itt(wire), b""
            else:
                yield (ev, *arcnet.decode_pac(wire))
        except arcnet.FrameError as exc:
            raise AssertionError(f"{_where(ev)}: {exc}") from None


def _where(ev) -> str:
    return f"{ev.t_ms:.3f} ms, {ev['frm']} -> {ev['to']}"


# Who puts each kind of packet on the ring, as the trace names the handover: (event kind, board).
_PACKET_SENDERS = {"status": ("status.tx", "CPU3"), "block": ("block.tx", "CPU3"), "command": ("cmd.tx", "MDM8")}


@then(parsers.parse("分析仪看到的每个令牌都发给跨段另一端的节点,每个数据包都带有发送节点的编号"))
@then(parsers.parse("every token the analyser saw is addressed to the node across the span and every packet carries "
                    "its sender's node ID"))
def _(sut: TrainDriver, t_action: int) -> None:
    """NET-10 field by field against the exchange, not only the layout: a token (ITT) names the node it is
    passed to, the one at the far end of the span (node number = ring position + 1); a packet's source ID
    (SID) is the node that handed it to the ring (a status or block from its CPU3, a command from its
    MDM8), its destination broadcast (0) or a node of the ring. A frame layout that is wrong but
    self-consistent (IDs swapped, one constant ID) decodes and is understood by its own nodes: this
    rejects it. A packet still on its way at the end may have been handed over just before the action."""
    numbers = {name: index + 1 for index, name in enumerate(sut.ring_nodes())}
    end = sut.now_us
    handed: dict[str, dict[int, int]] = {}        # packet kind -> sender node number -> last handover time
    for kind, (event, board) in _PACKET_SENDERS.items():
        for ev in sut.trace.select(kind=event, since=t_action - us(50)):
            node = ev.source.removesuffix(f".{board}")
            if node in numbers:
                handed.setdefault(kind, {})[numbers[node]] = ev.t
    carried: dict[str, set[int]] = {}
    for ev, sid, did, _ in _analysed(sut, t_action):
        where = _where(ev)
        if sid is None:
            assert did == numbers[ev["to"]], (f"{where}: the token is addressed to node {did}; it is passed to "
                                              f"{ev['to']}, node {numbers[ev['to']]}")
            continue
        assert did == arcnet.BROADCAST or did in numbers.values(), f"{where}: {ev['frame']} packet for node {did}, not on the ring"
        if ev["frame"] in _PACKET_SENDERS:
            senders = handed.get(ev["frame"], {})
            assert sid in senders, (f"{where}: a {ev['frame']} packet from node {sid}; nodes that handed one to the "
                                    f"ring: {sorted(senders)}")
        else:                            # token formation: no handover in the trace to hold the ID against
            assert sid in numbers.values(), f"{where}: a {ev['frame']} packet from node {sid}, not on the ring"
        carried.setdefault(ev["frame"], set()).add(sid)
    # NET-03 asks only that every node is reached: a broadcast sent one way round an intact ring reaches
    # everyone and crosses every span but the one behind its sender. So every node's status (sent early
    # enough) crosses the span, except perhaps one of the two nodes at its ends; a wire that misnames senders
    # (one constant ID) shows far fewer source IDs than that.
    early = {sid for sid, t in handed.get("status", {}).items() if t <= end - us(100)}
    ends = {numbers[n] for ev in sut.trace.select(kind="link.tx", since=t_action) for n in (ev["frm"], ev["to"])
            if n in numbers}
    missing = early - carried.get("status", set())
    assert early and len(missing - ends) == 0 and len(missing) <= 1, \
        f"no status packet with the source ID of node(s) {sorted(missing)} crossed the span"


@then(parsers.parse("分析仪发现被损坏的{kind}帧未通过ARCNET校验"), converters={"kind": zh.frame})
@then(parsers.parse("the analyser finds the corrupted {kind} frame failing its ARCNET check"))
def _(sut: TrainDriver, t_action: int, kind: str) -> None:
    bad = []
    for ev in sut.trace.select(kind="link.tx", since=t_action, frame=kind):
        try:
            arcnet.decode_pac(bytes.fromhex(ev["hex"]))
        except arcnet.FrameError as exc:
            bad.append(str(exc))
    assert bad, f"every {kind} frame the analyser saw passed its check"
