"""validation/runs.py's kept results: a run that has not got as far as its kept copy (begun
again, or resumed from an earlier checkpoint) neither replaces nor hides that copy. A run of
another source (`sluice --stats` names it) is another result: a kept copy never hides it."""
import json
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "validation"))
import runs  # noqa: E402


def write_probes(directory, end, step=0.1):
    os.makedirs(directory, exist_ok=True)
    rows = ["time [s],P1 [Pa]"] + [f"{k * step:g},{k}" for k in range(round(end / step) + 1)]
    with open(os.path.join(directory, "probes.csv"), "w") as f:
        f.write("\n".join(rows) + "\n")


def kept_end(results, name):
    return runs.last_time(os.path.join(results, name, "probes.csv.gz"))


@pytest.fixture
def results(tmp_path, monkeypatch):
    monkeypatch.setattr(runs, "RESULTS", str(tmp_path / "results"))
    return str(tmp_path / "results")


def test_last_time_reads_the_last_row_of_a_time_series(tmp_path):
    write_probes(str(tmp_path), 2.0)
    assert runs.last_time(str(tmp_path / "probes.csv")) == pytest.approx(2.0)
    with open(tmp_path / "table.csv", "w") as f:
        f.write("model,drag\nwcsph,1\n")
    assert runs.last_time(str(tmp_path / "table.csv")) is None


def keep_two_runs(run, first_end, second_end):
    """Keeps a run reaching first_end, then the same run begun again reaching second_end."""
    for end in (first_end, second_end):
        write_probes(run, end)
        runs.keep_results(run, "f3/mac")


def test_a_longer_run_replaces_its_kept_copy(tmp_path, results):
    run = str(tmp_path / "run")
    keep_two_runs(run, 1.0, 2.0)
    assert kept_end(results, "f3/mac") == pytest.approx(2.0)
    assert runs.result_path(run, "f3/mac", "probes.csv") == os.path.join(run, "probes.csv")


def test_a_shorter_run_neither_replaces_nor_hides_the_kept_copy(tmp_path, results):
    run = str(tmp_path / "run")
    keep_two_runs(run, 2.0, 0.5)
    assert kept_end(results, "f3/mac") == pytest.approx(2.0)
    path = runs.result_path(run, "f3/mac", "probes.csv")
    assert path == os.path.join(results, "f3", "mac", "probes.csv.gz")
    assert runs.last_time(path) == pytest.approx(2.0)


def test_the_statistics_follow_the_files_they_belong_to(tmp_path, results):
    run = str(tmp_path / "run")
    write_probes(run, 2.0)
    leg = {"steps": 2000, "wall_seconds": 100.0, "simulated_seconds": 2.0, "threads": 2}
    with open(os.path.join(run, "stats_leg_0.json"), "w") as f:
        f.write(str(leg).replace("'", '"'))
    runs.keep_results(run, "f3/mac")
    write_probes(run, 0.5)
    with open(os.path.join(run, "stats_leg_0.json"), "w") as f:
        f.write(str(dict(leg, steps=500, simulated_seconds=0.5)).replace("'", '"'))
    assert runs.result_statistics(run, "f3/mac")["steps"] == 2000


def write_statistics(run, source, end):
    leg = {"steps": 10, "wall_seconds": 1.0, "simulated_seconds": end, "threads": 1}
    if source is not None:
        leg["source_revision"] = source
    with open(os.path.join(run, "stats.json"), "w") as f:
        json.dump(leg, f)


def test_a_run_of_another_source_is_not_hidden_by_the_kept_copy(tmp_path, results):
    run = str(tmp_path / "run")
    write_probes(run, 2.0)
    write_statistics(run, "aaaaaaaaaaaa", 2.0)
    runs.keep_results(run, "f3/mac")
    write_probes(run, 0.5)
    write_statistics(run, "bbbbbbbbbbbb", 0.5)
    assert runs.result_path(run, "f3/mac", "probes.csv") == os.path.join(run, "probes.csv")
    runs.keep_results(run, "f3/mac")
    assert kept_end(results, "f3/mac") == pytest.approx(0.5)
    # Of the same source, or where either does not say, the kept copy that reaches further wins.
    for source in ("bbbbbbbbbbbb", None):
        write_probes(run, 2.0)
        write_statistics(run, "bbbbbbbbbbbb", 2.0)
        runs.keep_results(run, "f3/mac")
        write_probes(run, 0.5)
        write_statistics(run, source, 0.5)
        assert runs.last_time(runs.result_path(run, "f3/mac", "probes.csv")) == pytest.approx(2.0)


def test_a_table_keeps_every_default_run_when_some_are_run():
    default = "mac@0.04,mac@0.02,wcsph@0.02"
    assert runs.runs_to_tabulate("mac@0.04", default) == default.split(",")
    assert runs.runs_to_tabulate("mps@0.02,mac@0.02", default) == default.split(",") + ["mps@0.02"]


def test_a_tables_build_cell_names_the_runs_source_or_says_it_was_not_recorded():
    assert runs.build_cell({"source_revision": "15b43079ea47"}) == "`15b4307`"
    assert runs.build_cell({"source_revision": "b69d7bcac34f-dirty"}) == "`b69d7bc-dirty`"
    assert runs.build_cell({"steps": 10}) == "not recorded"
    assert runs.build_cell(None) == "not recorded"
