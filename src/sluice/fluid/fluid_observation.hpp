// What a fluid lets the run observe of it, whatever its discretisation: its labelled fields
// (fluid_view.hpp), the probes' readings, its size, energy and the model's own counters.
// Frames, probes, energy.csv and the run's statistics (sim/) read the fluid through this alone.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/fluid/fluid_energy.hpp"
#include "sluice/fluid/fluid_view.hpp"

namespace sluice {

// How big the fluid is: its elements (particles or cells) and, of them, the fluid ones.
struct FluidSize {
  const char* element_name = "particles";  // what an element is, in messages
  std::size_t elements = 0;
  std::size_t fluid = 0;
  std::size_t wall = 0;
  std::size_t body = 0;
};

class FluidObservation {
 public:
  virtual ~FluidObservation() = default;

  // The present state's fields (docs/output.md): a particle model's particles; a grid model's
  // free surface, and its cells.
  virtual FluidView view() const = 0;
  // Probes: Shepard-averaged pressure at a point; height of the water column above the
  // domain's floor on a vertical gauge at (x, y); the furthest fluid along an axis (0 = x,
  // 1 = y).
  virtual double pressure_at(const Vec3& x) const = 0;
  virtual double water_height_at(const Vec3& gauge) const = 0;
  virtual double surge_front(int axis) const = 0;
  // The volume flux out of the domain through the case's open boundary `index` (inflow
  // negative) [m^3/s; 2D: m^2/s, per metre across]; NaN where the model has no such boundary.
  virtual double boundary_flux(std::size_t /*index*/) const {
    return std::numeric_limits<double>::quiet_NaN();
  }

  virtual FluidSize size() const = 0;
  virtual FluidEnergy energy() const = 0;  // and the fluid's mass
  // The model's own running totals, for the run's statistics (MPS: pressure solves and their
  // iterations); none by default.
  virtual std::vector<std::pair<std::string, double>> counters() const { return {}; }
};

}  // namespace sluice
