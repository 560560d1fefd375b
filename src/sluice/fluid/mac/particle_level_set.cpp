#include "sluice/fluid/mac/particle_level_set.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mac/advection.hpp"

namespace sluice {

namespace {

// Enright et al.'s bounds on a particle's radius, in cells.
constexpr Real kSmallestRadius = 0.1;
constexpr Real kLargestRadius = 0.5;

// The gradient of phi at x by central differences of the interpolant, normalised.
template <int D>
Vec<D> normal_at(const Lattice<D>& cells, const CellField& phi, const Vec<D>& x) {
  Vec<D> g;
  for (int a = 0; a < D; ++a) {
    Vec<D> step = Vec<D>::Zero();
    step[a] = 0.5 * cells.h;
    g[a] = cells.sample(phi, x + step) - cells.sample(phi, x - step);
  }
  const Real norm = g.norm();
  return norm > 0 ? Vec<D>(g / norm) : Vec<D>::Zero();
}

}  // namespace

template <int D>
void ParticleLevelSet<D>::reseed(const MacGrid<D>& grid, const CellField& phi) {
  const Lattice<D> cells = grid.cell_lattice();
  const Real h = grid.h;
  const Real band = band_ * h;
  // Dropped too: those carried out of the grid (through an outlet), which sampling would hold
  // on its boundary.
  auto outside = [&](const Marker& m) {
    for (int a = 0; a < D; ++a)
      if (m.x[a] < grid.origin[a] || m.x[a] > grid.origin[a] + grid.cells[a] * h) return true;
    return false;
  };
  std::erase_if(markers_, [&](const Marker& m) {
    return outside(m) || std::abs(cells.sample(phi, m.x)) > band;
  });
  std::vector<int> count(cells.size(), 0);
  for (const Marker& m : markers_) {
    GridIndex<D> c;
    for (int a = 0; a < D; ++a)
      c[a] = std::clamp(static_cast<int>(std::floor((m.x[a] - grid.origin[a]) / h)), 0,
                        grid.cells[a] - 1);
    ++count[cells.index(c)];
  }
  // A generator of the standard's own definition, so the same particles on every machine.
  std::mt19937 random(static_cast<std::mt19937::result_type>(++seed_counter_));
  auto uniform = [&] { return (random() >> 8) * (1.0 / 16777216.0); };
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (std::abs(phi[k]) > band || count[k] >= 2 * per_cell_) continue;
    const Vec<D> corner = cells.position(cells.coordinates(k)) - Vec<D>::Constant(0.5 * h);
    for (int n = count[k]; n < 2 * per_cell_; ++n) {
      Vec<D> x;
      for (int a = 0; a < D; ++a) x[a] = corner[a] + uniform() * h;
      const int sign = n % 2 == 0 ? 1 : -1;
      const Real goal = sign * (kSmallestRadius * h + uniform() * (band - kSmallestRadius * h));
      // Drawn along the normal towards the goal level, a few times (the surface is curved).
      for (int iteration = 0; iteration < 3; ++iteration)
        x += (goal - cells.sample(phi, x)) * normal_at(cells, phi, x);
      const Real level = sign * cells.sample(phi, x);
      if (level < kSmallestRadius * h || level > band) continue;
      markers_.push_back({x, std::clamp(level, kSmallestRadius * h, kLargestRadius * h), sign});
    }
  }
}

template <int D>
void ParticleLevelSet<D>::advect(const MacGrid<D>& grid, const FaceField<D>& u, Real dt) {
  exec::Default::for_each(markers_.size(), [&](std::size_t i) {
    Vec<D>& x = markers_[i].x;
    const Vec<D> middle = x + 0.5 * dt * velocity_at(grid, u, x);
    x = grid.wrapped(x + dt * velocity_at(grid, u, middle));
  });
}

template <int D>
std::size_t ParticleLevelSet<D>::correct(const MacGrid<D>& grid, CellField& phi) const {
  const Lattice<D> cells = grid.cell_lattice();
  CellField plus = phi, minus = phi;
  std::size_t escaped = 0;
  for (const Marker& m : markers_) {
    if (m.sign * cells.sample(phi, m.x) >= -m.radius) continue;
    ++escaped;
    GridIndex<D> base;
    for (int a = 0; a < D; ++a)
      base[a] = static_cast<int>(std::floor((m.x[a] - cells.first[a]) / cells.h));
    for (int corner = 0; corner < (1 << D); ++corner) {
      GridIndex<D> c = base;
      for (int a = 0; a < D; ++a) c[a] += (corner >> a) & 1;
      if (!cells.contains(c)) continue;
      const std::size_t k = cells.index(c);
      const Real sphere = m.sign * (m.radius - (cells.position(c) - m.x).norm());
      if (m.sign > 0) {
        plus[k] = std::max(plus[k], sphere);
      } else {
        minus[k] = std::min(minus[k], sphere);
      }
    }
  }
  if (escaped == 0) return 0;
  exec::Default::for_each_light(phi.size(), [&](std::size_t k) {
    phi[k] = std::abs(plus[k]) <= std::abs(minus[k]) ? plus[k] : minus[k];
  });
  return escaped;
}

template <int D>
void ParticleLevelSet<D>::adjust_radii(const MacGrid<D>& grid, const CellField& phi) {
  const Lattice<D> cells = grid.cell_lattice();
  const Real h = grid.h;
  std::vector<char> drop(markers_.size(), 0);
  exec::Default::for_each(markers_.size(), [&](std::size_t i) {
    Marker& m = markers_[i];
    const Real level = m.sign * cells.sample(phi, m.x);
    if (level < -1.5 * m.radius) {
      drop[i] = 1;
    } else if (level >= 0) {
      m.radius = std::clamp(level, kSmallestRadius * h, kLargestRadius * h);
    }
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < markers_.size(); ++i)
    if (!drop[i]) markers_[kept++] = markers_[i];
  markers_.resize(kept);
}

template <int D>
void ParticleLevelSet<D>::follow_shift(const MacGrid<D>& grid, const CellField& phi, Real shift) {
  const Lattice<D> cells = grid.cell_lattice();
  exec::Default::for_each(markers_.size(), [&](std::size_t i) {
    Marker& m = markers_[i];
    m.x -= shift * normal_at(cells, phi, m.x);
  });
}

template <int D>
std::vector<Vec<D>> ParticleLevelSet<D>::positions() const {
  std::vector<Vec<D>> out;
  for (const Marker& m : markers_) out.push_back(m.x);
  return out;
}

template <int D>
std::vector<int> ParticleLevelSet<D>::signs() const {
  std::vector<int> out;
  for (const Marker& m : markers_) out.push_back(m.sign);
  return out;
}

template class ParticleLevelSet<2>;
template class ParticleLevelSet<3>;

}  // namespace sluice
