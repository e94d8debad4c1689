"""Equivalent mutants only with machine evidence (outline/sequences/equivalence.py, issue 31): every mark in
sut/reference/EQUIVALENT_MUTANTS.txt has the differential checker's confirming record, for the text it has
now and the current budget, in the committed reports/equivalence.json (make equivalence writes it; this
reads it and simulates nothing); and the checker itself tells a changed threshold from a change nothing
can see, on a tiny budget."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from outline.sequences import equivalence
from outline.sequences.equivalence import Mark, check_mark, confirmed, load_report, read_marks

# The VDX rig's supply band (VDX-02: 70-125 % of 110 V) with its top at 110 % instead: a supply of 125-137 V
# leaves the reference's loop closed and opens the mutant's.
THRESHOLD = Mark("sut/reference/atp/vdx.py",
                 "return self.cfg.supply_lo * self.cfg.nominal_v <= v <= self.cfg.supply_hi * self.cfg.nominal_v",
                 "return self.cfg.supply_lo * self.cfg.nominal_v <= v <= 1.1 * self.cfg.nominal_v", "a test's own")
# A mark the checker confirmed: the isolation switch's state starts as None instead of False, and is only
# ever tested for truth.
UNSEEN = Mark("sut/reference/atp/vdx.py", "self.isolated = False", "self.isolated = None", "a test's own")
TINY = {"vdx": [({}, "paced", 300)]}     # ~5 s; the fitted train (atp-crh2) left out


def test_every_mark_has_the_checkers_confirming_record_for_its_text_now() -> None:
    report = load_report()
    missing = [m.line() for m in read_marks() if not confirmed(report, m)]
    assert not missing, (f"{len(missing)} marks of sut/reference/EQUIVALENT_MUTANTS.txt have no confirming record "
                         f"in reports/equivalence.json (budget {equivalence.budget_id()}): run `make equivalence` "
                         "(only those marks run), and take out a mark it overturns (`--move`). First:\n"
                         + "\n".join(missing[:10]))


def test_an_overturned_mark_is_noted_with_what_the_checker_saw_and_counts_as_a_survivor() -> None:
    report = load_report()
    now = {m.key for m in read_marks()}
    overturned = [r for key, r in report.get("marks", {}).items() if r["verdict"] == "overturned"]
    assert all(Mark(r["where"], r["before"], r["after"], "").key not in now for r in overturned)
    for r in overturned:
        seen = r["difference"]
        assert seen["observable"] and "reference" in seen and "mutant" in seen, r


def test_the_checker_overturns_a_changed_threshold_and_confirms_a_change_nothing_can_see() -> None:
    changed = check_mark(THRESHOLD, budget=TINY, exact=False, shrink_s=20)
    assert changed["verdict"] == "overturned", changed
    seen = changed["difference"]
    assert seen["profile"] == "vdx" and seen["sequence"][0] == "power_on()"
    assert any("set_supply_voltage('VDX'" in step for step in seen["sequence"]), seen
    unseen = check_mark(UNSEEN, budget=TINY, exact=False)
    assert unseen["verdict"] == "confirmed" and unseen["sequences"] == 300 and unseen["reached"] > 0, unseen


def _reach_of(original: str, mutated: str, *calls: str) -> int:
    """How often the changed statement of `mutated` (against `original`) ran while `calls` were evaluated."""
    start = next(i for i, (a, b) in enumerate(zip(original, mutated)) if a != b)
    tail = next(i for i, (a, b) in enumerate(zip(original[::-1], mutated[::-1])) if a != b)
    site = equivalence.Site("m.py", 0, "f", "", "", original, start, len(original) - tail,
                            mutated[start:len(mutated) - tail])
    assert site.source == mutated
    reach = equivalence.Reach()
    scope = {equivalence.REACH_NAME: reach}
    exec(equivalence.instrumented(site.source, "m.py", *equivalence.changed_at(site)), scope)
    for call in calls:
        eval(call, scope)
    return reach.count


def test_the_checker_counts_how_often_the_changed_statement_ran() -> None:
    # A branch the calls never take is not reached, whatever its change; a continuation line counts with its
    # statement; a default counts when the function is called, not when it is defined.
    branch = "def f(x):\n    if x:\n        y = {}\n        return y\n    return 0\n"
    assert _reach_of(branch.format(1), branch.format(2), "f(False)", "f(0)") == 0
    assert _reach_of(branch.format(1), branch.format(2), "f(True)", "f(False)", "f(3)") == 2
    call = "def g(a):\n    return max(a,\n               {})\n"
    assert _reach_of(call.format(1), call.format(2), "g(5)", "g(6)", "g(7)") == 3
    default = "class C:\n    def h(self, n={}):\n        \"\"\"Its doc.\"\"\"\n        return n\n"
    assert _reach_of(default.format(1), default.format(2)) == 0
    assert _reach_of(default.format(1), default.format(2), "C().h()", "C().h(4)", "C.h.__doc__ == 'Its doc.' or 1/0") \
        == 2
    handler = "def k(x):\n    try:\n        return 1 / x\n    except ZeroDivisionError:\n        return {}\n"
    assert _reach_of(handler.format(1), handler.format(2), "k(1)") == 0
    assert _reach_of(handler.format(1), handler.format(2), "k(0)", "k(0)") == 2


def test_an_unreached_mark_is_no_evidence_and_moves_out_with_the_overturned(tmp_path: Path) -> None:
    marks = tmp_path / "EQUIVALENT_MUTANTS.txt"
    kept, far = (Mark("sut/reference/bulk.py", f"a = {n}", f"a = {n + 1}", "why") for n in (1, 2))
    marks.write_text(f"{kept.line()}\n{far.line()}\n", encoding="utf-8")
    report = {"marks": {kept.key: {"verdict": "confirmed"},
                        far.key: {"verdict": "unreached", "unreached": {"line": 9, "function": "f"}}}}
    overturned = tmp_path / "OVERTURNED_MUTANTS.txt"
    assert equivalence.move_overturned(report, marks, overturned) == (1, 0)
    assert marks.read_text(encoding="utf-8") == f"{kept.line()}\n"
    assert "unreached, no sequence ran the changed statement (line 9 of f)" in overturned.read_text(encoding="utf-8")
    assert not confirmed({"marks": {far.key: {"verdict": "unreached", "budget": equivalence.mark_budget(far)}}}, far)


def test_a_mark_is_built_in_every_function_that_says_its_line_or_only_in_the_one_it_names(tmp_path: Path) -> None:
    source = tmp_path / "sut" / "reference" / "atp" / "x.py"
    source.parent.mkdir(parents=True)
    source.write_text("A = 1\n\nclass Relay:\n    def on(self):\n        x = 1\n\n    def off(self):\n"
                      "        x = 1\n        return x\n", encoding="utf-8")
    everywhere = equivalence.replaced_sites(Mark("sut/reference/atp/x.py", "x = 1", "x = 2", "r"), tmp_path)
    assert [(s.line, s.function) for s in everywhere] == [(5, "Relay.on"), (8, "Relay.off")]
    assert everywhere[1].source.splitlines()[7] == "        x = 2"
    assert everywhere[1].source.splitlines()[4] == "        x = 1"
    named = equivalence.replaced_sites(Mark("sut/reference/atp/x.py::Relay.off", "x = 1", "x = 2", "r"), tmp_path)
    assert [(s.line, s.function) for s in named] == [(8, "Relay.off")]
    assert equivalence.replaced_sites(Mark("sut/reference/atp/x.py", "A = 1", "A = 2", "r"), tmp_path) == []


def test_a_mark_is_keyed_by_its_text_and_a_record_by_the_budget(monkeypatch: pytest.MonkeyPatch) -> None:
    mark = Mark("sut/reference/bulk.py", "a = 1", "a = 2", "why")
    assert mark.key == Mark("sut/reference/bulk.py", "a = 1", "a = 2", "another wording").key
    assert mark.key != Mark("sut/reference/bulk.py", "a = 1", "a = 3", "why").key
    report = {"marks": {mark.key: {"verdict": "confirmed", "budget": equivalence.mark_budget(mark)}}}
    assert confirmed(report, mark)
    monkeypatch.setitem(equivalence.BUDGET, "vdx", [({}, "paced", 1)])
    assert not confirmed(report, mark)                   # checked in another budget: not evidence for this one


def test_a_budget_change_to_one_profile_checks_again_only_the_marks_that_profile_runs(
        monkeypatch: pytest.MonkeyPatch) -> None:
    metro, atp, shared = (Mark(path, "a = 1", "a = 2", "why") for path in
                          ("sut/reference/metro/tcds.py", "sut/reference/atp/onboard.py", "sut/reference/kernel.py"))
    before = {m.path: equivalence.mark_budget(m) for m in (metro, atp, shared)}
    monkeypatch.setitem(equivalence.BUDGET, "metro-tcn", [({}, "paced", 1)])
    after = {m.path: equivalence.mark_budget(m) for m in (metro, atp, shared)}
    assert after[atp.path] == before[atp.path]            # the ATP's marks keep their evidence
    assert after[metro.path] != before[metro.path] and after[shared.path] != before[shared.path]


def test_overturned_marks_move_out_of_the_marks_and_marks_naming_no_mutant_go(tmp_path: Path) -> None:
    marks = tmp_path / "EQUIVALENT_MUTANTS.txt"
    kept, wrong, gone = (Mark("sut/reference/bulk.py", f"a = {n}", f"a = {n + 1}", "why") for n in (1, 2, 3))
    marks.write_text(f"# header\n{kept.line()}\n{wrong.line()}\n{gone.line()}\n", encoding="utf-8")
    report = {"marks": {kept.key: {"verdict": "confirmed"}, gone.key: {"verdict": "names no mutant"},
                        wrong.key: {"verdict": "overturned", "difference": {
                            "profile": "crh2", "observable": "output traction", "reference": "'on'",
                            "mutant": "'off'"}}}}
    overturned = tmp_path / "OVERTURNED_MUTANTS.txt"
    assert equivalence.move_overturned(report, marks, overturned) == (1, 1)
    assert marks.read_text(encoding="utf-8") == f"# header\n{kept.line()}\n"
    assert overturned.read_text(encoding="utf-8").splitlines()[-1] == \
        "sut/reference/bulk.py | a = 2 | a = 3 | crh2: output traction, 'on' -> 'off'"


def test_a_mutant_is_found_in_the_source_as_mutmut_writes_it() -> None:
    source = "class A:\n    def f(self):\n        return g(1,\n                 2)\n"
    start = source.index("g(1")
    end = source.index("2)") + 2
    rendered = "g(1,\n         2)"                 # libcst's code for the node, without its block's indentation
    indent = equivalence._block_indent(source[start:end], rendered)
    assert indent == "        " and equivalence._indented("g(1,\n         3)", indent) == "g(1,\n                 3)"
    assert equivalence._first_change(source, start, end, "g(1,\n                 3)") == (4, "2)", "3)")
    assert equivalence._first_change(source, start, end, "h(1,\n                 2)") == (3, "return g(1,", "return h(1,")


def test_a_mutant_that_crashes_where_the_reference_does_not_is_overturned() -> None:
    # An event without a kind: the checker's look at the trace raises, outside any driver call; the reference
    # driven alone the same way raises nothing, so the crash is the mutant's, and a user would see it.
    crash = Mark("sut/reference/atp/vdx.py", 'self._emit("VDX", "fs.on")', 'self._emit("VDX", None)', "a test's own")
    record = check_mark(crash, budget=TINY, exact=False, shrink_s=5)
    assert record["verdict"] == "overturned", record
    assert record["difference"]["observable"] == "an error raised where the reference raises none", record


def test_a_board_failed_before_power_up_and_repaired_reaches_what_no_later_fault_does() -> None:
    # Seed 12: the crh2 monitor's default for a node heard but with none of its status fields held (its feeding
    # system's CPU3 down when they came) was confirmed by every sequence that starts powered up; the "cold"
    # draw fails boards before power-up and repairs them after, and finds the mutant's crash.
    defaults = Mark("sut/reference/crh2/ccu.py", 'if not fields.get("ports", 3) & bit:',
                    'if not fields.get("ports", None) & bit:', "a test's own")
    record = check_mark(defaults, budget={"crh2": [({}, "cold", 10)]}, exact=False, shrink_s=5)
    assert record["verdict"] == "overturned", record
    seen = record["difference"]
    assert seen["sequence"][0].startswith("fail(") and "power_on()" in seen["sequence"], seen
    assert any(step.startswith("repair(") for step in seen["sequence"]), seen


def test_a_change_no_random_sequence_reaches_is_reached_by_replaying_the_scenarios(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # C019's fault event: three paced VDX sequences never release the brake a few ms before a self-test at
    # 137 V with the old firmware; F-ATP-06's scenarios do, and their recorded stimuli reach it.
    import subprocess
    import sys
    from outline.sequences import replay
    corpus = tmp_path / "stimuli"
    run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:xdist", "-p", "no:cacheprovider",
                          "--item", "F-ATP-06", "--record-stimuli", str(corpus)],
                         cwd=equivalence.ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-2000:]
    monkeypatch.setattr(replay, "CORPUS", corpus)
    c019 = Mark("sut/reference/atp/vdx.py",
                'self._emit("VDX", "fault.C019", text="C019: FS output did not go low in its self-test")',
                'self._emit("VDX", "fault.C020", text="C019: FS output did not go low in its self-test")', "a test's own")
    # Each recording holds the lines of the references its scenario ran: those that ran the fault event's
    # line are probed first, so no probe is spent on one that does not reach it.
    line = next(i for i, text in enumerate((equivalence.ROOT / c019.path).read_text().splitlines(), 1)
                if '"fault.C019"' in text)
    recorded = replay.load(corpus)["vdx"]
    assert any(r.covers(c019.path, line) for r in recorded) and not all(r.covers(c019.path, line) for r in recorded)
    record = check_mark(c019, budget={"vdx": [({}, "paced", 3)]}, exact=False, shrink_s=1)
    assert record["verdict"] == "overturned", record
    assert record["difference"]["drawn"].startswith("replay of features/test_outline.py::test_fatp06"), record
    assert record["replay"]["reaching"], record
    assert record["replay"]["probed"] == len(record["replay"]["reaching"]), record


def _site(source: str, old: str, new: str) -> equivalence.Site:
    start = source.index(old)
    return equivalence.Site("sut/reference/x.py", source.count("\n", 0, start) + 1, "f", old, new,
                            original=source, start=start, end=start + len(old), text=new)


def test_the_reach_is_counted_at_the_statement_a_line_coverage_names() -> None:
    source = 'def f(a=1):\n    """doc"""\n    x = (a +\n         2)\n    return x\n'
    assert equivalence.counted_line(_site(source, "2)", "3)")) == 3     # a continuation line: its statement's
    assert equivalence.counted_line(_site(source, "a=1", "a=2")) == 3   # a default: the body's first after the doc


def test_a_rule_that_says_the_reference_never_runs_the_code_is_confirmed_by_no_stimulus_running_it() -> None:
    from outline.sequences.rule_check import NEVER_RUN_RULES, judged
    unreached = {"verdict": "unreached", "reached": 0}
    assert judged("faulty-variant branch", unreached, False)["verdict"] == "confirmed"
    assert judged("faulty-variant branch", unreached, False)["never_run"] is True
    assert judged("faulty-variant branch", unreached, True) == unreached       # the conformance run ran it
    assert judged("faulty-variant branch", unreached, None) == unreached       # recorded without lines
    assert judged("unread field", unreached, False) == unreached               # run but unread: no evidence
    assert judged("faulty-variant branch", {"verdict": "confirmed", "reached": 4}, None)["never_run"] is False
    assert judged("decided by the switches", {"verdict": "overturned"}, None) == {"verdict": "overturned"}
    assert set(NEVER_RUN_RULES) == {"decided by the switches", "faulty-variant branch", "only a faulty variant calls it"}


def test_records_the_random_sequences_decided_carry_over_to_new_replay_counts_and_unreached_ones_replay(
        monkeypatch: pytest.MonkeyPatch) -> None:
    done, open_, replayed = (Mark("sut/reference/atp/vdx.py", f"a = {n}", f"a = {n + 1}", "why") for n in (1, 2, 3))
    old = equivalence.mark_random_budget(done)
    report = {"marks": {done.key: {"verdict": "confirmed", "budget": old},
                        open_.key: {"verdict": "unreached", "budget": old},
                        replayed.key: {"verdict": "confirmed", "budget": old, "replay": {"reaching": ["x"]}}}}
    monkeypatch.setattr(equivalence, "REPLAY_PROBES", equivalence.REPLAY_PROBES + 1)
    assert equivalence.carry_over(report, [done, open_, replayed]) == [open_]
    assert confirmed(report, done)                                   # decided by the random sequences alone
    assert not confirmed(report, replayed)                           # its replay ran with other counts
    assert not confirmed(report, open_)


@pytest.mark.parametrize("ran, verdict", [(False, "confirmed"), (True, "unreached"), (None, "unreached")])
def test_a_mark_that_says_the_reference_never_runs_its_line_is_confirmed_only_where_nothing_ran_it(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, ran: bool | None, verdict: str) -> None:
    # A C019 that does not latch (c019_latches, off in the reference): only a faulty variant runs the line.
    from outline.sequences import replay
    monkeypatch.setattr(replay, "CORPUS", tmp_path)                       # no scenarios to replay
    seen = []
    monkeypatch.setattr(equivalence, "replay_ran_anywhere", lambda path, line: seen.append((path, line)) or ran)
    mark = Mark("sut/reference/atp/vdx.py::VdxInterface._selftest_end", "self.c019 = False", "self.c019 = None",
                f"{equivalence.NEVER_RUN} only the faulty variant whose C019 does not latch runs it")
    record = check_mark(mark, budget={"vdx": [({}, "paced", 3)]}, exact=False, shrink_s=1)
    assert record["verdict"] == verdict, record
    assert record.get("never_run", False) is (ran is False)
    assert seen and seen[0][0] == "sut/reference/atp/vdx.py"
    # a mark that does not say so: unreached whatever the recorded run ran
    plain = Mark(mark.where, mark.before, mark.after, "only the faulty variant whose C019 does not latch runs it")
    assert check_mark(plain, budget={"vdx": [({}, "paced", 3)]}, exact=False, shrink_s=1)["verdict"] == "unreached"
