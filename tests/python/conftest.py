"""Shared fixtures of the Python module's tests: the repository's root and a small dam break."""
import os

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
# The command line of the same build (ctest names it; by hand, the release build's).
SLUICE = os.environ.get("SLUICE_EXECUTABLE", os.path.join(ROOT, "build", "release", "sluice"))


def case_path(name):
    return os.path.join(ROOT, "cases", f"{name}.yaml")


@pytest.fixture
def small_dam_break():
    """cases/dam_break_2d.yaml at 0.05 m to 0.1 s: 800 particles, a few hundred steps."""
    import sluice
    return sluice.Case.from_yaml(case_path("dam_break_2d"),
                                 set={"spacing": 0.05, "end_time": 0.1})
