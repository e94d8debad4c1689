from pathlib import Path

from outline.allure_env import read_environment, write_environment


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
        "profile": "crh2-8, crh2-16",
        "cars": "8",
        "key with=sep": "a:b\\c ü",
    }
    text = path.read_text(encoding="ascii")
    assert "key\\ with\\=sep=a\\:b\\\\c \\u00fc\n" in text
    assert text.splitlines()[0].startswith("cars=")  # sorted: identical runs give identical files
