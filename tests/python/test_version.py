"""Which sluice this is: `sluice --version`, the module's __version__ and source_revision, and a
run's statistics all name the same release and source."""
import json
import os
import re
import subprocess

import sluice
from conftest import ROOT, SLUICE, case_path


def test_the_command_line_and_the_module_name_the_same_build():
    printed = subprocess.run([SLUICE, "--version"], capture_output=True, text=True, check=True)
    assert printed.stdout.strip() == f"sluice {sluice.__version__} (source {sluice.source_revision})"


def test_the_version_is_the_projects():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        declared = re.search(r"project\(sluice VERSION ([0-9.]+)", f.read()).group(1)
    assert sluice.__version__ == declared
    assert re.fullmatch(r"[A-Za-z0-9._+-]+", sluice.source_revision)


def test_a_runs_statistics_name_its_build(tmp_path):
    stats = tmp_path / "stats.json"
    subprocess.run([SLUICE, "run", case_path("dam_break_2d"), "--set", "spacing=0.1",
                    "--end", "0.01", "--out", str(tmp_path / "out"), "--stats", str(stats)],
                   capture_output=True, check=True)
    written = json.loads(stats.read_text())
    assert (written["sluice_version"], written["source_revision"]) == \
        (sluice.__version__, sluice.source_revision)
