"""`sluice render` on a finished run: pictures of the right size, the water where it is, a
movie, and bad input named."""
import importlib.util
import os
import subprocess

import matplotlib
import matplotlib.image
import numpy as np
import pytest
import sluice
from conftest import ROOT, SLUICE, case_path


@pytest.fixture(scope="module")
def finished_run(tmp_path_factory):
    """The 2D dam break at 0.1 m to 0.1 s: its water a column 1 m wide at the left of a 4 m
    tank."""
    out = str(tmp_path_factory.mktemp("run"))
    case = sluice.Case.from_yaml(case_path("dam_break_2d"),
                                 set={"spacing": 0.1, "end_time": 0.1, "output_interval": 0.05})
    sluice.Simulation(case, out=out, threads=1).run()
    return out


def render(*args):
    return subprocess.run([SLUICE, "render", *args], capture_output=True, text=True)


def water_pixels(image):
    """Which pixels hold one of viridis' colours (the water's)."""
    viridis = matplotlib.colormaps["viridis"](np.linspace(0, 1, 256))[:, :3]
    rgb = image[..., :3].reshape(-1, 1, 3)
    distance = np.min(np.linalg.norm(rgb - viridis[None, :, :], axis=2), axis=1)
    return (distance < 0.02).reshape(image.shape[:2])


def test_draws_the_water_where_it_is(finished_run):
    done = render(finished_run, "--field", "pressure", "--width", "400")
    assert done.returncode == 0, done.stderr
    pictures = sorted(name for name in os.listdir(os.path.join(finished_run, "render"))
                      if name.startswith("pressure_side_"))
    assert pictures == [f"pressure_side_{k:06d}.png" for k in range(3)]
    image = matplotlib.image.imread(os.path.join(finished_run, "render", pictures[0]))
    # 400 pixels of picture and 160 of colour bar across; the tank's 4.6 m by 3.3 m with its
    # walls, below 70 pixels of title.
    assert image.shape[1] == 560 and 330 < image.shape[0] < 390
    water = water_pixels(image[:, :400])
    assert water.sum() > 1000  # not empty
    rows, columns = np.nonzero(water)
    # At t = 0 the water is the column 0 < x < 1 m of the 4 m tank (4.9 m across with its walls
    # and margins): a fifth of the picture's width, in its left quarter.
    assert columns.max() < 0.3 * 400 and columns.max() - columns.min() > 0.15 * 400


def test_a_movie_of_the_pictures(finished_run):
    done = render(finished_run, "--view", "side", "--movie", "--width", "200")
    assert done.returncode == 0, done.stderr
    movie = os.path.join(finished_run, "render", "velocity_side.mp4")
    assert os.path.getsize(movie) > 1000


def test_an_unknown_field_is_bad_input(finished_run):
    done = render(finished_run, "--field", "vorticity")
    assert done.returncode == 2
    assert "has no field 'vorticity'; it has density, kind, pressure, velocity" in done.stderr


def test_a_folder_without_a_run_is_bad_input(tmp_path):
    done = render(str(tmp_path))
    assert done.returncode == 2
    assert f"{tmp_path}: no run's series (CASE.pvd) here" in done.stderr


def test_a_bad_view_or_width_is_bad_input(finished_run):
    done = render(finished_run, "--view", "front")
    assert done.returncode == 2 and "--view: front not in {side,top,iso}" in done.stderr
    done = render(finished_run, "--width", "8")
    assert done.returncode == 2 and "--width" in done.stderr


def test_a_broken_series_is_bad_input(tmp_path):
    (tmp_path / "run.pvd").write_text("<VTKFile><Collection><DataSet timestep=")
    done = render(str(tmp_path))
    assert done.returncode == 2 and "run.pvd: not a readable series" in done.stderr


def test_one_picture_at_a_time(finished_run):
    picture = os.path.join(finished_run, "render", "density_side_000001.png")
    done = render(finished_run, "--field", "density", "--time", "0.06", "--width", "200")
    assert done.returncode == 0, done.stderr
    # The frames are at 0, 0.05 and 0.1 s: the nearest to 0.06 s is the second, alone.
    assert done.stdout.strip() == f"render: {picture} (t = 0.05 s)"
    assert sorted(name for name in os.listdir(os.path.join(finished_run, "render"))
                  if name.startswith("density_side_")) == ["density_side_000001.png"]
    assert water_pixels(matplotlib.image.imread(picture)[:, :200]).sum() > 100


def test_a_bad_time_is_bad_input(finished_run):
    done = render(finished_run, "--time", "soon")
    assert done.returncode == 2 and "--time: expected a time in seconds, got 'soon'" in done.stderr
    done = render(finished_run, "--time", "0.05", "--movie")
    assert done.returncode == 2 and "one picture makes no movie" in done.stderr


def test_the_nearer_point_covers_the_farther_whole():
    """Two points seen from the side, the farther (larger y) a little above the nearer: every
    pixel of the nearer's disc takes its colour, whichever disc offset reaches it last."""
    spec = importlib.util.spec_from_file_location("render_script",
                                                  os.path.join(ROOT, "scripts", "render.py"))
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    spacing = 0.1
    frame = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 1.0]])  # the framing: 1 m by 1 m
    canvas = script.Canvas(frame, "side", 200, spacing)
    points = np.array([[0.5, 0.0, 0.5], [0.5, 1.0, 0.53]])  # nearer, then farther and higher
    colours = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    image = canvas.draw(points, colours, np.array([False, False]), "side")
    col = int((0.5 - canvas.u0) * canvas.scale)
    row = canvas.height - 1 - int((0.5 - canvas.v0) * canvas.scale)
    r = canvas.radius
    disc = [(row + dr, col + dc) for dr in range(-r, r + 1) for dc in range(-r, r + 1)
            if dr * dr + dc * dc <= r * r]
    assert all(tuple(image[p]) == (1.0, 0.0, 0.0) for p in disc)
    # The farther shows above it, where the nearer does not reach.
    assert tuple(image[row - r - 2, col]) == (0.0, 0.0, 1.0)
