#include "field_arrays.hpp"

#include <memory>
#include <string>
#include <vector>

namespace py = pybind11;

namespace sluice::python {

namespace {

// What an array without a copy keeps alive: the view (which may hold its values, or a state
// downloaded for it) and the simulation whose memory it points into.
struct Keeper {
  std::shared_ptr<const FluidView> view;
  py::object owner;
};

// One field as an array of `shape`: viewing its values (read-only) unless `copy`.
py::array array_of(const FieldView& field, std::vector<py::ssize_t> shape,
                   const std::shared_ptr<const FluidView>& view, const py::object& owner,
                   bool copy) {
  if (field.components() > 1) shape.push_back(field.components());
  py::array out;
  const auto make = [&](const auto* data) {
    using T = std::remove_const_t<std::remove_pointer_t<decltype(data)>>;
    if (copy) return py::array(py::array_t<T>(shape, data));
    auto* keeper = new Keeper{view, owner};
    py::capsule base(keeper, [](void* p) { delete static_cast<Keeper*>(p); });
    return py::array(py::array_t<T>(shape, data, base));
  };
  out = field.is_integer() ? make(field.integers().data()) : make(field.reals().data());
  if (!copy) out.attr("setflags")(py::arg("write") = false);
  return out;
}

}  // namespace

py::dict fields_of(FluidView view, const py::object& owner, bool copy) {
  const auto shared = std::make_shared<const FluidView>(std::move(view));
  const auto points = static_cast<py::ssize_t>(shared->positions.elements());
  py::dict out;
  out["position"] = array_of(shared->positions, {points}, shared, owner, copy);
  for (const FieldView& field : shared->fields) {
    out[py::str(field.name())] = array_of(field, {points}, shared, owner, copy);
  }
  return out;
}

py::object grid_fields_of(FluidView view, const py::object& owner, bool copy) {
  if (!view.cells) return py::none();
  const auto shared = std::make_shared<const FluidView>(std::move(view));
  const FluidView::Cells& cells = *shared->cells;
  const std::vector<py::ssize_t> shape{cells.count[2], cells.count[1], cells.count[0]};
  py::dict out;
  for (const FieldView& field : cells.fields) {
    out[py::str(field.name())] = array_of(field, shape, shared, owner, copy);
  }
  out["origin"] = py::array_t<double>(3, cells.origin.data());
  out["spacing"] = cells.spacing;
  return out;
}

py::array_t<double> vector_array(const Vec3& v, std::optional<double> w) {
  py::array_t<double> out(w ? 4 : 3);
  auto a = out.mutable_unchecked<1>();
  for (int k = 0; k < 3; ++k) a(k) = v[k];
  if (w) a(3) = *w;
  return out;
}

}  // namespace sluice::python
