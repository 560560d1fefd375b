"""Reading one output frame (a .vtp file of sluice's series): its points and the point fields
asked for, as numpy arrays; and the grid model's cells (a .vti file) alike; and the frames a run's
.pvd collection lists."""
import os
import xml.etree.ElementTree as ElementTree

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader

from runs import require


def frame_series(out):
    """(time, path) of each frame listed in the output's .pvd collection."""
    pvd = [name for name in os.listdir(out) if name.endswith(".pvd")]
    require(os.path.join(out, pvd[0] if pvd else "*.pvd"))
    root = ElementTree.parse(os.path.join(out, pvd[0])).getroot()
    return [(float(d.get("timestep")), os.path.join(out, d.get("file")))
            for d in root.iter("DataSet")]


def read_frame(path, *fields):
    """(points, {name: values}) of the frame at `path`: points n x 3, each field n or n x 3."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    values = data.GetPointData()
    return (vtk_to_numpy(data.GetPoints().GetData()),
            {name: vtk_to_numpy(values.GetArray(name)) for name in fields})


def read_grid(path, *fields):
    """(centres, {name: values}) of the grid model's cells in the .vti at `path`: the cells'
    centres n x 3 (x fastest, then y, then z), each cell field n or n x 3."""
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    extent, origin, spacing = image.GetExtent(), image.GetOrigin(), image.GetSpacing()
    # A 2D grid's y extent is one point (no cells along it): its cells lie at its y.
    axes = [origin[a] + spacing[a] * (np.arange(extent[2 * a], extent[2 * a + 1]) + 0.5)
            if extent[2 * a + 1] > extent[2 * a] else np.array([origin[a]]) for a in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    centres = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    values = image.GetCellData()
    return centres, {name: vtk_to_numpy(values.GetArray(name)) for name in fields}
