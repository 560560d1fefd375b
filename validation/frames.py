"""Reading one output frame (a .vtp file of sluice's series): its points and the point fields
asked for, as numpy arrays."""
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read_frame(path, *fields):
    """(points, {name: values}) of the frame at `path`: points n x 3, each field n or n x 3."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    values = data.GetPointData()
    return (vtk_to_numpy(data.GetPoints().GetData()),
            {name: vtk_to_numpy(values.GetArray(name)) for name in fields})
