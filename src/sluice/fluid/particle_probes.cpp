// The particle base's probe queries.
#include <array>
#include <cmath>
#include <vector>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/fluid/water_column.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

// Shepard average of the fluid's pressure with a Wendland weight over the model's support;
// zero where no fluid is within reach.
template <int D>
double ParticleFluid<D>::pressure_at(const Vec3& point) const {
  refresh_host();
  const ParticleState<D>& s = state_;
  const Vec<D> x = from_3d<D>(point);
  const WendlandC2<D> kernel(radius_ / 2);
  const auto& ps = s.particles;
  const std::int32_t* counted = counted_kinds();
  std::array<double, 2> sums{};  // of the weights, and of the weighted pressures
  s.cells.for_each_near(ps.position, x, radius_ * radius_,
                        [&](std::size_t j, const Vec<D>&, Real r2) {
                          if (counted[j] != 0) return;  // fluid this rank owns
                          const Real w = kernel.value(std::sqrt(r2)) * ps.mass[j] / ps.density[j];
                          sums[0] += w;
                          sums[1] += w * ps.pressure[j];
                        });
  ranks_.sum(sums);
  return sums[0] > 0 ? sums[1] / sums[0] : 0;
}

template <int D>
double ParticleFluid<D>::boundary_flux(std::size_t index) const {
  if (open_.empty()) return FluidObservation::boundary_flux(index);
  refresh_host();
  if (!exchange_) return open_.outflow(state_.particles, open_zone_, index);
  return ranks_.sum(open_.outflow(state_.particles, open_zone_, index, owned_kind_));
}

// Height above the domain floor of the top of the lowest water on the gauge's vertical line,
// water being where the fluid's kernel-summed volume fraction is at least one half (so isolated
// drops do not count), sampled every dx/4; a dip shorter than a spacing is bridged (`granular`'s
// support, about one spacing, leaves its sum below one half between its layers of spheres).
template <int D>
double ParticleFluid<D>::water_height_at(const Vec3& gauge) const {
  refresh_host();
  const ParticleState<D>& s = state_;
  const WendlandC2<D> kernel(radius_ / 2);
  const auto& ps = s.particles;
  const Real floor = s.domain.min[2];
  constexpr int kSamplesPerSpacing = 4;
  const Real step = s.spacing / kSamplesPerSpacing;
  const std::int32_t* counted = counted_kinds();
  std::vector<double> heights, fractions;
  for (Real z = floor; z <= s.domain.max[2]; z += step) {
    const Vec<D> x = from_3d<D>(Vec3(gauge[0], gauge[1], z));
    double fraction = 0;
    s.cells.for_each_near(ps.position, x, radius_ * radius_,
                          [&](std::size_t j, const Vec<D>&, Real r2) {
                            if (counted[j] == 0)  // fluid this rank owns
                              fraction += kernel.value(std::sqrt(r2)) * ps.mass[j] / ps.density[j];
                          });
    heights.push_back(z - floor);
    fractions.push_back(fraction);
  }
  ranks_.sum(fractions);
  const std::ptrdiff_t top = top_of_lowest_water(
      fractions.size(), [&](std::size_t k) { return fractions[k] >= 0.5; }, kSamplesPerSpacing - 1);
  return top < 0 ? 0.0 : heights[static_cast<std::size_t>(top)];
}

// Largest coordinate of the fluid along the axis, to the edge of the particle (+ dx/2).
template <int D>
double ParticleFluid<D>::surge_front(int axis3) const {
  refresh_host();
  const ParticleState<D>& s = state_;
  const int axis = (D == 2 && axis3 == 0) ? 0 : axis3;
  const auto& ps = s.particles;
  const std::int32_t* counted = counted_kinds();
  const Real front = exec::Default::max_of(
      ps.size(), [&](std::size_t i) { return counted[i] == 0 ? ps.position[i][axis] : -1e300; });
  return ranks_.max(front) + 0.5 * s.spacing;
}

// The class is instantiated in particle_fluid.cpp; these are its members defined here.
template double ParticleFluid<2>::pressure_at(const Vec3&) const;
template double ParticleFluid<2>::water_height_at(const Vec3&) const;
template double ParticleFluid<2>::surge_front(int) const;
template double ParticleFluid<2>::boundary_flux(std::size_t) const;
template double ParticleFluid<3>::pressure_at(const Vec3&) const;
template double ParticleFluid<3>::water_height_at(const Vec3&) const;
template double ParticleFluid<3>::surge_front(int) const;
template double ParticleFluid<3>::boundary_flux(std::size_t) const;

}  // namespace sluice
