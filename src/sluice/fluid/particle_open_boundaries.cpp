#include "sluice/fluid/particle_open_boundaries.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace sluice {

template <int D>
ParticleOpenBoundaries<D>::ParticleOpenBoundaries(std::vector<io::BoundaryConfig> sides,
                                                  const AxisBox& domain, Real spacing, int layers,
                                                  Real density, Real up_gravity)
    : sides_(std::move(sides)),
      domain_(domain),
      spacing_(spacing),
      buffer_depth_(layers * spacing),
      density_(density),
      up_gravity_(up_gravity) {}

template <int D>
Real ParticleOpenBoundaries<D>::inner_face(const io::BoundaryConfig& side) const {
  return side.upper ? domain_.max[side.axis] - buffer_depth_
                    : domain_.min[side.axis] + buffer_depth_;
}

template <int D>
Real ParticleOpenBoundaries<D>::surface_of(const io::BoundaryConfig& side) const {
  return side.depth ? domain_.min[2] + *side.depth : domain_.max[2];
}

template <int D>
std::vector<std::pair<std::size_t, AxisBox>> ParticleOpenBoundaries<D>::inlet_buffers() const {
  std::vector<std::pair<std::size_t, AxisBox>> out;
  for (std::size_t b = 0; b < sides_.size(); ++b) {
    const io::BoundaryConfig& side = sides_[b];
    if (side.kind != io::BoundaryKind::kInlet) continue;
    AxisBox box = domain_;
    (side.upper ? box.min : box.max)[side.axis] = inner_face(side);
    box.max[2] = std::min(box.max[2], surface_of(side));
    out.emplace_back(b, box);
  }
  return out;
}

template <int D>
bool ParticleOpenBoundaries<D>::in_inlet_buffer(const Vec<D>& x) const {
  for (const io::BoundaryConfig& side : sides_) {
    if (side.kind == io::BoundaryKind::kInlet && beyond_inner_face(side, x) > 0) return true;
  }
  return false;
}

template <int D>
Vec<D> ParticleOpenBoundaries<D>::inflow_velocity(std::size_t index, const Vec<D>& x,
                                                  double time) const {
  const io::BoundaryConfig& side = sides_[index];
  const int a = model_axis(side);
  Real factor = 1;
  for (int b = 0; b < D; ++b) {
    if (b == a) continue;
    const int b3 = D == 3 ? b : 2 * b;
    const Real lo = domain_.min[b3];
    const Real hi = b3 == 2 ? std::min(domain_.max[2], surface_of(side)) : domain_.max[b3];
    factor *= side.profile_across((x[b] - lo) / (hi - lo));
  }
  Vec<D> v = Vec<D>::Zero();
  v[a] = -outward(side) * side.speed_at(time) * factor;
  return v;
}

template <int D>
bool ParticleOpenBoundaries<D>::join_outlet(ParticleSet<D>& ps, FieldHandle<std::int32_t> zone,
                                            std::size_t i) const {
  for (std::size_t b = 0; b < sides_.size(); ++b) {
    const io::BoundaryConfig& side = sides_[b];
    if (side.kind == io::BoundaryKind::kOutlet && beyond_inner_face(side, ps.position[i]) > 0) {
      ps.kind[i] = ParticleKind::kWall;
      ps[zone][i] = static_cast<std::int32_t>(b + 1);
      return true;
    }
  }
  return false;
}

template <int D>
std::size_t ParticleOpenBoundaries<D>::start(ParticleSet<D>& ps,
                                             FieldHandle<std::int32_t> zone) const {
  std::size_t joined = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps.is_fluid(i) && join_outlet(ps, zone, i)) ++joined;
  }
  return joined;
}

template <int D>
void ParticleOpenBoundaries<D>::advance(ParticleSet<D>& ps, FieldHandle<std::int32_t> zone,
                                        double time, Real dt, std::vector<bool>& gone,
                                        BufferHandOver& hand_over,
                                        std::optional<FieldHandle<std::int32_t>> owned) const {
  const std::size_t before = ps.size();
  gone.assign(before, false);
  hand_over.joined.clear();
  hand_over.left.clear();
  hand_over.dropped.clear();
  for (std::size_t b = 0; b < sides_.size(); ++b) {
    if (sides_[b].kind == io::BoundaryKind::kOutlet)
      extrapolate_outlet_velocity(ps, zone, b, owned);
  }
  std::vector<unsigned char> copy;
  for (std::size_t i = 0; i < before; ++i) {
    if (owned && ps[*owned][i] < 0) continue;
    const std::int32_t z = ps[zone][i];
    if (z == 0) {
      if (!ps.is_fluid(i)) continue;
      // Fluid that entered an outlet's buffer joins it, at the velocity it has; fluid that
      // drifted back into an inlet's goes.
      if (join_outlet(ps, zone, i)) {
        hand_over.left.push_back(static_cast<std::uint32_t>(i));
      } else if (in_inlet_buffer(ps.position[i])) {
        gone[i] = true;
        hand_over.dropped.push_back(static_cast<std::uint32_t>(i));
      }
      continue;
    }
    const std::size_t b = static_cast<std::size_t>(z - 1);
    const io::BoundaryConfig& side = sides_[b];
    ps.position[i] += dt * ps.velocity[i];
    const bool inside = beyond_inner_face(side, ps.position[i]) <= 0;
    if (side.kind == io::BoundaryKind::kInlet) {
      ps.velocity[i] = inflow_velocity(b, ps.position[i], time + dt);
      if (!inside) continue;
      // Into the domain: a copy one buffer's depth back takes its place in the buffer.
      copy.clear();
      ps.pack({static_cast<std::uint32_t>(i)}, copy);
      ps.unpack_append(copy.data(), 1);
      ps.position.back()[model_axis(side)] += outward(side) * buffer_depth_;
      ps.velocity.back() = inflow_velocity(b, ps.position.back(), time + dt);
    } else {
      const Real beyond_side =
          outward(side) * (ps.position[i][model_axis(side)] -
                           (side.upper ? domain_.max[side.axis] : domain_.min[side.axis]));
      if (beyond_side >= 0) gone[i] = true;  // out of the domain
      if (!inside) continue;
    }
    ps.kind[i] = ParticleKind::kFluid;
    ps[zone][i] = 0;
    hand_over.joined.push_back(static_cast<std::uint32_t>(i));
  }
  gone.resize(ps.size(), false);
}

template <int D>
void ParticleOpenBoundaries<D>::extrapolate_outlet_velocity(
    ParticleSet<D>& ps, FieldHandle<std::int32_t> zone, std::size_t index,
    std::optional<FieldHandle<std::int32_t>> owned) const {
  const io::BoundaryConfig& side = sides_[index];
  const Real width = 2 * spacing_;
  // The squares across the flow: the domain's other axes (2D: the one), in widths of two
  // spacings.
  std::array<int, 2> across{}, count{1, 1};
  for (int b = 0, k = 0; b < D; ++b) {
    if (b == model_axis(side)) continue;
    across[static_cast<std::size_t>(k)] = b;
    const int b3 = D == 3 ? b : 2 * b;
    count[static_cast<std::size_t>(k++)] =
        std::max(1, static_cast<int>(std::ceil((domain_.max[b3] - domain_.min[b3]) / width)));
  }
  // The square of x, or -1 for a point beyond the domain across the flow (a periodic axis's
  // image of the water on the other side, which that water's own square counts already).
  auto square_of = [&](const Vec<D>& x) {
    std::ptrdiff_t square = 0;
    for (int k = 0; k < D - 1; ++k) {
      const int b = across[static_cast<std::size_t>(k)];
      const int b3 = D == 3 ? b : 2 * b;
      if (x[b] < domain_.min[b3] || x[b] > domain_.max[b3]) return std::ptrdiff_t{-1};
      const int n = count[static_cast<std::size_t>(k)];
      const int at =
          std::min(static_cast<int>(std::floor((x[b] - domain_.min[b3]) / width)), n - 1);
      square = square * n + at;
    }
    return square;
  };
  std::vector<Vec<D>> sum(static_cast<std::size_t>(count[0]) * static_cast<std::size_t>(count[1]),
                          Vec<D>::Zero());
  std::vector<int> found(sum.size(), 0);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    const Real beyond = beyond_inner_face(side, ps.position[i]);
    if (beyond > 0 || beyond < -width) continue;
    const std::ptrdiff_t square = square_of(ps.position[i]);
    if (square < 0) continue;
    sum[static_cast<std::size_t>(square)] += ps.velocity[i];
    ++found[static_cast<std::size_t>(square)];
  }
  const auto own = static_cast<std::int32_t>(index + 1);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps[zone][i] != own || (owned && ps[*owned][i] < 0)) continue;
    const std::ptrdiff_t square = square_of(ps.position[i]);
    if (square < 0) continue;
    const auto s = static_cast<std::size_t>(square);
    if (found[s] > 0) ps.velocity[i] = sum[s] / found[s];
  }
}

template <int D>
Real ParticleOpenBoundaries<D>::outlet_pressure(const io::BoundaryConfig& side, const Vec<D>& x,
                                                Real surface_shift) const {
  const Real head =
      side.depth ? std::max(Real(0), surface_of(side) + surface_shift - x[D - 1]) : Real(0);
  return side.pressure.value_or(0) - density_ * up_gravity_ * head;
}

template <int D>
double ParticleOpenBoundaries<D>::outflow(const ParticleSet<D>& ps, FieldHandle<std::int32_t> zone,
                                          std::size_t index,
                                          std::optional<FieldHandle<std::int32_t>> owned) const {
  const io::BoundaryConfig& side = sides_[index];
  const int a = model_axis(side);
  const auto& in = ps[zone];
  const auto own = static_cast<std::int32_t>(index + 1);
  double sum = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if ((!ps.is_fluid(i) && in[i] != own) || (owned && ps[*owned][i] < 0)) continue;
    const Real hat = 1 - std::abs(beyond_inner_face(side, ps.position[i])) / spacing_;
    if (hat <= 0) continue;
    sum += ps.mass[i] / density_ * outward(side) * ps.velocity[i][a] * hat / spacing_;
  }
  return sum;
}

template class ParticleOpenBoundaries<2>;
template class ParticleOpenBoundaries<3>;

}  // namespace sluice
