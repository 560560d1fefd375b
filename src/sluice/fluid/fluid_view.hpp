// What a fluid shows of itself, whatever its discretisation: labelled fields over its elements
// (particles, a grid's surface points, a grid's cells). A field views the model's own array
// where the model keeps one, or holds values the model works out for the view (a grid's
// velocity at the cell centres). sim/ turns a view into frames (sim/frame_output.hpp); a view is
// read before the model's next stage, which may change what it points at.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace sluice {

// One labelled field: `components` values an element, element after element, either reals
// or 32-bit integers. A field of two components is a vector in the x-z plane of a 2D case;
// one of three, a vector in space.
class FieldView {
 public:
  static FieldView of(std::string name, int components, const double* values,
                      std::size_t elements) {
    FieldView f(std::move(name), components);
    f.reals_ = {values, elements * static_cast<std::size_t>(components)};
    return f;
  }
  static FieldView of(std::string name, const std::int32_t* values, std::size_t elements) {
    FieldView f(std::move(name), 1);
    f.integers_ = {values, elements};
    f.integer_ = true;
    return f;
  }
  static FieldView holding(std::string name, int components, std::vector<double> values) {
    FieldView f(std::move(name), components);
    f.held_reals_ = std::move(values);
    return f;
  }
  static FieldView holding(std::string name, std::vector<std::int32_t> values) {
    FieldView f(std::move(name), 1);
    f.held_integers_ = std::move(values);
    f.integer_ = true;
    return f;
  }

  const std::string& name() const { return name_; }
  int components() const { return components_; }
  bool is_integer() const { return integer_; }
  std::size_t elements() const {
    return integer_ ? integers().size() : reals().size() / static_cast<std::size_t>(components_);
  }
  std::span<const double> reals() const {
    return held_reals_.empty() ? reals_ : std::span<const double>(held_reals_);
  }
  std::span<const std::int32_t> integers() const {
    return held_integers_.empty() ? integers_ : std::span<const std::int32_t>(held_integers_);
  }

 private:
  FieldView(std::string name, int components) : name_(std::move(name)), components_(components) {}

  std::string name_;
  int components_ = 1;
  bool integer_ = false;
  std::span<const double> reals_;
  std::span<const std::int32_t> integers_;
  std::vector<double> held_reals_;
  std::vector<std::int32_t> held_integers_;
};

// A fluid at one time: its points (a particle model's particles; a grid model's free surface,
// in segments or triangles) with their positions and fields, and a grid model's cells.
struct FluidView {
  struct Cells {
    std::array<int, 3> count{1, 1, 1};      // along x, y, z (a 2D grid: 1 along y)
    std::array<double, 3> origin{0, 0, 0};  // the first cell's lower corner
    double spacing = 1;
    std::vector<FieldView> fields;  // per cell, x fastest
  };

  FieldView positions = FieldView::holding("position", 3, {});
  std::vector<FieldView> fields;  // per point
  // How the points make cells: each a vertex (1), consecutive pairs segments (2), consecutive
  // triples triangles (3).
  int points_per_cell = 1;
  std::optional<Cells> cells;
  // What the fields point into where the view, not the model, owns it (a state downloaded from
  // a device for the view).
  std::shared_ptr<const void> keeps;
};

}  // namespace sluice
