"""make mutate (outline/mutate/mutation.py, outline/mutate/mutation_plugin.py): where a mutant is, what is equivalent,
the kill rate per reference, and which scenario killed a mutant. The mutmut run itself is `make mutate`
(minutes), not part of make test; its configuration is checked here."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tomllib
from dataclasses import asdict
from pathlib import Path

import pytest

from outline.mutate import mutation, quick_trampoline
from outline.mutate.mutation import Mutant

ROOT = Path(__file__).resolve().parents[1]


def _line_saying(path: str, text: str) -> tuple[int, str]:
    """The first line of a reference that holds `text`: its number and its stripped text."""
    lines = (ROOT / path).read_text(encoding="utf-8").splitlines()
    return next((i, line.strip()) for i, line in enumerate(lines, start=1) if text in line)


@pytest.fixture(autouse=True)
def _session_ends() -> None:
    """Tests here call the plugin's pytest_configure by hand; what it swaps in mutmut's trampoline for a session
    (quick_trampoline.py) goes back as pytest_unconfigure would put it back."""
    yield
    quick_trampoline.uninstall()


def test_a_mutant_is_placed_on_its_line_inside_its_method(tmp_path: Path) -> None:
    source = tmp_path / "relay.py"
    source.write_text("x = 1\n\nclass Relay:\n    def power(self, on):\n        x = 1\n        self.on = on\n\n"
                      "def x_helper():\n    x = 1\n", encoding="utf-8")
    assert mutation._line_of(source, "xǁRelayǁpower", "x = 1") == 5
    assert mutation._line_of(source, "x_x_helper", "x = 1") == 9
    assert mutation._line_of(source, "xǁRelayǁpower", "    self.on = on") == 6


def test_a_line_said_twice_in_a_function_is_placed_by_the_diff(tmp_path: Path) -> None:
    source = tmp_path / "loop.py"
    source.write_text("def x_run():\n    for a in b:\n        if a:\n            continue\n        if c:\n"
                      "            continue\n        d()\n", encoding="utf-8")
    # mutmut's diff of the second `continue`: its hunk starts 3 lines above it, counted from the def line
    diff = ["--- loop.py", "+++ loop.py", "@@ -3,7 +3,7 @@", "         if a:", "             continue",
            "         if c:", "-            continue", "+            break", "         d()"]
    assert mutation._offset(diff) == 6
    assert mutation._line_of(source, "x_x_run", "continue", mutation._offset(diff)) == 6
    assert mutation._line_of(source, "x_x_run", "continue") == 4           # without the diff: the first


def test_parts_are_the_three_references_and_the_shared_modules() -> None:
    assert [mutation.part_of(p) for p in ("sut/reference/crh2/ring.py", "sut/reference/metro/tcds.py",
                                           "sut/reference/atp/vdx.py", "sut/reference/bulk.py")] == \
        ["crh2", "metro", "atp", "shared"]


def test_an_equivalent_needs_its_reason(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    marked = tmp_path / "EQUIVALENT_MUTANTS.txt"
    monkeypatch.setattr(mutation, "EQUIVALENTS", marked)
    marked.write_text("# comment\nsut/reference/bulk.py | a = 1 | a = 2 | only the jump's size changes\n")
    assert mutation.equivalents() == [("sut/reference/bulk.py", "a = 1", "a = 2")]
    marked.write_text("sut/reference/bulk.py | a = 1 | a = 2 |\n")
    with pytest.raises(ValueError, match="EQUIVALENT_MUTANTS.txt: want 'path | before | after | reason'"):
        mutation.equivalents()


def test_a_line_of_code_holding_the_separator_is_written_escaped(tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    # seed 25: the metro's `sent.seq & 0xFFFF` survivor read `... sent.seq | 0xFFFF):` mutated, unmarkable
    from outline.sequences.equivalence import Mark, read_marks
    mark = Mark("sut/reference/metro/tcds.py", "x = a & 0xFFFF", "x = a | 0xFFFF", "why | and why not")
    marked = tmp_path / "EQUIVALENT_MUTANTS.txt"
    marked.write_text(mark.line() + "\n")
    assert "x = a \\| 0xFFFF" in marked.read_text()
    assert read_marks(marked) == [mark]
    monkeypatch.setattr(mutation, "EQUIVALENTS", marked)
    assert mutation.equivalents() == [("sut/reference/metro/tcds.py", "x = a & 0xFFFF", "x = a | 0xFFFF")]


def test_the_checked_in_equivalents_parse() -> None:
    assert all(path.startswith("sut/reference/") for path, _, _ in mutation.equivalents())


def test_a_mark_may_name_the_function_where_the_same_line_is_said_elsewhere_in_the_file() -> None:
    marked = {("sut/reference/atp/vdx.py::Relay.__init__", "self.powered = False", "self.powered = None")}
    mine = Mutant("sut.reference.atp.vdx.xǁRelayǁ__init____mutmut_3", "atp", "sut/reference/atp/vdx.py", 32,
                  "self.powered = False", "self.powered = None")
    other = Mutant("sut.reference.atp.vdx.xǁVdxInterfaceǁpower_off__mutmut_1", "atp", "sut/reference/atp/vdx.py",
                   91, "self.powered = False", "self.powered = None")
    assert mutation.function_of(mine.name) == "Relay.__init__"
    assert mutation.function_of("sut.reference.metro.tcds.x__one_check_encode__mutmut_2") == "_one_check_encode"
    assert mutation.is_marked(mine, marked) and not mutation.is_marked(other, marked)


def test_kill_rate_per_part_counts_timeouts_as_detected_and_untested_as_survivors() -> None:
    def m(part: str, status: str) -> Mutant:
        return Mutant(f"{part}-{status}", part, f"sut/reference/{part}/x.py", 1, "a", "b", status, "")
    sampled = [m("atp", "killed"), m("atp", "survived"), m("metro", "timeout"), m("metro", "no tests"),
               m("metro", "not checked")]
    assert mutation.rates(sampled) == {"atp": (1, 2), "metro": (1, 2), "all": (2, 4)}
    assert "1 sampled mutants were not checked" in mutation.table(sampled, seed=7)
    text = mutation.table(sampled, seed=7)
    assert "| atp | 1/2 = 50.0 % | 1/2 = 50.0 % | 1/2 = 50.0 % |" in text
    assert "| all | 2/4 = 50.0 % | 2/4 = 50.0 % | 2/4 = 50.0 % |" in text
    assert "seed 7" in text


def _evidence(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, *marks: tuple[str, str, str]) -> None:
    """reports/equivalence.json, as if the checker had confirmed these marks in the current budget."""
    from outline.sequences import equivalence
    report = tmp_path / "equivalence.json"
    confirmed = [equivalence.Mark(*m, "") for m in marks]
    report.write_text(json.dumps({"marks": {mark.key: {"verdict": "confirmed", "budget": equivalence.mark_budget(mark)}
                                            for mark in confirmed}}), encoding="utf-8")
    monkeypatch.setattr(equivalence, "REPORT", report)


def test_survivors_marked_equivalent_since_the_draw_leave_the_last_rate_only_with_the_checkers_evidence(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    marked = tmp_path / "EQUIVALENT_MUTANTS.txt"
    marked.write_text("sut/reference/atp/x.py | a | b | the reason\n", encoding="utf-8")
    monkeypatch.setattr(mutation, "EQUIVALENTS", marked)
    sampled = [Mutant("k", "atp", "sut/reference/atp/x.py", 1, "k", "l", "killed", "test_x"),
               Mutant("e", "atp", "sut/reference/atp/x.py", 2, "a", "b", "survived", ""),       # marked since
               Mutant("s", "atp", "sut/reference/atp/x.py", 3, "c", "d", "survived", "")]       # a real gap
    assert mutation.rates(sampled) == {"atp": (1, 3), "all": (1, 3)}
    assert mutation.rates(sampled, reviewed=True) == {"atp": (1, 2), "all": (1, 2)}
    _evidence(tmp_path, monkeypatch)                              # the mark not checked: still a survivor
    text = mutation.table(sampled, seed=1)
    assert "| atp | 1/3 = 33.3 % | 1/3 = 33.3 % | 1/3 = 33.3 % |" in text
    assert "| sut/reference/atp/x.py:2 | `a` -> `b` | survived | marked equivalent, not confirmed by make " \
           "equivalence: a survivor |" in text
    _evidence(tmp_path, monkeypatch, ("sut/reference/atp/x.py", "a", "b"))
    text = mutation.table(sampled, seed=1)
    assert "| atp | 1/3 = 33.3 % | 1/3 = 33.3 % | 1/2 = 50.0 % |" in text
    assert "| sut/reference/atp/x.py:2 | `a` -> `b` | survived | equivalent: marked equivalent |" in text
    assert "| sut/reference/atp/x.py:3 | `c` -> `d` | survived |  |" in text
    (tmp_path / "mutation.json").write_text(json.dumps({"seed": 1, "mutants": [asdict(m) for m in sampled]}))
    assert mutation.main(["--review", "--out", str(tmp_path)]) == 0
    assert "| atp | 1/3 = 33.3 % | 1/3 = 33.3 % | 1/2 = 50.0 % |" in (tmp_path / "mutation.md").read_text(
        encoding="utf-8")


def test_three_rates_of_everything_drawn_after_the_rules_and_after_proven_equivalents(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    marked = tmp_path / "EQUIVALENT_MUTANTS.txt"
    marked.write_text("sut/reference/atp/x.py | p | q | proven\nsut/reference/atp/x.py | u | v | not proven\n",
                      encoding="utf-8")
    monkeypatch.setattr(mutation, "EQUIVALENTS", marked)
    _evidence(tmp_path, monkeypatch, ("sut/reference/atp/x.py", "p", "q"))

    def m(name: str, part: str, status: str, before: str = "a") -> Mutant:
        return Mutant(name, part, f"sut/reference/{part}/x.py", 1, before, "z" if before == "a" else
                      {"p": "q", "u": "v"}[before], status, "")
    sampled = [m(f"k{i}", "atp", "killed") for i in range(6)] + [m("s", "atp", "survived"),
               m("t", "atp", "timeout"), m("mk", "metro", "killed"), m("ms", "metro", "no tests"),
               m("nc", "metro", "not checked")]
    passed = [(m("r1", "atp", "not checked"), "usage error"), (m("r2", "atp", "not checked"), "unread event"),
              (m("e1", "atp", "not checked", "p"), "marked equivalent"),          # its mark confirmed
              (m("e2", "atp", "not checked", "u"), "marked equivalent"),          # its mark not confirmed
              (m("r3", "metro", "not checked"), "never run")]
    three = mutation.three_rates(sampled, passed, why={})
    # atp: 7 of 8 run detected; drawn also 4 passed over; the rules take 2; the proven mark 1 more
    assert three["atp"] == [(7, 12), (7, 10), (7, 9)]
    assert three["metro"] == [(1, 3), (1, 2), (1, 2)]          # the mutant never checked counts nowhere
    assert three["all"] == [(8, 15), (8, 12), (8, 11)]
    # a survivor under a rule made after the draw leaves the second and third rates, as one passed over
    assert mutation.three_rates(sampled, passed, why={"s": "unread field"})["atp"] == [(7, 12), (7, 9), (7, 8)]
    text = mutation.table(sampled, 1, {"usage error": 1}, passed)
    assert "| part | of everything drawn | after the rules | after proven equivalents |" in text
    assert "| atp | 7/12 = 58.3 % | 7/10 = 70.0 % | 7/9 = 77.8 % |" in text


def test_mutmut_mutates_the_references_and_runs_the_features_with_the_kill_recorder() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    mutmut = config["tool"]["mutmut"]
    assert mutmut["source_paths"] == ["sut/reference/"]
    assert mutmut["pytest_add_cli_args_test_selection"] == ["features/", "tests/test_bulk.py", "tests/test_kernel.py",
                                                            "tests/test_bad_input.py", "tests/test_eventlog.py"]
    assert tuple(mutmut["pytest_add_cli_args_test_selection"]) == mutation.MAPPED_TESTS
    assert "outline.mutate.mutation_plugin" in mutmut["pytest_add_cli_args"]
    # snapshots off only while mutmut maps who reaches what (the plugin's pytest_configure), on for each mutant
    assert "--no-snapshots" not in mutmut["pytest_add_cli_args"]
    assert {"steps/", "features/", "outline/", "conftest.py"} <= set(mutmut["also_copy"])
    # coverage (which mutmut needs too): the lines each recorded scenario ran, for the checker's replay order
    assert config["project"]["optional-dependencies"]["mutate"] == ["mutmut==3.8.1", "coverage"]


def test_the_plugin_notes_the_scenario_that_killed_a_mutant(tmp_path: Path) -> None:
    (tmp_path / "features").mkdir()
    (tmp_path / "features" / "test_x.py").write_text("def test_ok():\n    pass\n\ndef test_breaks():\n    assert False\n")
    (tmp_path / "test_own.py").write_text("def test_own():\n    assert False\n")     # not a judge of a train
    kills = tmp_path / "kills.tsv"
    env = dict(os.environ, MUTANT_UNDER_TEST="sut.reference.atp.vdx.xǁRelayǁpower__mutmut_3",
               CRH2_MUTATION_KILLS=str(kills), PYTHONPATH=str(ROOT))
    subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "outline.mutate.mutation_plugin", "-p", "no:cacheprovider",
                    "test_own.py", "features/test_x.py"], cwd=tmp_path, env=env, capture_output=True, text=True,
                   timeout=120)
    assert kills.read_text(encoding="utf-8") == \
        "sut.reference.atp.vdx.xǁRelayǁpower__mutmut_3\tfeatures/test_x.py::test_breaks\n"


def test_the_last_run_becomes_one_entry_of_the_allure_report(tmp_path: Path) -> None:
    kept = tmp_path / "mutation.json"
    assert mutation.to_allure(tmp_path, kept) is None                  # make mutate never ran: nothing added
    sampled = [Mutant("a", "atp", "sut/reference/atp/vdx.py", 135, "x", "y", "killed", "test_fatp04_x"),
               Mutant("b", "crh2", "sut/reference/crh2/ring.py", 9, "x", "y", "survived", "")]
    kept.write_text(json.dumps({"seed": 3, "mutants": [asdict(m) for m in sampled]}), encoding="utf-8")
    result = json.loads(mutation.to_allure(tmp_path, kept).read_text(encoding="utf-8"))
    assert result["name"] == ("Mutation testing of the references: 50.0 % killed after proven equivalents "
                              "(50.0 % of everything drawn, 50.0 % after the rules; target 90 % per reference)")
    assert result["status"] == "failed" and "atp 1/1, crh2 0/1" in result["statusDetails"]["message"]
    attached = (tmp_path / result["attachments"][0]["source"]).read_text(encoding="utf-8")
    assert "| sut/reference/atp/vdx.py:135 | `x` -> `y` | killed | test_fatp04_x |" in attached


def test_the_summary_names_the_mutation_entry_and_does_not_count_it_as_a_scenario(tmp_path: Path) -> None:
    from outline.report import summary
    kept = tmp_path / "mutation.json"
    kept.write_text(json.dumps({"seed": 1, "mutants": [asdict(Mutant("a", "atp", "p.py", 1, "x", "y", "killed"))]}))
    mutation.to_allure(tmp_path, kept)
    text = summary.format_summary(summary.summarize(summary.load_results(tmp_path)))
    assert text.splitlines()[0].startswith("0 scenarios: 0 passed")
    assert text.splitlines()[-1] == ("Mutation testing of the references: 100.0 % killed after proven "
                                     "equivalents (100.0 % of everything drawn, 100.0 % after the rules; "
                                     "target 90 % per reference)")


def _usage_error_lines(root: Path, monkeypatch: pytest.MonkeyPatch, path: str, source: str) -> list[int]:
    """The lines of `source`, written as `path` under a project at `root`, that `make mutate` counts as part of
    a usage error."""
    (root / path).parent.mkdir(parents=True)
    (root / path).write_text(source, encoding="utf-8")
    monkeypatch.setattr(mutation, "ROOT", root)
    monkeypatch.setattr(mutation, "_RAISES", {})
    return [line for line in range(1, source.count("\n") + 2) if mutation.in_usage_error(path, line)]


def test_a_mutant_inside_a_usage_error_is_passed_over_and_counted(tmp_path: Path,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    path = "sut/reference/atp/desk.py"
    assert _usage_error_lines(tmp_path, monkeypatch, path, (
        "from sut.errors import OutOfRange\n\ndef set_notch(n):\n    if not 0 <= n <= 7:\n"
        "        raise OutOfRange('notch', n,\n                         '0..7')\n"
        "    if n == 3:\n        raise ValueError('three')\n    return n\n")) == [5, 6]

    lines = {"x_set_notch__mutmut_1": (4, "if not 1 <= n <= 7:"), "x_set_notch__mutmut_2": (6, "'XX0..7XX')"),
             "x_set_notch__mutmut_3": (8, "raise ValueError('THREE')")}
    monkeypatch.setattr(mutation, "describe", lambda name: Mutant(
        name, "atp", path, lines[name.split(".")[-1]][0], "", lines[name.split(".")[-1]][1]))
    monkeypatch.setattr(mutation, "equivalents", lambda: [])
    left_out: dict[str, int] = {}
    names = [f"sut.reference.atp.desk.{n}" for n in sorted(lines)]
    chosen = mutation.sample(names, 3, seed=1, left_out=left_out)
    # The guard's test is drawn: `1 <= n` refuses notch 0, a good stimulus.
    assert sorted(m.name.split(".")[-1] for m in chosen) == ["x_set_notch__mutmut_1", "x_set_notch__mutmut_3"]
    assert left_out == {"usage error": 1}
    assert "Passed over while drawing: 1 usage error" in mutation.table(chosen, 1, left_out)


def test_a_train_reference_is_judged_by_the_scenarios_and_bad_input_the_engine_also_by_its_own_tests() -> None:
    from outline.mutate.mutation_plugin import judges
    ids = ["tests/test_bulk.py::test_both_ways", "features/test_outline.py::test_fnet01_a", "tests/test_kernel.py::test_k",
           "features/test_outline.py::test_filk06_b", "tests/test_bad_input.py::test_unknown_names[0]"]
    assert judges("sut.reference.crh2.ring.xǁRingǁ_start__mutmut_4", ids) == \
        ["tests/test_bad_input.py::test_unknown_names[0]", "features/test_outline.py::test_fnet01_a",
         "features/test_outline.py::test_filk06_b"]
    assert judges("sut.reference.bulk.x_slope__mutmut_53", ids) == \
        ["tests/test_bulk.py::test_both_ways", "tests/test_kernel.py::test_k",
         "features/test_outline.py::test_fnet01_a", "features/test_outline.py::test_filk06_b"]


@pytest.mark.parametrize(("under_test", "snapshots"), [("stats", False), ("", True),
                                                       ("sut.reference.crh2.ring.xǁRingǁ_start__mutmut_4", True)])
def test_snapshots_are_off_only_while_mutmut_maps_scenarios_to_functions(under_test: str, snapshots: bool,
                                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    # A scenario restored from a stored state never calls the functions that built it: in the mapping run
    # that would hide who reaches what; in a mutant's own run (a fresh session) every stored state was built
    # under that mutant, so the verdicts are those of a run without snapshots.
    from types import SimpleNamespace

    from outline.mutate import mutation_plugin
    monkeypatch.setenv("MUTANT_UNDER_TEST", under_test)
    config = SimpleNamespace(option=SimpleNamespace(no_snapshots=False))
    mutation_plugin.pytest_configure(config)
    assert config.option.no_snapshots is not snapshots


def test_a_mutant_of_a_backend_s_self_description_is_passed_over_and_counted(monkeypatch: pytest.MonkeyPatch) -> None:
    names = ["sut.reference.metro.backend.xǁReferenceMetroǁdescribe__mutmut_3",
             "sut.reference.metro.config.xǁMetroConfigǁdescribe__mutmut_23",
             "sut.reference.metro.backend.xǁReferenceMetroǁmonitor__mutmut_2"]
    monkeypatch.setattr(mutation, "describe", lambda name: Mutant(name, "metro", "sut/reference/metro/backend.py",
                                                                  1, "a", "b"))
    monkeypatch.setattr(mutation, "equivalents", lambda: [])
    monkeypatch.setattr(mutation, "in_usage_error", lambda path, line: False)
    left_out: dict[str, int] = {}
    chosen = mutation.sample(names, 3, seed=1, left_out=left_out)
    assert [m.name for m in chosen] == [names[2]]
    assert left_out == {"self-description": 2}


def test_a_backend_s_name_list_and_input_read_back_are_passed_over_but_a_model_s_input_is_not(
        monkeypatch: pytest.MonkeyPatch) -> None:
    names = ["sut.reference.metro.backend.xǁReferenceMetroǁinput__mutmut_1",
             "sut.reference.crh2.backend.xǁReferenceTrainǁvehicle_names__mutmut_2",
             "sut.reference.metro.ports.xǁIoPortǁinput__mutmut_1"]
    monkeypatch.setattr(mutation, "describe", lambda name: Mutant(
        name, "metro", mutation.NAME.match(name)["module"].replace(".", "/") + ".py", 1, "a", "b"))
    monkeypatch.setattr(mutation, "equivalents", lambda: [])
    monkeypatch.setattr(mutation, "in_usage_error", lambda path, line: False)
    left_out: dict[str, int] = {}
    chosen = mutation.sample(names, 10, seed=1, left_out=left_out)     # more than there are: every one seen
    assert [m.name for m in chosen] == [names[2]]
    assert left_out == {"stimulus read-back": 1, "self-description": 1}


def test_a_resumed_run_keeps_the_kills_and_runs_survivors_and_the_unchecked_again(tmp_path: Path,
                                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    drawn = [Mutant(f"sut.reference.atp.vdx.x_f__mutmut_{n}", "atp", "sut/reference/atp/vdx.py", 1, "a", "b")
             for n in (1, 2, 3, 4)]
    before = {drawn[0].name: 1, drawn[1].name: 0, drawn[2].name: None, drawn[3].name: 36}   # killed, survived, -, timeout
    after = {**before, drawn[1].name: 1, drawn[2].name: 0}
    ran: list[tuple[str, ...]] = []
    try:
        import mutmut.stats  # noqa: F401  (installed by make mutate, not by make test)
    except ModuleNotFoundError:             # mutmut's own table of exit codes, the part run() reads
        from collections import defaultdict
        from types import ModuleType
        stats = ModuleType("mutmut.stats")
        stats.status_by_exit_code = defaultdict(lambda: "suspicious", {1: "killed", 0: "survived", 36: "timeout",
                                                                       33: "no tests", None: "not checked"})
        monkeypatch.setitem(sys.modules, "mutmut", ModuleType("mutmut"))
        monkeypatch.setitem(sys.modules, "mutmut.stats", stats)
    kills = tmp_path / "kills.tsv"
    kills.write_text(f"{drawn[0].name}\tfeatures/test_outline.py::test_fatp01_a\n", encoding="utf-8")
    monkeypatch.setattr(mutation, "KILLS", kills)
    monkeypatch.setattr(mutation, "_codes", lambda: after if ran else before)
    monkeypatch.setattr(mutation, "_mutmut", lambda *args, env=None: ran.append(args))
    monkeypatch.setattr(mutation, "probe_mutant_mode", lambda: ran.append(("probe",)))
    mutation.run(drawn, 2, resume=True)
    assert ran == [("probe",), ("run", "--max-children", "2", drawn[1].name, drawn[2].name)]
    assert [m.status for m in drawn] == ["killed", "killed", "survived", "timeout"]
    assert drawn[0].killed_by == "test_fatp01_a"          # the last run's killer kept


def test_a_mutant_inside_the_emit_of_an_event_no_check_reads_is_passed_over() -> None:
    def line_of(path: str, text: str) -> int:
        lines = (ROOT / path).read_text(encoding="utf-8").splitlines()
        return next(i for i, line in enumerate(lines, start=1) if text in line)

    vdx = "sut/reference/atp/vdx.py"
    assert mutation.in_unread_event(vdx, line_of(vdx, '"fs.on"'))              # the relays are what steps read
    assert not mutation.in_unread_event(vdx, line_of(vdx, '"loop.change"'))    # "the loop opens within 6 ms"
    assert not mutation.in_unread_event(vdx, line_of(vdx, "self.testing = True"))
    kinds, _, _ = mutation.read_kinds()
    assert {"loop.change", "out.change", "cmd.rx", "wtb.msg"} <= kinds
    assert "line.switch" not in kinds              # named only by the timing diagram, which is not a check
    onboard = "sut/reference/atp/onboard.py"       # a kind without a dot, and the kind is the last positional
    assert mutation.in_unread_event(onboard, line_of(onboard, 'self._emit("ATP", "balise", group=group'))
    assert not mutation.in_unread_event(onboard, line_of(onboard, '"neutral.command", state='))


def test_the_map_is_made_again_when_a_scenario_or_step_changes(tmp_path: Path) -> None:
    (tmp_path / "features" / "x").mkdir(parents=True)
    (tmp_path / "steps").mkdir()
    feature = tmp_path / "features" / "x" / "F-X-01.feature"
    feature.write_text("Feature: x\n  Scenario: a\n    Given one\n", encoding="utf-8")
    (tmp_path / "steps" / "s.py").write_text("# steps\n", encoding="utf-8")
    before = mutation.scenarios_digest(tmp_path)
    assert mutation.scenarios_digest(tmp_path) == before
    feature.write_text("Feature: x\n  Scenario: a\n    Given one\n    Then two\n", encoding="utf-8")
    assert mutation.scenarios_digest(tmp_path) != before      # same scenario id, new steps: mapped again
    changed = mutation.scenarios_digest(tmp_path)
    (tmp_path / "README.md").write_text("not a scenario", encoding="utf-8")
    assert mutation.scenarios_digest(tmp_path) == changed     # what no scenario is made from leaves the map


STEPS = """from steps import analysis


@given("one")
def _():
    analysis.check(1)


@then("two")
def _():
    pass
"""


def test_a_step_module_is_read_as_its_step_definitions_and_the_rest(tmp_path: Path) -> None:
    module = tmp_path / "s.py"
    module.write_text(STEPS, encoding="utf-8")
    definitions, rest = mutation.step_definitions(module)
    assert sorted(definitions) == [4, 9]                      # the first decorator's line: co_firstlineno
    module.write_text(STEPS + '\n\n# a new one\n@then("three")\ndef _():\n    pass\n', encoding="utf-8")
    grown, same_rest = mutation.step_definitions(module)
    assert same_rest == rest and set(definitions.values()) < set(grown.values())
    module.write_text(STEPS.replace("analysis.check(1)", "analysis.check(2)"), encoding="utf-8")
    edited, still_rest = mutation.step_definitions(module)
    assert still_rest == rest and edited[4] != definitions[4] and edited[9] == definitions[9]
    module.write_text(STEPS.replace("from steps import analysis", "from steps import analysis, zh"), encoding="utf-8")
    assert mutation.step_definitions(module)[1] != rest      # an import: every definition may read it


def test_only_the_tests_made_of_what_changed_are_mapped_again() -> None:
    old = {"features/a.feature": "1", "features/b.feature": "1", "steps/s.py": "r", "steps/s.py@one": "one",
           "steps/s.py@two": "two", "steps/analysis.py": "h", "steps/fixtures.py": "f", "tests/test_bulk.py": "t"}
    inputs = {"features/test_outline.py::test_a": ["features/a.feature", "steps/s.py", "steps/s.py@one"],
              "features/test_outline.py::test_b": ["features/b.feature", "steps/s.py", "steps/s.py@two"],
              "tests/test_bulk.py::test_c": ["tests/test_bulk.py"]}
    imports = {"steps/s.py": {"steps/s.py", "steps/analysis.py"}, "steps/analysis.py": {"steps/analysis.py"},
               "steps/fixtures.py": {"steps/fixtures.py"}}

    def again(**changes: str | None) -> set[str] | None:
        new = dict(old)
        for name, digest in changes.items():
            name = name.replace("__", "/").replace("_feature", ".feature").replace("_py", ".py")
            if digest is None:
                new.pop(name, None)
            else:
                new[name] = digest
        found = mutation.tests_to_map_again(old, new, inputs, imports)
        return None if found is None else {t.rsplit("_", 1)[-1] for t in found}

    assert again() == set()
    assert again(features__a_feature="2") == {"a"}                     # its own scenarios
    assert again(**{"steps__s_py@two": None, "steps__s_py@three": "three"}) == {"b"}    # a definition edited
    assert again(**{"steps__s_py@four": "four"}) == set()              # one added: new scenarios are new tests
    assert again(steps__analysis_py="h2") == {"a", "b"}                # a helper their step module imports
    assert again(tests__test_bulk_py="t2") == {"c"}
    assert again(steps__fixtures_py="f2") is None                      # no noted test is made of it: all
    assert again(outline__mutate__mutation_plugin_py="p2") is None             # how every test is mapped: all


def test_tests_taken_out_of_mutmuts_map_are_mapped_again_as_new(tmp_path: Path) -> None:
    stats = tmp_path / "mutmut-stats.json"
    stats.write_text(json.dumps({"tests_by_mangled_function_name": {"f": ["a", "b"], "g": ["b"]},
                                 "duration_by_test": {"a": 1.0, "b": 2.0}, "stats_time": 3.0}), encoding="utf-8")
    mutation._forget(stats, {"b"})
    data = json.loads(stats.read_text(encoding="utf-8"))
    assert data["tests_by_mangled_function_name"] == {"f": ["a"], "g": []}
    assert data["duration_by_test"] == {"a": 1.0} and data["stats_time"] == 3.0


@pytest.mark.cost(3)
def test_what_each_scenario_is_made_of_is_noted_from_the_real_features(tmp_path: Path,
                                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(mutation, "INPUTS", tmp_path / "inputs.json")
    mutation.note_inputs()
    inputs = json.loads((tmp_path / "inputs.json").read_text(encoding="utf-8"))
    sources = mutation.map_sources()
    scenario = next(test for test, made_of in inputs.items() if "features/function/network-transmission-redundancy/"
                    "F-NET-25.feature" in made_of)
    assert {"steps/train.py", "steps/metro.py"} <= set(inputs[scenario])
    assert all(f in sources for f in inputs[scenario] if f.startswith(("steps/", "features/function")))
    kernel = [test for test in inputs if test.startswith("tests/test_kernel.py::")]
    assert kernel and all(inputs[test] == ["tests/test_kernel.py"] for test in kernel)


def test_an_if_that_names_the_known_names_and_raises_a_usage_error_is_passed_over(tmp_path: Path,
                                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    assert _usage_error_lines(tmp_path, monkeypatch, "sut/reference/metro/reading.py", (
        "from sut.errors import UnknownName\n\ndef reading(name, wanted):\n"
        "    if wanted is None or name != wanted:\n        known = ['speed', wanted]\n"
        "        raise UnknownName('reading', name, known)\n    if name == 'x':\n"
        "        print('a side effect')\n        raise UnknownName('reading', name, [])\n"
        "    return 1\n")) == [5, 6, 9]


def test_a_mutant_in_a_branch_only_faulty_variants_take_is_passed_over() -> None:
    def line_of(path: str, text: str) -> int:
        lines = (ROOT / path).read_text(encoding="utf-8").splitlines()
        return next(i for i, line in enumerate(lines, start=1) if text in line)

    node = "sut/reference/crh2/node.py"        # block_data_both_ways defaults to True: the else is the variant's
    assert mutation.in_variant_only_branch(node, line_of(node, "self.train.ring.send(self, frame, R if"))
    assert not mutation.in_variant_only_branch(node, line_of(node, "self.train.ring.broadcast(self, frame)\n"
                                                             .strip()))
    ring = "sut/reference/crh2/ring.py"        # self.source_id is only ever set from packet_source_id (None)
    assert mutation.in_variant_only_branch(ring, line_of(ring, "offset, _ = declared_length(frame.wire)"))
    vehicle = "sut/reference/crh2/vehicle.py"  # the test itself is behaviour: its mutants stay in
    assert not mutation.in_variant_only_branch(vehicle, line_of(vehicle, "if oil and self.train.cfg.behaviour."
                                                                         "oil_protection:"))
    assert mutation.behaviour_defaults("sut/reference/metro/tcds.py")["message_ack"] is True


@pytest.mark.parametrize(("test", "value"), [
    ("behaviour.on", True), ("not behaviour.on", False), ("self.cfg.behaviour.off", False),
    ("not behaviour.on and frame.ok", False),              # decided by the switch alone
    ("behaviour.on and frame.ok", None),                   # the reference's frames decide: not a variant's branch
    ("behaviour.on or frame.ok", True), ("behaviour.number is not None", False), ("behaviour.bits == 32", True),
    ("self.alias", False), ("self.mixed", None),
])
def test_a_test_is_read_with_the_switches_at_their_defaults(test: str, value: bool | None) -> None:
    import ast

    defaults = {"on": True, "off": False, "number": None, "bits": 32}
    got = mutation._value(ast.parse(test, mode="eval").body, {"alias": "off"}, defaults)
    assert (None if got is mutation._UNKNOWN else got) == value


def test_the_test_of_an_if_that_only_emits_unread_events_is_passed_over() -> None:
    tcds = "sut/reference/metro/tcds.py"      # train.stop: only the timing diagram names it
    lines = (ROOT / tcds).read_text(encoding="utf-8").splitlines()
    stop = next(i for i, text in enumerate(lines, start=1) if text.strip() == "if self.speed_kmh == 0:")
    assert 'emit("train", "train.stop")' in lines[stop] and mutation.in_unread_event(tcds, stop)
    assert not mutation.in_unread_event(tcds, stop - 1)      # the speed itself is read
    apply_ = next(i for i, text in enumerate(lines, start=1) if text.strip() == "if mode != self.modes[unit]:")
    assert not mutation.in_unread_event(tcds, apply_)        # its body changes the mode too


def test_a_mutant_in_a_field_no_check_reads_is_passed_over_one_in_a_read_field_is_not() -> None:
    bulk = "sut/reference/bulk.py"
    lines = (ROOT / bulk).read_text(encoding="utf-8").splitlines()
    line = next(i for i, text in enumerate(lines, start=1) if '"time.skip", frm=sampled_until' in text)
    before = lines[line - 1].strip()
    # time.skip is read for where a skip starts and ends (frm, to), never for its period
    assert mutation.in_unread_field(bulk, line, before, before.replace("period_us=period", "period_us=None"))
    assert not mutation.in_unread_field(bulk, line, before, before.replace("frm=sampled_until", "frm=None"))
    assert not mutation.in_unread_field(bulk, line, before, before.replace('"time.skip"', '"XXtime.skipXX"'))
    assert {"frm", "to", "state"} <= mutation.read_fields() and "period_us" not in mutation.read_fields()


def test_a_change_that_may_raise_instead_is_no_longer_passed_over_by_what_nobody_reads() -> None:
    """The two rule exclusions the differential checker overturned (reports/equivalence.md, 2026-11-27)."""
    vdx, backend = "sut/reference/atp/vdx.py", "sut/reference/metro/backend.py"
    texts = {path: (ROOT / path).read_text(encoding="utf-8").splitlines() for path in (vdx, backend)}
    field = next(i for i, t in enumerate(texts[vdx], start=1) if "fall_ms=round(fall, 3)" in t)
    before = texts[vdx][field - 1].strip()
    assert mutation.rule_reason(vdx, field, before, before.replace("fall_ms=round(fall, 3)", "fall_ms=round(fall, 4)")) \
        == "unread field"
    assert mutation.rule_reason(vdx, field, before, before.replace("round(fall, 3)", "round(None, 3)")) is None
    raise_ = next(i for i, t in enumerate(texts[backend], start=1) if 'raise UnknownName("reading", name, known)' in t)
    before = texts[backend][raise_ - 1].strip()
    assert mutation.rule_reason(backend, raise_, before, before.replace('"reading"', '"XXreadingXX"')) == "usage error"
    assert mutation.rule_reason(backend, raise_, before, before.replace("name, known", "None, known")) is None
    assert mutation.may_raise_otherwise("f(a, b)", "f(a, )") and mutation.may_raise_otherwise("f(a, b)", "f(b)")
    assert not mutation.may_raise_otherwise("x = a < b", "x = a <= b")


def test_the_columns_a_mutation_changes_are_found_in_its_line() -> None:
    line = '        emit("a", x=1, y=2)'
    assert mutation.changed_columns(line, 'emit("a", x=1, y=2)', 'emit("a", x=1, y=None)') == (25, 26)
    assert mutation.changed_columns(line, 'emit("a", x=1, y=2)', 'emit("a", y=2)') == (18, 23)   # the comma too


def test_code_the_switches_leave_unread_and_functions_only_a_variant_calls_are_passed_over() -> None:
    def at(path: str, text: str) -> tuple[int, str]:
        lines = (ROOT / path).read_text(encoding="utf-8").splitlines()
        line = next(i for i, found in enumerate(lines, start=1) if text in found)
        return line, lines[line - 1].strip()

    def reason(path: str, text: str, old: str, new: str) -> str | None:
        line, before = at(path, text)
        assert old in before
        return mutation.never_run_reason(path, line, before, before.replace(old, new, 1))

    lcu = "sut/reference/crh2/lcu.py"          # path3_steps_only (True) decides the `or` before these are read
    assert reason(lcu, "or not self.lcu.mdm8.alive)", "not self.lcu", "self.lcu") == "decided by the switches"
    # ... but the deciding operand is the reference's behaviour
    assert reason(lcu, "steps_only = behaviour.do_steps_only", "behaviour.do_steps_only", "True") is None
    tcds = "sut/reference/metro/tcds.py"       # long_one: a local the switches decide (one_check_sequence off)
    assert reason(tcds, "wire = _one_check_encode(data) if long_one", "_one_check_encode(data)", "None") \
        == "decided by the switches"
    assert reason(tcds, "wire = _one_check_encode(data) if long_one", "encode_slave(data)", "None") is None
    # functions whose every use is in such code: the one-check codec, the status data on the self-diagnostic
    # line (after an early return the switch decides)
    assert reason(tcds, "if len(raw) != size_bits // 8 + 1", "// 8", "// 9") == "only a faulty variant calls it"
    selfdiag = "sut/reference/crh2/selfdiag.py"
    assert reason(selfdiag, 'self._queue(("status"', '"status"', '"XXstatusXX"') == "only a faulty variant calls it"
    assert reason(selfdiag, "self.queue.append(item)", "append", "appendleft") is None     # commands use it
    # a method the steps call through the driver interface is in
    assert reason("sut/reference/crh2/backend.py", "if me is not self.train.block_master()", "is not", "is") is None


def test_a_mutants_run_starts_with_the_references_per_process_caches_empty(monkeypatch: pytest.MonkeyPatch) -> None:
    from types import SimpleNamespace

    from outline.mutate import mutation_plugin
    from sut.reference import bulk
    from sut.reference.crh2 import frames
    from sut.reference.crh2.backend import ReferenceTrain
    from sut.reference.metro import tcds

    train = ReferenceTrain()
    train.power_on()
    train.advance_ms(1200)                          # bulk reads the train; packets are built from templates
    assert bulk._CLASSES and frames._TEMPLATES
    caches = mutation_plugin.reference_caches()
    assert all(any(cache is found for found in caches)
               for cache in (bulk._CLASSES, frames._TEMPLATES, frames._ZERO_RUNS, tcds._message_us))
    monkeypatch.setenv("MUTANT_UNDER_TEST", "stats")              # mutmut's map: the caches stay
    mutation_plugin.pytest_configure(SimpleNamespace(option=SimpleNamespace(no_snapshots=False)))
    assert bulk._CLASSES
    monkeypatch.setenv("MUTANT_UNDER_TEST", "sut.reference.bulk.x__class_info__mutmut_1")
    mutation_plugin.pytest_configure(SimpleNamespace(option=SimpleNamespace(no_snapshots=False)))
    assert not bulk._CLASSES and not frames._TEMPLATES and not frames._ZERO_RUNS
    assert tcds._message_us.cache_info().currsize == 0
    train.advance_ms(100)                           # filled again as they are needed
    assert bulk._CLASSES or frames._TEMPLATES


def test_a_mutated_modules_own_tables_of_mutants_are_not_taken_for_caches(tmp_path: Path,
                                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    """A module as mutmut writes it (a trampoline per function, its mutants in a module-level table filled at
    the end): emptying that table before a mutant's run left every trampolined call without its original, so
    every test failed and every mutant looked killed (seed 7's first run). The module's real cache is still
    emptied."""
    import importlib.util
    from types import SimpleNamespace

    from outline.mutate import mutation_plugin

    source = tmp_path / "mutated_shape.py"
    source.write_text(
        "MutantDict = dict\n"
        "_LOOKUPS: dict[str, int] = {}\n"
        "mutants_x_lookup__mutmut: MutantDict = {}  # type: ignore\n"
        "mutants_xǁPartǁread__mutmut = {}\n"
        "def x_lookup__mutmut_orig(name):\n"
        "    return _LOOKUPS.setdefault(name, len(name))\n"
        "mutants_x_lookup__mutmut['_mutmut_orig'] = x_lookup__mutmut_orig\n"
        "mutants_xǁPartǁread__mutmut['_mutmut_orig'] = x_lookup__mutmut_orig\n", encoding="utf-8")
    spec = importlib.util.spec_from_file_location("sut.reference.mutated_shape", source)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    monkeypatch.setitem(sys.modules, "sut.reference.mutated_shape", module)
    module.x_lookup__mutmut_orig("VCB")

    caches = mutation_plugin.reference_caches()
    assert any(cache is module._LOOKUPS for cache in caches)
    tables = (module.mutants_x_lookup__mutmut, getattr(module, "mutants_xǁPartǁread__mutmut"))
    assert not any(cache is table for cache in caches for table in tables)
    monkeypatch.setenv("MUTANT_UNDER_TEST", "sut.reference.mutated_shape.x_lookup__mutmut_1")
    mutation_plugin.pytest_configure(SimpleNamespace(option=SimpleNamespace(no_snapshots=False)))
    assert not module._LOOKUPS and all("_mutmut_orig" in table for table in tables)


def test_while_mutmut_maps_every_test_starts_with_the_caches_empty(monkeypatch: pytest.MonkeyPatch) -> None:
    """The map is learnt in one process: a cache filled by the first test that reads a class would hide the
    code that fills it from every later test, and a mutant of that code would meet only the first."""
    from outline.mutate import mutation_plugin
    from sut.reference import bulk

    monkeypatch.setitem(bulk._CLASSES, int, ())
    monkeypatch.setenv("MUTANT_UNDER_TEST", "sut.reference.bulk.x__class_info__mutmut_1")
    mutation_plugin.pytest_runtest_setup(None)
    assert int in bulk._CLASSES                   # a mutant's own run: emptied once, at its start
    monkeypatch.setenv("MUTANT_UNDER_TEST", "stats")
    mutation_plugin.pytest_runtest_setup(None)
    assert not bulk._CLASSES


def test_each_modules_caches_are_read_from_its_source_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """The map asks before every test, and a mutated module's source is large (6 s for all of them)."""
    import ast

    from outline.mutate import mutation_plugin
    import sut.reference.bulk  # noqa: F401

    first = mutation_plugin.reference_caches()
    parsed: list[str] = []
    monkeypatch.setattr(ast, "parse", lambda source, *a, **k: parsed.append(source) or ast.Module([], []))
    again = mutation_plugin.reference_caches()
    assert not parsed and len(again) == len(first) and all(a is b for a, b in zip(again, first))


def test_a_field_no_contract_lists_is_passed_over_unless_the_change_may_raise() -> None:
    """The contracts define what a step can read of an event (the guard refuses any other field), so a change
    to an unlisted field is unobservable, provided it cannot raise: its whole value made None or the keyword
    dropped cannot; None inside the computation of its value may."""
    onboard, vdx = "sut/reference/atp/onboard.py", "sut/reference/atp/vdx.py"
    line, before = _line_saying(onboard, 'self._emit("ATP", "def.step", step=step + 1')
    assert mutation.rule_reason(onboard, line, before, before.replace("step=step + 1", "step=None")) == "unlisted field"
    assert mutation.in_unlisted_field(onboard, line, before, before.replace("step + 1", "step + 2"))
    listed = before.replace('readback="ok" if readback else "wrong"', "readback=None")   # def.step lists readback
    assert mutation.rule_reason(onboard, line, before, listed) is None
    line, before = _line_saying(vdx, 'self._emit(self.name, "relay.change", energised=energised)')
    assert mutation.rule_reason(vdx, line, before, before.replace("energised=energised", "")) == "unlisted field"
    # None inside a field's computation may raise (round(None, 3)): not this rule's to pass over.
    line, before = _line_saying(onboard, 'self._emit("ATP", "mode.change", mode=mode, at_m=round(self.position_m, 3))')
    inside = before.replace("round(self.position_m, 3)", "round(None, 3)")
    assert mutation.in_unlisted_field(onboard, line, before, inside) is False
    assert mutation.in_unlisted_field(onboard, line, before, before.replace("round(self.position_m, 3)", "None"))


def test_a_field_change_that_may_raise_is_no_rule_s_to_pass_over() -> None:
    """The checker overturned `cab=fields["XXcabXX"]` under "unlisted field" (a KeyError every run that
    receives a command meets): a change inside a subscript, a call or arithmetic of an unread or unlisted
    field may raise, so neither rule passes it over."""
    lcu = "sut/reference/crh2/lcu.py"
    lines = (ROOT / lcu).read_text(encoding="utf-8").splitlines()
    line = next(i for i, text in enumerate(lines, start=1) if 'self.emit("cmd.rx", seq=fields["seq"]' in text)
    before = lines[line - 1].strip()
    after = before.replace('cab=fields["cab"]', 'cab=fields["XXcabXX"]')
    assert mutation.rule_reason(lcu, line, before, after) is None
    assert mutation.rule_reason(lcu, line, before, before.replace('cab=fields["cab"]', "cab=None")) == "unlisted field"


def test_the_source_of_an_event_no_contract_lists_is_passed_over_unless_the_change_may_raise() -> None:
    """An emit stores its source as it is; an event of a kind no contract lists is read by no step and compared
    by no checker, so its source is as unobservable as its unlisted fields (seed 9: `cfsk.carrier_set` and
    `order.given` signed None survived). A listed kind's source is checked wherever a step reads the event."""
    onboard, ccu = "sut/reference/atp/onboard.py", "sut/reference/crh2/ccu.py"
    line, before = _line_saying(onboard, 'self._emit("CFSK", "cfsk.carrier_set"')
    assert mutation.rule_reason(onboard, line, before, before.replace('"CFSK"', "None")) == "unlisted source"
    renamed = before.replace('"CFSK"', '"XXCFSKXX"')                   # no None: the older rule's already
    assert mutation.in_unlisted_source(onboard, line, before, renamed)
    assert mutation.rule_reason(onboard, line, before, renamed) == "unread event"
    line, before = _line_saying(ccu, '"order.given", name=name, value=value)')
    assert mutation.rule_reason(ccu, line, before, before.replace('f"car{self.car}.monitor"', "None")) == \
        "unlisted source"
    assert mutation.in_unlisted_source(ccu, line, before, before.replace("car{self.car}", "XXcar{self.car}XX"))
    line, before = _line_saying(onboard, 'self._emit("ATP", "linking.missing", group=link.group, reaction="none")')
    assert mutation.rule_reason(onboard, line, before, before.replace('"ATP"', '"atp"')) is None     # listed
    assert not mutation.in_unlisted_source(onboard, line, before, before.replace('"linking.missing"', "None"))


def test_a_usage_error_worded_with_none_is_passed_over_only_where_its_constructor_only_words_it() -> None:
    """OutOfRange words all three of its arguments; UnknownName words what it is asked for but sorts the
    known names and looks the name up among them, where None raises a TypeError instead (seed 9 drew
    `OutOfRange(name, value, None)` and `UnknownName(None, name, lamps)`: both the same error, only worded
    "None"). A dropped argument is a TypeError either way."""
    assert mutation.words_only_parameters()["OutOfRange"] == ("what", "value", "allowed")
    assert mutation.words_only_parameters()["UnknownName"] == ("what", "", "")
    atp, crh2 = "sut/reference/atp/backend.py", "sut/reference/crh2/backend.py"
    line, before = _line_saying(atp, 'raise OutOfRange(name, value, f"{limits[0]:g}..{limits[1]:g}")')
    assert mutation.rule_reason(atp, line, before, "raise OutOfRange(name, value, None)") == "usage error worded None"
    assert mutation.rule_reason(atp, line, before, 'raise OutOfRange(name, value, )') is None
    line, before = _line_saying(crh2, 'raise UnknownName("cab lamp", name, lamps)')
    assert mutation.rule_reason(crh2, line, before, "raise UnknownName(None, name, lamps)") == \
        "usage error worded None"
    assert mutation.rule_reason(crh2, line, before, 'raise UnknownName("cab lamp", None, lamps)') is None
    assert mutation.rule_reason(crh2, line, before, 'raise UnknownName("cab lamp", name, None)') is None


def test_a_keyword_dropped_from_the_middle_of_an_emit_is_inside_that_keyword() -> None:
    """mutmut drops a middle keyword with the ", " after it; seed 9 drew `to=to, ` of the metro's line.switch
    (no contract lists that kind) and the field rules did not see the change as inside the keyword."""
    tcds = "sut/reference/metro/tcds.py"
    line, before = _line_saying(tcds, '"line.switch", frm=frm, to=to, reason=why')
    assert mutation.rule_reason(tcds, line, before, before.replace("to=to, ", "")) == "unlisted field"
    assert mutation.rule_reason(tcds, line, before, before.replace("reason=why", "")) == "unlisted field"
    # A listed field dropped from the middle stays a mutant to run.
    onboard = "sut/reference/atp/onboard.py"
    line, before = _line_saying(onboard, 'self._emit("ATP", "linking.missing", group=link.group, reaction="none")')
    assert mutation.rule_reason(onboard, line, before, before.replace("group=link.group, ", "")) is None
