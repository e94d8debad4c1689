from pathlib import Path

from outline.report.allure_env import read_environment, write_environment


def test_none_dir_does_nothing():
    assert write_environment(None, {"sut": "reference"}) is None


def test_merge_escape_and_accumulate(tmp_path: Path):
    out = tmp_path / "results"
    path = write_environment(out, {"sut": "reference", "profile": "crh2-8", "cars": 8, "skip": None})
    write_environment(out, {"profile": "crh2-16", "key with=sep": "a:b\\c ü"})
    write_environment(out, {"profile": "crh2-8"})
    assert path == out / "environment.properties"
    assert read_environment(out) == {
        "sut": "reference",
        "profile": "crh2-8 | crh2-16",
        "cars": "8",
        "key with=sep": "a:b\\c ü",
    }
    text = path.read_text(encoding="ascii")
    assert "key\\ with\\=sep=a\\:b\\\\c \\u00fc\n" in text
    assert text.splitlines()[0].startswith("cars=")  # sorted: identical runs give identical files


def test_a_value_holding_commas_or_the_separator_is_merged_once(tmp_path: Path):
    for _ in range(3):
        write_environment(tmp_path, {"MVB": "1.5 Mbit/s, basic period 1 ms", "odd": "a | b"})
    write_environment(tmp_path, {"MVB": "2 Mbit/s"})
    assert read_environment(tmp_path) == {"MVB": "1.5 Mbit/s, basic period 1 ms | 2 Mbit/s", "odd": "a / b"}


def test_a_run_of_three_profiles_keeps_each_profiles_environment_apart(tmp_path: Path):
    """Issue 17: a reviewer signing off one train must not read another's composition or backend."""
    import subprocess
    import sys

    from tests.test_faulty_variants import ROOT

    results = tmp_path / "results"
    run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
                          "--item=R-CTL-01,F-NET-21,F-ATP-04", f"--alluredir={results}"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-2000:]
    env = read_environment(results)
    # F-ATP-04 is a vdx item: the ATP rig files it under its own profile (it said "atp" for all three until seed 25)
    modules = {"crh2": "sut.reference.crh2.", "metro-tcn": "sut.reference.metro.", "vdx": "sut.reference.atp."}
    assert sorted(env["[run] profiles"].split(" | ")) == sorted(modules)
    for profile, module in modules.items():
        assert env[f"[{profile}] SUT class"].startswith(module), env[f"[{profile}] SUT class"]
    for key, value in env.items():
        prefix = key[1:key.index("]")] if key.startswith("[") else None
        assert prefix in (*modules, "run"), f"a key outside every profile: {key}"
        others = [module for profile, module in modules.items() if profile != prefix]
        assert not any(module in value for module in others), f"{key} carries another profile's value: {value}"
        parts = value.split(" | ")
        assert len(parts) == len(set(parts)), f"{key} repeats a value: {value}"
    assert {"[run] command", "[run] commit", "[run] date", "[run] host"} <= env.keys()
    assert env["[crh2] cars per set"] == "8" and env["[metro-tcn] cars"].startswith("6 "), env


def test_evidence_for_failed_scenarios_only_keeps_the_environment(tmp_path: Path):
    """--evidence failed (a campaign's thousands of passing rows): no attachment on a passing scenario, a
    failing one keeps its evidence, and the run's environment is written all the same."""
    import json
    import subprocess
    import sys

    from tests.test_faulty_variants import ROOT

    def run(results: Path, *args: str) -> dict[str, list]:
        subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p",
                        "no:xdist", "--item=F-NET-30", "-k", "car3", f"--alluredir={results}", *args],
                       cwd=ROOT, capture_output=True, text=True, timeout=600)
        by_status: dict[str, list] = {}           # status -> attachments per result
        for path in results.glob("*-result.json"):
            result = json.loads(path.read_text())
            by_status.setdefault(result["status"], []).append(len(result.get("attachments", [])))
        return by_status

    passing = run(tmp_path / "passing", "--evidence", "failed")
    assert set(passing) == {"passed"} and not any(passing["passed"]), passing
    assert read_environment(tmp_path / "passing")["[crh2] cars per set"] == "8"
    failing = run(tmp_path / "failing", "--evidence", "failed", "--sut", "tests.variants:NoSelfDiagnosticFallback")
    assert failing.get("failed") and all(failing["failed"]), failing
    assert all(run(tmp_path / "all")["passed"])


def test_a_backend_opened_without_a_profile_describes_its_first_declared_profile():
    """TrainDriver.open: None is the first profile a backend declares, and the environment the report files a
    run under says so (seed 26 filed an ATP rig opened without a profile under vdx)."""
    from sut.backends import open_backend
    from sut.reference.atp.backend import ReferenceAtp

    assert ReferenceAtp.open().describe()["profile"] == ReferenceAtp.PROFILES[0] == "atp"
    for profile in ReferenceAtp.PROFILES:
        assert open_backend("reference", profile).describe()["profile"] == profile
