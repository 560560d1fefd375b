// A fluid's view (fluid/fluid_view.hpp) as numpy arrays: without a copy, read-only, where the
// view points into the model's memory.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>

#include "sluice/core/types.hpp"
#include "sluice/fluid/fluid_view.hpp"

namespace sluice::python {

// {name: array} of the view's point fields and 'position'. Without `copy`, an array that views
// the model's memory keeps `owner` (the simulation) alive and is read-only.
pybind11::dict fields_of(FluidView view, const pybind11::object& owner, bool copy);
// A grid model's cell fields, shaped (nz, ny, nx[, components]), with 'origin' and 'spacing';
// None where the view has no cells.
pybind11::object grid_fields_of(FluidView view, const pybind11::object& owner, bool copy);
// (x, y, z), or (x, y, z, w) with `w`, as a new array.
pybind11::array_t<double> vector_array(const Vec3& v, std::optional<double> w = std::nullopt);

}  // namespace sluice::python
