"""sluice.sweep and sluice.compare: their tables as rows, as the command line writes them;
runs that diverge; bad input before anything runs. And Simulation(device=...)."""
import csv
import os
import signal
import threading
import time

import numpy as np
import pytest
import sluice
from conftest import ROOT, case_path

ESCAPE = os.path.join(ROOT, "tests", "cli", "diverging", "escape.yaml")


def read_csv(path):
    with open(path, newline="") as table:
        return list(csv.DictReader(table))


def test_sweep_gives_a_row_per_combination_as_its_summary(tmp_path, capfd):
    out = tmp_path / "sweep"
    rows = sluice.sweep(case_path("dam_break_2d"),
                        set={"spacing": [0.05, 0.04], "end_time": 0.05,
                             "fluid.blocks.0.max": [[0.5, 1.0], [0.6, 1.0]]},
                        out=out, jobs=2, progress=False)
    assert [(r["run"], r["spacing"], r["fluid.blocks.0.max"]) for r in rows] == [
        (1, 0.05, "[0.5, 1]"), (2, 0.05, "[0.6, 1]"), (3, 0.04, "[0.5, 1]"),
        (4, 0.04, "[0.6, 1]")]
    assert all(r["status"] == "done" for r in rows)
    assert all(os.path.isdir(r["out"]) for r in rows)
    assert capfd.readouterr().out == ""  # progress=False: not a line, the plots' neither
    # The rows hold what summary.csv holds, to its 6 digits.
    for row, written in zip(rows, read_csv(out / "summary.csv")):
        for name in ("front [m]", "steps"):
            assert row[name] == pytest.approx(float(written[name]), rel=1e-5)
    # The finer spacing takes more steps; the longer column of water runs further.
    assert rows[2]["steps"] > rows[0]["steps"]
    assert rows[1]["front [m]"] > rows[0]["front [m]"]


def test_a_run_that_diverges_is_a_row_with_its_status(tmp_path):
    rows = sluice.sweep(ESCAPE, set={"fluid.blocks.0.velocity": [[0, 0], [0, 50]]},
                        out=tmp_path / "escape", end=0.1, jobs=1, progress=False)
    assert [r["status"] for r in rows] == ["done", "diverged"]
    assert "steps" in rows[0] and "steps" not in rows[1]


def test_a_bad_sweep_value_is_refused_before_anything_runs(tmp_path):
    out = tmp_path / "bad"
    with pytest.raises(sluice.InputError) as error:
        sluice.sweep(case_path("dam_break_2d"), set={"spacing": [0.05, -1]}, out=out)
    assert error.value.key == "spacing" and "greater than zero" in str(error.value)
    assert not out.exists()
    with pytest.raises(sluice.InputError) as error:
        sluice.sweep(case_path("dam_break_2d"), set={"spacing": []}, out=out)
    assert error.value.key == "spacing" and "an empty list of values" in str(error.value)
    with pytest.raises(ValueError):
        sluice.sweep(case_path("dam_break_2d"), set={"spacing": 0.1}, out=out, jobs=-1)
    with pytest.raises(ValueError):
        sluice.sweep(case_path("dam_break_2d"), set={"spacing": 0.1}, out=out, end=0)
    with pytest.raises(sluice.InputError):
        sluice.sweep(os.path.join(ROOT, "cases", "no_such_case.yaml"), set={"spacing": 0.1})


def test_compare_gives_a_row_per_model_as_its_table(tmp_path, capfd):
    out = tmp_path / "compare"
    rows = sluice.compare(case_path("dam_break_2d"), models=["wcsph", "mps"],
                          set={"spacing": 0.05}, out=str(out), end=0.05)
    printed = capfd.readouterr().out
    assert "[1/2] wcsph: done" in printed and "[2/2] mps: done" in printed
    assert [(r["model"], r["status"]) for r in rows] == [("wcsph", "done"), ("mps", "done")]
    assert rows[0]["settings"] == "the case's" and rows[1]["settings"] == "model={name: mps}"
    assert rows[0]["fluid"] == rows[1]["fluid"] == "800 particles"
    for row, written in zip(rows, read_csv(out / "compare.csv")):
        assert row["model"] == written["model"]
        assert row["front end [m]"] == pytest.approx(float(written["front end [m]"]), rel=1e-5)
        assert os.path.exists(os.path.join(row["out"], "probes.csv"))
    # mps's implicit pressure takes larger steps than wcsph's sound speed allows.
    assert rows[1]["steps"] < rows[0]["steps"]


def test_an_unknown_model_is_refused_before_anything_runs(tmp_path):
    out = tmp_path / "compare"
    with pytest.raises(sluice.InputError) as error:
        sluice.compare(case_path("dam_break_2d"), models=["wcsph", "sph"], out=out)
    assert str(error.value).startswith("models: unknown fluid model 'sph'")
    assert not out.exists()


def test_device_choice(small_dam_break, tmp_path):
    with pytest.raises(sluice.InputError) as error:
        sluice.Simulation(small_dam_break, device="tpu")
    assert "expected cpu, gpu or emulated" in str(error.value)
    mac = sluice.Case.from_yaml(case_path("dam_break_2d"), set={"model": {"name": "mac"}})
    with pytest.raises(sluice.InputError) as error:
        sluice.Simulation(mac, device="gpu")
    assert "runs the wcsph model only, not 'mac'" in str(error.value)
    # The device's code emulated on the CPU steps as the CPU's does.
    positions = {}
    for device in ("cpu", "emulated"):
        sim = sluice.Simulation(small_dam_break, out=str(tmp_path / device), threads=1,
                                end=0.02, device=device)
        sim.run()
        positions[device] = np.sort(sim.fields(copy=True)["position"], axis=0)
        assert sim.steps > 0
    # (identical here; 1e-6 m, 2e-5 of the spacing, leaves room for another processor's SIMD)
    np.testing.assert_allclose(positions["emulated"], positions["cpu"], atol=1e-6)


def test_a_quoted_value_keeps_its_commas(tmp_path):
    rows = sluice.sweep(case_path("dam_break_2d"),
                        set={"name": ["a, b", "c"], "spacing": 0.1, "end_time": 0.01},
                        out=tmp_path / "names", progress=False)
    assert [(r["name"], r["status"]) for r in rows] == [('"a, b"', "done"), ("c", "done")]


def sluice_processes_writing_into(folder):
    """The processes whose command line names `folder`."""
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as cmdline:
                if str(folder).encode() in cmdline.read():
                    found.append(int(pid))
        except OSError:
            pass  # ended meanwhile
    return found


def test_ctrl_c_stops_a_sweep_and_its_runs(tmp_path):
    out = tmp_path / "stopped"

    def press_ctrl_c_once_they_run():
        """SIGINT to this process half a second after the runs (minutes each) have written
        their first frames."""
        while not (os.path.exists(out / "run_001" / "frames") and
                   os.path.exists(out / "run_002" / "frames")):
            time.sleep(0.05)
        time.sleep(0.5)
        os.kill(os.getpid(), signal.SIGINT)

    interrupt = threading.Thread(target=press_ctrl_c_once_they_run, daemon=True)
    interrupt.start()
    with pytest.raises(KeyboardInterrupt):
        sluice.sweep(case_path("dam_break_2d"), set={"spacing": [0.01, 0.012]}, out=out, jobs=2,
                     progress=False)
    interrupt.join()
    assert sluice_processes_writing_into(out) == []  # none of the runs is left
