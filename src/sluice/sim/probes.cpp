#include "sluice/sim/probes.hpp"

#include <cmath>

#include "sluice/exec/policy.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

template <int D>
Probes<D>::Probes(const std::vector<io::ProbeConfig>& probes, const std::string& csv_path,
                  Real radius)
    : probes_(probes), radius_(radius) {
  if (probes_.empty() || csv_path.empty()) return;
  std::vector<std::string> header{"time [s]"};
  for (const auto& p : probes_) {
    switch (p.kind) {
      case io::ProbeKind::kPressure:
        header.push_back(p.name + " pressure [Pa]");
        break;
      case io::ProbeKind::kWaterHeight:
        header.push_back(p.name + " water height [m]");
        break;
      case io::ProbeKind::kSurgeFront:
        header.push_back(p.name + " front [m]");
        break;
    }
  }
  csv_ = std::make_unique<io::CsvWriter>(csv_path, header);
}

template <int D>
std::vector<double> Probes<D>::measure(const ParticleState<D>& s) const {
  std::vector<double> row;
  for (const auto& p : probes_) {
    switch (p.kind) {
      case io::ProbeKind::kPressure:
        row.push_back(pressure_at(s, from_3d<D>(p.point)));
        break;
      case io::ProbeKind::kWaterHeight:
        row.push_back(water_height_at(s, p.point));
        break;
      case io::ProbeKind::kSurgeFront:
        row.push_back(surge_front(s, p.axis));
        break;
    }
  }
  return row;
}

template <int D>
void Probes<D>::record(const ParticleState<D>& s) {
  if (!csv_) return;
  std::vector<double> row{s.time};
  for (double v : measure(s)) row.push_back(v);
  csv_->row(row);
}

// Shepard average of the fluid's pressure with a Wendland weight over the model's support;
// zero where no fluid is within reach.
template <int D>
Real Probes<D>::pressure_at(const ParticleState<D>& s, const Vec<D>& x) const {
  const WendlandC2<D> kernel(radius_ / 2);
  const auto& ps = s.particles;
  Real sum_w = 0, sum_pw = 0;
  s.cells.for_each_near(ps.position, x, radius_ * radius_,
                        [&](std::size_t j, const Vec<D>&, Real r2) {
                          if (!ps.is_fluid(j)) return;
                          const Real w = kernel.value(std::sqrt(r2)) * ps.mass[j] / ps.density[j];
                          sum_w += w;
                          sum_pw += w * ps.pressure[j];
                        });
  return sum_w > 0 ? sum_pw / sum_w : 0;
}

// Height above the domain floor of the highest point of the gauge line where the fluid's
// kernel-summed volume fraction is at least one half (isolated drops do not count).
template <int D>
Real Probes<D>::water_height_at(const ParticleState<D>& s, const Vec3& gauge) const {
  const WendlandC2<D> kernel(radius_ / 2);
  const auto& ps = s.particles;
  const Real floor = s.domain.min[2];
  const Real step = 0.25 * s.spacing;
  Real height = 0;
  for (Real z = floor; z <= s.domain.max[2]; z += step) {
    const Vec<D> x = from_3d<D>(Vec3(gauge[0], gauge[1], z));
    Real fraction = 0;
    s.cells.for_each_near(ps.position, x, radius_ * radius_,
                          [&](std::size_t j, const Vec<D>&, Real r2) {
                            if (ps.is_fluid(j))
                              fraction += kernel.value(std::sqrt(r2)) * ps.mass[j] / ps.density[j];
                          });
    if (fraction >= 0.5) height = z - floor;
  }
  return height;
}

// Largest coordinate of the fluid along the axis, to the edge of the particle (+ dx/2).
template <int D>
Real Probes<D>::surge_front(const ParticleState<D>& s, int axis3) const {
  const int axis = (D == 2 && axis3 == 0) ? 0 : axis3;
  const auto& ps = s.particles;
  const Real front = exec::Default::max_of(
      ps.size(), [&](std::size_t i) { return ps.is_fluid(i) ? ps.position[i][axis] : -1e300; });
  return front + 0.5 * s.spacing;
}

template class Probes<2>;
template class Probes<3>;

}  // namespace sluice
