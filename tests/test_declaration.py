"""Implementation declarations (sut/contract/declaration.py): every mistake is an error naming the file, line
and key before any scenario runs; the reference's declarations tell the truth about it; a scenario needing an
option a SUT does not claim is "not applicable", reported apart from pass, fail and skip."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from outline.report.summary import load_results, summarize
from sut.contract.declaration import DeclarationError, form, load, of_backend
from sut.reference.atp.backend import ReferenceAtp
from sut.reference.crh2.backend import ReferenceTrain
from sut.reference.metro.backend import ReferenceMetro
from steps import messages
from tests.variants import (CRH2_FAULTS_ZH, CRH2_RECORDS_ZH, FREEDOM, IN_BAND, METRO_MODES_ZH, METRO_TEXTS_ZH,
                            ChineseDisplayMetro, ChineseMonitorCrh2)

ROOT = Path(__file__).resolve().parents[1]

GOOD_ATP = """\
sut: vendor
profiles:
  vdx:
    options: [vdx-new-firmware]
    parameters: {timing_resolution_us: 1000}
  atp:
    parameters:
      timing_resolution_us: 1000
      d_sen_m: 3.0
      position_uncertainty_m: 5.0
      decode_delay_ms: 150
      cfsk_period_ms: 50
    texts:
      CFSK fault: CFSK故障
"""


GOOD_METRO = """\
sut: vendor
profiles:
  metro-tcn:
    parameters:
      timing_resolution_us: 1000
    texts:
      no cab: 无激活司机室
      "<bus> line <line>: fault": "<bus> <line>线故障"
"""


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "vendor.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_a_good_declaration_gives_its_options_parameters_and_texts(tmp_path: Path) -> None:
    found = load(_write(tmp_path, GOOD_ATP))
    atp, vdx = found.of("atp"), found.of("vdx")
    assert vdx.claims("vdx-new-firmware") and not vdx.claims("vdx-old-firmware") and not atp.claims("vdx-new-firmware")
    assert atp.parameter("timing_resolution_us") == 1000
    assert atp.text("CFSK fault") == "CFSK故障"
    assert atp.text("DEF fault") == "DEF fault"          # not declared: the message identifier itself


@pytest.mark.parametrize(("change", "where", "why"), [
    (("sut: vendor\n", "sut: vendor\nvendor: x\n"), ":2: vendor:", "unknown key"),
    (("  atp:\n", "  tram:\n"), ":6: profiles.tram:", "no such profile"),
    (("[vdx-new-firmware]", "[vdx-newest-firmware]"), ":4: profiles.vdx.options.vdx-newest-firmware:", "not an option"),
    (("      d_sen_m: 3.0\n", "      d_sen_m: 3.0\n      dsen: 3\n"), ":10: profiles.atp.parameters.dsen:", "unknown parameter"),
    (("d_sen_m: 3.0", "d_sen_m: 300"), ":9: profiles.atp.parameters.d_sen_m:", "out of range: 0..30 (ATP-02)"),
    (("d_sen_m: 3.0", "d_sen_m: three"), ":9: profiles.atp.parameters.d_sen_m:", "is not a number"),
    (("timing_resolution_us: 1000", "timing_resolution_us: 0.5"), ":5: profiles.vdx.parameters.timing_resolution_us:",
     "is not an integer"),
    (("      cfsk_period_ms: 50\n", ""), ":7: profiles.atp.parameters:", "missing needed parameter(s) cfsk_period_ms"),
    (("CFSK fault: CFSK故障", "CFSK failure: CFSK故障"), ":14: profiles.atp.texts.CFSK failure:", "no such message"),
    (("CFSK fault: CFSK故障", "CFSK fault: ''"), ":14: profiles.atp.texts.CFSK fault:", "non-empty string"),
    (("    options: [vdx-new-firmware]\n", "    options: [vdx-new-firmware\n"), ":", "not YAML"),
])
def test_every_mistake_names_file_line_and_key(tmp_path: Path, change: tuple[str, str], where: str, why: str) -> None:
    old, new = change
    assert old in GOOD_ATP
    path = _write(tmp_path, GOOD_ATP.replace(old, new))
    with pytest.raises(DeclarationError) as caught:
        load(path)
    message = str(caught.value)
    assert message.startswith(str(path) + where) and why in message, message


def test_a_text_keeps_the_placeholders_of_its_message_identifier(tmp_path: Path) -> None:
    metro = load(_write(tmp_path, GOOD_METRO)).of("metro-tcn")
    assert metro.text("<bus> line <line>: fault") == "<bus> <line>线故障" and metro.text("no cab") == "无激活司机室"
    fault = ":8: profiles.metro-tcn.texts.<bus> line <line>: fault: the text must hold <bus>, <line> once each"
    for old, new, why in [('"<bus> <line>线故障"', '"<bus>线故障"', fault),
                          ('"<bus> <line>线故障"', '"<bus> <line>线故障<line>"', fault),
                          ("无激活司机室", "<cab>无激活司机室", ":7: profiles.metro-tcn.texts.no cab: the text must hold no")]:
        path = _write(tmp_path, GOOD_METRO.replace(old, new))
        with pytest.raises(DeclarationError) as caught:
            load(path)
        assert str(caught.value).startswith(str(path) + why), str(caught.value)


def test_the_metro_declarations_word_every_message_as_the_sut_shows_it() -> None:
    """The reference declares the identifiers' own words; ChineseDisplayMetro what its display shows."""
    messages = set(form()["metro-tcn"]["texts"])
    reference = of_backend(ReferenceMetro).of("metro-tcn")
    assert set(reference.texts) == messages and all(reference.text(m) == m for m in messages)
    chinese = of_backend(ChineseDisplayMetro).of("metro-tcn")
    assert set(chinese.texts) == messages
    for message in messages:
        assert chinese.text(message) == {**METRO_MODES_ZH, **METRO_TEXTS_ZH}[message], message


def test_the_crh2_declarations_word_every_monitor_message_as_the_sut_shows_it() -> None:
    """Every crh2 text is shown in one part of the SUT's answers (the cab monitor's faults or maintenance view,
    or the fault records' event words); the reference declares the identifiers' own words, ChineseMonitorCrh2
    what its monitor shows (its records keep the English words)."""
    texts = form()["crh2"]["texts"]
    assert {spec.get("view") for spec in texts.values()} == {"faults", "maintenance", "records"}
    reference = of_backend(ReferenceTrain).of("crh2")
    assert set(reference.texts) == set(texts) and all(reference.text(m) == m for m in texts)
    chinese = of_backend(ChineseMonitorCrh2).of("crh2")
    assert set(chinese.texts) == set(texts)
    for message in texts:
        assert chinese.text(message) == {**CRH2_FAULTS_ZH, **CRH2_RECORDS_ZH}.get(message, message), message


def test_a_feature_text_is_found_in_the_declared_words() -> None:
    """steps/messages.py: a text filling in an identifier, an identifier itself, a leading part of identifiers
    with a name in it (any of the messages it begins), the bare words of one; in the view the step reads."""
    chinese = of_backend(ChineseMonitorCrh2).of("crh2")
    pattern, said = messages.message(chinese, "car5.LCU.MDM9 failure", "faults")
    assert pattern.fullmatch("car5.LCU.MDM9故障") and not pattern.fullmatch("car5.LCU.MDM8故障")
    assert said == "'car5.LCU.MDM9 failure' (declared as 'car5.LCU.MDM9故障')"
    pattern, _ = messages.message(chinese, "no status data from <node>", "faults")
    assert pattern.fullmatch("car3.LCU无状态数据") and not pattern.fullmatch("car3.LCU故障")
    pattern, _ = messages.message(chinese, "car3.LCU.supply restarted", "maintenance")
    assert pattern.search("1200 ms car3.LCU电源因低温重启") and pattern.search("5 ms car3.LCU电源因断电重启")
    assert not pattern.search("1200 ms car4.LCU电源因低温重启")
    pattern, _ = messages.message(chinese, "car7.LCU.MDM9", "maintenance")
    assert pattern.search("9 ms car7.LCU.MDM9发生故障") and pattern.search("9 ms car7.LCU.MDM9恢复正常")
    assert not pattern.search("9 ms car7.LCU.MDM8发生故障")
    pattern, _ = messages.message(chinese, "insufficient brake", "faults")
    assert pattern.fullmatch("制动力不足")
    for text, view in [("car3.LCU.MDM9 failed", "faults"), ("brake force low", "faults"), ("neutral section", None)]:
        with pytest.raises(ValueError, match="message identifier"):
            messages.message(chinese, text, view)


def test_a_bad_declaration_stops_the_run_before_any_scenario(tmp_path: Path) -> None:
    path = _write(tmp_path, GOOD_ATP.replace("d_sen_m: 3.0", "d_sen_m: -1"))
    run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
                          "--profile", "atp", f"--declaration={path}"], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 4, run.stdout[-2000:] + run.stderr[-2000:]
    assert f"{path}:9: profiles.atp.parameters.d_sen_m: -1 m is out of range" in run.stderr
    assert "passed" not in run.stdout and "failed" not in run.stdout


@pytest.mark.parametrize("cls", [ReferenceTrain, ReferenceMetro, ReferenceAtp])
def test_the_reference_declares_every_profile_it_implements(cls: type) -> None:
    found = of_backend(cls)
    assert found is not None and set(cls.PROFILES) <= set(found.profiles)
    for profile in cls.PROFILES:
        assert found.of(profile).parameter("timing_resolution_us") == 1     # a simulation in whole microseconds


@pytest.mark.parametrize("cls", [c for c in [ReferenceAtp, *IN_BAND, *FREEDOM] if issubclass(c, ReferenceAtp)],
                         ids=lambda c: c.__name__)
def test_an_atp_declares_the_parameters_it_has(cls: type) -> None:
    """The declaration is a claim: the ATP's own figures (its configuration: the atp contract asks no SUT to
    repeat them, so this reads the reference's own) must be what it declares, or the features would compute
    their edges for another train."""
    declared = of_backend(cls).of("atp")
    atp = cls()._cfg.atp
    actual = {"d_sen_m": atp.d_sen_m, "position_uncertainty_m": atp.position_uncertainty_m,
              "decode_delay_ms": atp.decode_delay_us / 1000, "cfsk_period_ms": atp.cfsk_period_us / 1000}
    for name in actual:
        assert declared.parameter(name) == actual[name], f"{cls.__name__} declares {name}={declared.parameter(name)}, " \
                                                          f"has {actual[name]}"


def test_the_form_gives_every_parameter_a_type_unit_and_range() -> None:
    for profile, section in form().items():
        for name, spec in section["parameters"].items():
            assert spec.get("type") and spec.get("unit") and len(spec.get("range", [])) == 2, (profile, name)
            assert spec.get("requirement") and spec.get("note"), (profile, name)


@pytest.mark.cost(8)
def test_a_scenario_needing_an_undeclared_option_is_not_applicable(tmp_path: Path) -> None:
    path = _write(tmp_path, GOOD_ATP.replace("    texts:\n      CFSK fault: CFSK故障\n", ""))
    results = tmp_path / "allure-results"
    run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
                          "--item", "F-ATP-06", f"--declaration={path}", f"--alluredir={results}", "-rs"],
                         cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-3000:]
    assert "not applicable: 5 of the skipped scenarios" in run.stdout
    assert "does not claim the option vdx-old-firmware" in run.stdout
    summary = summarize(load_results(results))
    assert summary.counts["not applicable"] == 5 and summary.counts["passed"] >= 3, summary.counts
    assert summary.counts["failed"] == 0 and summary.counts["skipped"] == 0, summary.counts
    categories = json.loads((results / "categories.json").read_text(encoding="utf-8"))
    assert any(c["name"].startswith("Not applicable") for c in categories)


# The same for what the other profiles declare: a declaration is a claim about the product, and a wrong claim
# would make the features compute their bounds for another train.
_LOOPS = {"ACS": "acs_poll_period_ms", "PID": "pid_poll_period_ms", "APU": "apu_poll_period_ms",
          "SDD": "sdd_send_period_ms", "DD": "dd_report_period_ms"}
_LOOP_DEFAULTS_US = {"SDD": 1_000_000, "DD": 100_000}      # sut/reference/crh2/train.py, when TIMING names none


@pytest.mark.parametrize("cls", [c for c in [ReferenceTrain, *IN_BAND, *FREEDOM] if issubclass(c, ReferenceTrain)],
                         ids=lambda c: c.__name__)
def test_a_crh2_declares_the_loop_periods_it_has(cls: type) -> None:
    from sut.reference.crh2.config import TrainConfig

    declared = of_backend(cls).of("crh2")
    periods = {**_LOOP_DEFAULTS_US, **dict(TrainConfig().with_timing(**cls.TIMING).timing.current_loop_periods_us)}
    tolerance = declared.parameter("loop_period_tolerance_pct") / 100
    for device, name in _LOOPS.items():
        period = declared.parameter(name)
        assert abs(periods[device] / 1000 - period) <= period * tolerance, \
            f"{cls.__name__} declares {name}={period} ms (+-{tolerance:.0%}), polls every {periods[device] / 1000} ms"


@pytest.mark.parametrize("cls", [c for c in [ReferenceMetro, *IN_BAND, *FREEDOM] if issubclass(c, ReferenceMetro)],
                         ids=lambda c: c.__name__)
def test_a_metro_declares_the_io_map_it_has(cls: type) -> None:
    from steps.metro import IO_MAP           # what a declaration that names no I/O map stands for
    from sut.reference.metro.config import MetroConfig

    declared = {**IO_MAP, **of_backend(cls).of("metro-tcn").parameters}
    wired = MetroConfig().with_behaviour(**cls.BEHAVIOUR).behaviour
    for name, actual in (("traction_demand_ai", wired.ai_traction), ("brake_demand_ai", wired.ai_brake),
                         ("forward_di", wired.di_forward), ("demand_full_scale", wired.ai_full_scale)):
        assert declared[name] == actual, f"{cls.__name__} declares {name}={declared[name]}, is wired {actual}"


@pytest.mark.parametrize("cls", [c for c in [ReferenceMetro, *IN_BAND, *FREEDOM] if issubclass(c, ReferenceMetro)],
                         ids=lambda c: c.__name__)
def test_a_metro_declares_the_silent_polls_it_counts(cls: type) -> None:
    from steps.metro import SILENT_POLLS     # what a declaration that names no count stands for
    from sut.reference.metro.config import MetroConfig

    declared = of_backend(cls).of("metro-tcn").parameters
    counts = MetroConfig().with_timing(**cls.TIMING).timing.status_silence_polls
    for name in ("wtb_silent_polls", "status_silent_polls"):
        assert declared.get(name, SILENT_POLLS) == counts, f"{cls.__name__} declares {name}={declared.get(name)}, " \
                                                           f"counts {counts}"


@pytest.mark.parametrize("cls", [c for c in [ReferenceAtp, *IN_BAND, *FREEDOM]
                                 if issubclass(c, ReferenceAtp) and "vdx" in c.PROFILES], ids=lambda c: c.__name__)
def test_a_vdx_measures_its_supply_within_its_declared_accuracy(cls: type) -> None:
    """VDX-02's range is 70..125 % of 110 V; a VDX that takes other edges measures its supply off by that much."""
    from sut.reference.atp.config import Vdx

    declared = of_backend(cls).of("vdx").parameters.get("supply_accuracy_pct", 0)   # none declared: exact
    edges = {"supply_lo": 0.70, "supply_hi": 1.25}
    for name, edge in edges.items():
        taken = getattr(Vdx(**cls.VDX), name)
        assert abs(edge / taken - 1) * 100 <= declared + 1e-9, \
            f"{cls.__name__} takes {name}={taken:.5f} for {edge}: off by more than its declared {declared} %"


@pytest.mark.parametrize("cls", [c for c in [ReferenceTrain, *IN_BAND, *FREEDOM] if issubclass(c, ReferenceTrain)],
                         ids=lambda c: c.__name__)
def test_a_crh2_reads_pressure_and_speed_within_its_declared_accuracy(cls: type) -> None:
    """The interlocks act on the pressure and speed the train measures; a CRH2 whose measurement is off by more
    than it declares would be fed its edges too near (steps/vehicle.py EDGES)."""
    from sut.reference.crh2.config import Behaviour

    declared = of_backend(cls).of("crh2")
    reads = Behaviour(**cls.BEHAVIOUR)
    for name, off in (("pressure_accuracy_kpa", reads.pressure_read_kpa), ("speed_accuracy_kmh", reads.speed_read_kmh)):
        assert abs(off) <= declared.parameter(name), \
            f"{cls.__name__} reads {off:+g} off, declares {name}={declared.parameter(name)}"
