"""sluice.Case: read and checked as `sluice check` does; bad input raised with file, line, key."""
import os

import pytest
import sluice
from conftest import ROOT, case_path


def test_reads_a_case_file():
    case = sluice.Case.from_yaml(case_path("dam_break_2d"))
    assert (case.name, case.dimension, case.model) == ("dam_break_2d", 2, "wcsph")
    assert case.spacing == 0.025 and case.end_time == 1.0
    assert case.file.endswith("dam_break_2d.yaml")


def test_set_overrides_keys_as_the_command_line_does():
    case = sluice.Case.from_yaml(case_path("dam_break_2d"),
                                 set={"model": {"name": "mps"}, "spacing": 0.05,
                                      "fluid.blocks": [{"min": [0, 0], "max": [1, 1]}]})
    assert (case.model, case.spacing) == ("mps", 0.05)


def test_builds_a_case_from_a_dict():
    case = sluice.Case({
        "name": "tank", "dimension": 2, "spacing": 0.05,
        "domain": {"min": [0, 0], "max": [1, 1]}, "end_time": 0.1, "output_interval": 0.05,
        "fluid": {"blocks": [{"min": [0, 0], "max": [1, 0.5]}]},
        "walls": [{"type": "tank", "min": [0, 0], "max": [1, 1], "open": ["z+"]}],
        "model": {"name": "wcsph"}})
    assert (case.name, case.dimension, case.file) == ("tank", 2, "<dict>")
    assert "tank" in repr(case)


def test_a_bad_file_names_its_file_line_and_key():
    path = os.path.join(ROOT, "tests", "cli", "bad_input", "boundary_inlet_negative_ramp.yaml")
    with pytest.raises(sluice.InputError) as raised:
        sluice.Case.from_yaml(path)
    error = raised.value
    assert (error.line, error.key) == (14, "boundaries[0].ramp_time")
    assert error.file == path
    assert "must not be negative" in str(error) and isinstance(error, ValueError)


def test_a_bad_override_names_its_key():
    with pytest.raises(sluice.InputError) as raised:
        sluice.Case.from_yaml(case_path("dam_break_2d"), set={"spacing": -1})
    assert raised.value.key == "spacing"


def test_a_bad_dict_names_its_key():
    with pytest.raises(sluice.InputError) as raised:
        sluice.Case({"dimension": 4})
    assert raised.value.file == "<dict>" and raised.value.key == "dimension"


def test_a_missing_file_is_bad_input():
    with pytest.raises(sluice.InputError) as raised:
        sluice.Case.from_yaml(os.path.join(ROOT, "cases", "no_such_case.yaml"))
    assert "cannot open" in str(raised.value)


def test_a_value_no_case_can_hold_is_a_type_error():
    with pytest.raises(TypeError):
        sluice.Case({"name": object()})
