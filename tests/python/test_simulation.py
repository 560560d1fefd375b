"""sluice.Simulation: stepping, callbacks, fields, probes, bodies, checkpoints, errors."""
import csv
import os
import subprocess
import threading

import numpy as np
import pytest
import sluice
from conftest import ROOT, SLUICE, case_path


def test_steps_and_runs_to_a_time(small_dam_break, tmp_path):
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path), threads=1)
    assert (sim.time, sim.steps, sim.threads, sim.dimension) == (0.0, 0, 1, 2)
    sim.step()
    assert sim.steps == 1 and 0 < sim.time < 0.02
    sim.run(until=0.05)
    assert sim.time == pytest.approx(0.05, abs=1e-12)
    sim.run()
    assert sim.time == pytest.approx(sim.end_time, abs=1e-12)
    assert os.path.exists(os.path.join(str(tmp_path), "dam_break_2d.pvd"))
    with pytest.raises(ValueError):
        sim.step()


def test_calls_back_every_interval(small_dam_break, tmp_path):
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path), threads=1)
    times = []
    sim.run(every=0.03, callback=lambda s: times.append(s.time))
    np.testing.assert_allclose(times, [0.03, 0.06, 0.09], atol=1e-12)


def test_a_callback_that_raises_stops_the_run_at_a_whole_step(small_dam_break, tmp_path):
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path), threads=1)

    def stop(s):
        raise KeyError("stop here")

    with pytest.raises(KeyError):
        sim.run(every=0.02, callback=stop)
    assert sim.time == pytest.approx(0.02, abs=1e-12)
    sim.run(until=0.04)  # and it goes on
    assert sim.time == pytest.approx(0.04, abs=1e-12)


def test_until_past_the_end_is_refused(small_dam_break, tmp_path):
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path), threads=1)
    with pytest.raises(ValueError):
        sim.run(until=5.0)
    with pytest.raises(ValueError):
        sim.run(every=0)


def test_fields_view_the_particles_read_only(small_dam_break, tmp_path):
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path), threads=1)
    sim.run(until=0.02)
    fields = sim.fields()
    position, pressure = fields["position"], fields["pressure"]
    assert position.shape[0] == pressure.shape[0] > 800
    assert not position.flags.writeable and not position.flags.owndata
    with pytest.raises(ValueError):
        pressure[0] = 1.0
    kind = fields["kind"]
    water = kind == 0
    assert water.sum() == 800
    # The water stays in the tank, under the column's top.
    assert position[water].min() >= -1e-9 and position[water, -1].max() < 2.0
    copied = sim.fields(copy=True)
    assert copied["pressure"].flags.writeable
    np.testing.assert_array_equal(copied["pressure"], pressure)
    assert sim.grid_fields() is None


def test_probes_read_as_the_csv_labels_them(small_dam_break, tmp_path):
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path), threads=1)
    sim.run(until=0.05)
    probes = sim.probes()
    assert list(probes) == ["front [m]", "gauge_left [m]", "right_wall [Pa]"]
    assert 1.0 < probes["front [m]"] < 1.5


def test_the_same_answer_as_the_command_line(small_dam_break, tmp_path):
    """The Python loop takes the command line's steps: the same probes.csv, to the digit."""
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path / "python"), threads=1)
    sim.run(every=0.01, callback=lambda s: s.probes())
    subprocess.run([SLUICE, "run", case_path("dam_break_2d"), "--set", "spacing=0.05",
                    "--set", "end_time=0.1", "--threads", "1", "--out", str(tmp_path / "cli")],
                   check=True, capture_output=True)
    with open(tmp_path / "python" / "probes.csv") as a, open(tmp_path / "cli" / "probes.csv") as b:
        rows = list(csv.reader(a))
        assert rows == list(csv.reader(b))
    # probe_record() holds what probes.csv holds, to the file's digits.
    record = sim.probe_record()
    assert list(record) == rows[0]
    for k, label in enumerate(rows[0]):
        np.testing.assert_allclose(record[label], [float(r[k]) for r in rows[1:]], rtol=1e-8,
                                   atol=1e-9)


def test_bodies_and_their_loads(tmp_path):
    case = sluice.Case.from_yaml(case_path("floating_box_2d"), set={"end_time": 0.02})
    sim = sluice.Simulation(case, out=str(tmp_path), threads=1)
    sim.run()
    bodies = sim.bodies()
    assert len(bodies) == 1
    box = next(iter(bodies.values()))
    assert box["position"].shape == (3,) and box["orientation"].shape == (4,)
    assert box["mass"] > 0
    # Floating: the water holds up about its weight (within the start's transient).
    assert box["fluid_force"][2] > 0
    np.testing.assert_array_equal(box["contact_force"], [0, 0, 0])  # it touches nothing


def test_contact_loads_carry_the_weight(tmp_path):
    """cases/resting_cubes.yaml: a cube on the floor, and a stack of three; the floor carries
    each bottom cube's load, the weight of what stands on it."""
    case = sluice.Case.from_yaml(case_path("resting_cubes"), set={"end_time": 0.3})
    sim = sluice.Simulation(case, out=str(tmp_path), threads=1)
    sim.run()
    bodies = sim.bodies()
    weight = bodies["single"]["mass"] * 9.81
    # The stack settles by 0.3 s: each body's contact load is its weight to 0.3 % (the springs'
    # last oscillation), against a bar of 2 %.
    assert bodies["single"]["contact_force"][2] == pytest.approx(weight, rel=0.02)
    assert bodies["stack_top"]["contact_force"][2] == pytest.approx(weight, rel=0.02)
    # The bottom cube: the floor's push up, less the two cubes' weight on it.
    assert bodies["stack_bottom"]["contact_force"][2] == pytest.approx(weight, rel=0.02)
    assert abs(bodies["single"]["contact_force"][0]) < 0.01 * weight


def test_a_checkpoint_resumes_to_the_same_state(small_dam_break, tmp_path):
    first = sluice.Simulation(small_dam_break, out=str(tmp_path / "a"), threads=1)
    first.run(until=0.04)
    first.save()
    first.run()
    resumed = sluice.Simulation.resume(small_dam_break, str(tmp_path / "a"), threads=1)
    assert resumed.time == pytest.approx(0.04, abs=1e-12)
    resumed.run()
    np.testing.assert_array_equal(resumed.fields(copy=True)["position"],
                                  first.fields(copy=True)["position"])


def test_resuming_without_a_checkpoint_is_bad_input(small_dam_break, tmp_path):
    with pytest.raises(sluice.InputError):
        sluice.Simulation.resume(small_dam_break, str(tmp_path / "empty"))


def test_a_run_that_goes_wrong_raises(tmp_path):
    case = sluice.Case.from_yaml(os.path.join(ROOT, "tests", "cli", "diverging", "escape.yaml"))
    sim = sluice.Simulation(case, out=str(tmp_path), threads=1)
    with pytest.raises(sluice.DivergenceError, match="left the domain"):
        sim.run()
    for go_on in (sim.step, sim.run, sim.save):
        with pytest.raises(RuntimeError, match="the run diverged"):
            go_on()


def test_a_grid_model_shows_its_cells(tmp_path):
    case = sluice.Case.from_yaml(case_path("dam_break_2d"),
                                 set={"model": {"name": "mac", "cell_size": 0.1},
                                      "end_time": 0.02})
    sim = sluice.Simulation(case, out=str(tmp_path), threads=1)
    sim.run()
    grid = sim.grid_fields()
    assert grid["spacing"] == pytest.approx(0.1)
    names = [k for k in grid if k not in ("origin", "spacing")]
    assert names and all(grid[k].shape[:3] == (30, 1, 40) for k in names)


def tank_with_a_paddle(motion="prescribed"):
    """Water 0.3 m deep in a 2 m tank with a box held in it, prescribed (at rest) or free."""
    body = {"name": "paddle", "shape": "box", "size": [0.1, 0.4], "density": 500,
            "position": [0.4, 0.35], "motion": motion}
    if motion == "prescribed":
        body["prescribed"] = {"type": "constant_velocity"}
    return sluice.Case({
        "name": "paddle_tank", "dimension": 2, "spacing": 0.05, "end_time": 0.1,
        "output_interval": 0.05, "domain": {"min": [0, 0], "max": [2, 0.8]},
        "fluid": {"blocks": [{"min": [0.5, 0], "max": [2, 0.3]}]},
        "walls": [{"type": "tank", "min": [0, 0], "max": [2, 0.8], "open": ["z+"]}],
        "bodies": [body], "model": {"name": "wcsph"}})


def test_a_controller_drives_a_prescribed_body(tmp_path):
    sim = sluice.Simulation(tank_with_a_paddle(), out=str(tmp_path), threads=1)
    start = sim.bodies()["paddle"]["position"].copy()
    calls = []

    def controller(s):
        calls.append(s.time)
        return [0.2, 0.0]  # 2D: (x, z)

    sim.drive("paddle", controller)
    sim.run()
    paddle = sim.bodies()["paddle"]
    assert len(calls) == sim.steps  # once before every step
    np.testing.assert_allclose(paddle["velocity"], [0.2, 0, 0], atol=1e-12)
    np.testing.assert_allclose(paddle["position"] - start, [0.2 * sim.time, 0, 0], atol=1e-9)
    assert sim.summary()["controller_seconds"] > 0
    sim.drive("paddle", None)  # stops calling it


def test_a_controller_turns_a_body(tmp_path):
    sim = sluice.Simulation(tank_with_a_paddle(), out=str(tmp_path), threads=1)
    sim.drive("paddle", lambda s: ([0, 0, 0], [0, 0.5, 0]))
    sim.run(until=0.05)
    paddle = sim.bodies()["paddle"]
    np.testing.assert_allclose(paddle["angular_velocity"], [0, 0.5, 0], atol=1e-9)
    # Turned by 0.5 rad/s * 0.05 s about y: the quaternion's y is sin(angle / 2).
    assert paddle["orientation"][1] == pytest.approx(np.sin(0.0125), abs=1e-9)


def test_only_a_prescribed_body_is_driven(tmp_path):
    sim = sluice.Simulation(tank_with_a_paddle("free"), out=str(tmp_path), threads=1)
    with pytest.raises(ValueError, match="prescribed"):
        sim.drive("paddle", lambda s: [0, 0])
    with pytest.raises(KeyError):
        sim.drive("no_such_body", lambda s: [0, 0])


def test_a_controller_that_raises_stops_before_the_step(tmp_path):
    sim = sluice.Simulation(tank_with_a_paddle(), out=str(tmp_path), threads=1)
    sim.drive("paddle", lambda s: 1 / 0)
    with pytest.raises(ZeroDivisionError):
        sim.run()
    assert sim.steps == 0
    sim.drive("paddle", lambda s: [1, 2, 3, 4])
    with pytest.raises(ValueError, match="3 components"):
        sim.step()
    assert sim.steps == 0
    sim.drive("paddle", lambda s: [0.1, 0])
    sim.step()
    assert sim.steps == 1


def test_a_controller_reads_but_does_not_step(tmp_path):
    sim = sluice.Simulation(tank_with_a_paddle(), out=str(tmp_path), threads=1)
    heights = []

    def reads(s):
        heights.append(s.bodies()["paddle"]["position"][2])
        return [0, 0.1]

    sim.drive("paddle", reads)
    sim.run(until=0.02)
    assert len(heights) == sim.steps and heights[-1] > heights[0]
    sim.drive("paddle", lambda s: s.step())
    with pytest.raises(RuntimeError, match="not step"):
        sim.step()


def test_a_2d_body_moves_in_its_plane_alone(tmp_path):
    sim = sluice.Simulation(tank_with_a_paddle(), out=str(tmp_path), threads=1)
    start = sim.bodies()["paddle"]["position"].copy()
    sim.drive("paddle", lambda s: ([0.1, 0.3, 0], [0.2, 0.5, 0.2]))
    sim.run(until=0.02)
    paddle = sim.bodies()["paddle"]
    np.testing.assert_allclose(paddle["angular_velocity"], [0, 0.5, 0], atol=1e-9)
    assert paddle["position"][1] == start[1]  # y is locked in 2D


def test_a_step_goes_forward_only(small_dam_break, tmp_path):
    sim = sluice.Simulation(small_dam_break, out=str(tmp_path), threads=1)
    sim.run(until=0.02)
    for until in (0.01, 0.02):
        with pytest.raises(ValueError, match="after the simulation's time"):
            sim.step(until=until)
    sim.run(until=0.02)  # already there: nothing to do
    assert sim.time == pytest.approx(0.02, abs=1e-12)


def test_no_thread_count_is_openmps_default(small_dam_break, tmp_path):
    """threads=0 takes OpenMP's default, as the command line does: OMP_NUM_THREADS where set."""
    expected = int(os.environ.get("OMP_NUM_THREADS", os.cpu_count()))
    assert sluice.Simulation(small_dam_break, out=str(tmp_path)).threads == expected
    assert sluice.Simulation(small_dam_break, out=str(tmp_path), threads=3).threads == 3


def test_another_thread_may_not_read_or_step_it_while_it_steps(tmp_path):
    """The steps run without the GIL: while one thread steps the simulation, another that
    reads or steps it gets RuntimeError (never a view of particles being moved), and once the
    run is over it reads it again."""
    case = sluice.Case.from_yaml(case_path("dam_break_2d"),
                                 set={"spacing": 0.04, "end_time": 0.1})
    sim = sluice.Simulation(case, out=str(tmp_path), threads=1)
    stepper = threading.Thread(target=sim.run)
    stepper.start()
    refused = 0
    while stepper.is_alive():
        for call in (sim.probes, sim.fields, sim.step):
            try:
                call()
            except RuntimeError:
                refused += 1
            except ValueError:  # step() after the run returned, before its thread ended
                assert sim.time == pytest.approx(0.1, abs=1e-12)
    stepper.join()
    assert refused > 0
    assert sim.time == pytest.approx(0.1, abs=1e-12)
    assert sim.probes()["front [m]"] > 1.0
