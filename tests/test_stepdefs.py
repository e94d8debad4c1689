from outline.plugin.stepdefs import definitions_in_modules, matching, step_problem


def test_finds_pytest_bdd_registered_definitions(data_on_path):
    data_on_path("good")
    defs = definitions_in_modules(["good_steps"])
    ours = [d for d in defs if d.module == "good_steps"]
    assert len(ours) == 7
    assert {d.type for d in ours} == {"given", "when", "then"}
    # pytest-bdd's own "trace" steps are always visible to pytest, so they count here too.
    assert any(d.module == "pytest_bdd.plugin" and d.pattern == "trace" for d in defs)


def test_step_type_is_respected(data_on_path):
    data_on_path("bad")
    defs = definitions_in_modules(["bad_steps"])
    assert step_problem("when", "the driver does something", defs) is None
    assert step_problem("given", "the driver does something", defs) == (
        'unknown step "Given the driver does something"'
    )


def test_ambiguity_names_modules_and_lines(data_on_path):
    data_on_path("bad")
    defs = definitions_in_modules(["bad_steps"])
    message = step_problem("then", "the notch is 3", defs)
    assert message.startswith('ambiguous step "Then the notch is 3" matches 2 definitions: ')
    assert "bad_steps:16 ('the notch is {notch:d}')" in message
    assert "bad_steps:21 ('the notch is 3')" in message
    assert len(matching("then", "the notch is 4", defs)) == 1


def test_reexported_definitions_are_not_ambiguous(data_on_path, tmp_path, monkeypatch):
    data_on_path("bad")
    (tmp_path / "reexport_steps.py").write_text("from bad_steps import *  # noqa: F403\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    defs = definitions_in_modules(["bad_steps", "reexport_steps"])
    assert step_problem("given", "a train of 8 cars", defs) is None
