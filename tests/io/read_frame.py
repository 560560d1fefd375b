#!/usr/bin/python3
"""Checks a ParaView .pvd series written by sluice: every listed .vtp (or .pvtp, a run on several
ranks) must load in VTK's own reader without errors and carry the named point arrays; optionally the last frame's point count.
A grid model's series (--cells): every .vti must hold N cells with the named cell arrays, and
every .vtp must be a surface (line segments or triangles covering all its points).

usage: read_frame.py PVD_FILE [--points N | --min-points M] [--arrays velocity,pressure,...]
       read_frame.py PVD_FILE --cells N [--cell-arrays pressure,level_set,...]
Prints one summary line and exits 0, or prints the problem and exits 1.
"""
import argparse
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk

# Vector arrays and their required number of components; any other array may have any.
COMPONENTS = {"velocity": 3}


class Problem(Exception):
    pass


def read_pvd(path):
    """Returns [(time, vtp_path)] in file order. VTK 9.1's Python has no PVD reader."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as error:
        raise Problem(f"{path}: cannot parse: {error}")
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        raise Problem(f"{path}: not a VTKFile of type Collection")
    base = os.path.dirname(os.path.abspath(path))
    frames = []
    for dataset in root.iter("DataSet"):
        file, time = dataset.get("file"), dataset.get("timestep")
        if not file or time is None:
            raise Problem(f"{path}: DataSet without file or timestep attribute")
        try:
            time = float(time)
        except ValueError:
            raise Problem(f"{path}: DataSet {file}: timestep '{time}' is not a number")
        if not math.isfinite(time) or (frames and time < frames[-1][0]):
            raise Problem(f"{path}: DataSet {file}: timestep {time} is not finite and increasing")
        frames.append((time, os.path.join(base, file)))
    if not frames:
        raise Problem(f"{path}: no DataSet entries")
    return frames


def read_xml(path):
    """Loads one .vtp, .pvtp or .vti; fails on anything VTK reports as an error, from the reader or its
    parser."""
    if not os.path.isfile(path):
        raise Problem(f"{path}: listed in the .pvd but missing")
    log = vtk.vtkStringOutputWindow()
    vtk.vtkOutputWindow.SetInstance(log)
    errors = []
    # A run on several ranks writes each frame as a .pvtp that joins the ranks' pieces.
    reader = (vtk.vtkXMLImageDataReader() if path.endswith(".vti")
              else vtk.vtkXMLPPolyDataReader() if path.endswith(".pvtp")
              else vtk.vtkXMLPolyDataReader())
    reader.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
    reader.SetFileName(path)
    reader.Update()
    reported = log.GetOutput().strip()
    if errors or reader.GetErrorCode() != 0 or "ERROR" in reported:
        # The first message line after the "ERROR: In FILE, line N" location line.
        lines = [s for s in reported.splitlines() if s and not s.startswith("ERROR: In")]
        message = lines[0] if lines else f"error code {reader.GetErrorCode()}"
        raise Problem(f"{path}: VTK cannot read it: {message}")
    return reader.GetOutput()


def check_arrays(path, data, wanted, n, kind):
    for name in wanted:
        array = data.GetAbstractArray(name)
        if array is None:
            raise Problem(f"{path}: no {kind} array '{name}'")
        components, expected = array.GetNumberOfComponents(), COMPONENTS.get(name)
        if expected is not None and components != expected:
            raise Problem(f"{path}: '{name}' has {components} components, expected {expected}")
        if array.GetNumberOfTuples() != n:
            raise Problem(f"{path}: '{name}' has {array.GetNumberOfTuples()} tuples for {n} {kind}s")


def check_grid(path, data, cells, wanted):
    if data.GetNumberOfCells() != cells:
        raise Problem(f"{path}: {data.GetNumberOfCells()} cells, expected {cells}")
    check_arrays(path, data.GetCellData(), wanted, cells, "cell")


def check_surface(path, data):
    n = data.GetNumberOfPoints()
    lines, triangles = data.GetNumberOfLines(), data.GetNumberOfPolys()
    if data.GetNumberOfVerts() != 0 or 2 * lines + 3 * triangles != n:
        raise Problem(f"{path}: {lines} lines and {triangles} triangles for {n} points")


def check_frame(path, data, wanted):
    n = data.GetNumberOfPoints()
    if data.GetNumberOfVerts() != n:
        raise Problem(f"{path}: {data.GetNumberOfVerts()} vertex cells for {n} points")
    check_arrays(path, data.GetPointData(), wanted, n, "point")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd")
    count = parser.add_mutually_exclusive_group()
    count.add_argument("--points", type=int, help="the last frame has exactly N points")
    count.add_argument("--min-points", type=int, help="the last frame has at least M points")
    count.add_argument("--cells", type=int, help="a grid model's: every grid has exactly N cells")
    parser.add_argument("--arrays", default="", help="comma-separated point arrays every frame has")
    parser.add_argument("--cell-arrays", default="", help="comma-separated cell arrays every grid has")
    args = parser.parse_args()
    wanted = [name for name in args.arrays.split(",") if name]
    wanted_cells = [name for name in args.cell_arrays.split(",") if name]
    # Errors are collected per file (see read_vtp); keep vtkLogger from repeating them on stderr.
    vtk.vtkLogger.SetStderrVerbosity(vtk.vtkLogger.VERBOSITY_OFF)

    try:
        frames = read_pvd(args.pvd)
        for _, path in frames:
            if path.endswith(".vti"):
                check_grid(path, read_xml(path), args.cells, wanted_cells)
            elif args.cells is not None:
                check_surface(path, read_xml(path))
            else:
                data = read_xml(path)
                check_frame(path, data, wanted)
        if args.cells is not None:
            grids = sum(path.endswith(".vti") for _, path in frames)
            if grids == 0 or 2 * grids != len(frames):
                raise Problem(f"{args.pvd}: {grids} grids among {len(frames)} files")
            print(f"read {grids} grids of {args.cells} cells and their surfaces")
            return 0
        n, last = data.GetNumberOfPoints(), frames[-1][1]
        if args.points is not None and n != args.points:
            raise Problem(f"{last}: last frame has {n} points, expected {args.points}")
        if args.min_points is not None and n < args.min_points:
            raise Problem(f"{last}: last frame has {n} points, expected >= {args.min_points}")
    except Problem as problem:
        print(f"read_frame: {problem}")
        return 1

    point_data = data.GetPointData()
    arrays = ", ".join(
        f"{point_data.GetArrayName(i)}({point_data.GetAbstractArray(i).GetNumberOfComponents()})"
        for i in range(point_data.GetNumberOfArrays()))
    print(f"read {len(frames)} frames, last has {n} points, arrays: {arrays}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
