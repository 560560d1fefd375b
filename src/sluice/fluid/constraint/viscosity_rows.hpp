// The viscosity constraints' rows (viscosity_constraints.hpp) as loop bodies over plain arrays,
// each a function of one fluid particle's index (its D rows), so that the host's threads run
// them on the group's vectors and a device run on its copy: the weights, the rows' velocities,
// the gathered impulses, the diagonal.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// A fluid neighbour j of particle i: forward = w_ij (row i's weight of j), backward = w_ji.
struct ViscosityEntry {
  std::uint32_t particle;
  Real forward, backward;
};

// Particle i's neighbours from offsets[i]; its rows along the world axes axes[0, axis_count)
// (2D: x and z), particle-major; particle i is the problem's body first + i.
struct ViscosityRows {
  std::size_t first;
  Real inverse_mass, compliance;
  const std::size_t* offsets;
  const ViscosityEntry* entries;
  int axes[3];
  std::size_t axis_count;
};

// Particle i's neighbours' kernel values summed (entries' `forward` holding W before normalise).
struct ViscosityKernelSum {
  const std::size_t* offsets;
  const ViscosityEntry* entries;
  Real* total;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    for (std::size_t k = offsets[i]; k < offsets[i + 1]; ++k) total[i] += entries[k].forward;
  }
};

// Particle i's entries' W turned into the weights w_ij = W / total_i and w_ji = W / total_j.
struct ViscosityWeights {
  const std::size_t* offsets;
  ViscosityEntry* entries;
  const Real* total;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    for (std::size_t k = offsets[i]; k < offsets[i + 1]; ++k) {
      ViscosityEntry& e = entries[k];
      const Real w = e.forward;
      e.forward = w / total[i];
      e.backward = w / total[e.particle];
    }
  }
};

// Particle i's rows: its velocity less the weighted mean of its neighbours', along each axis.
struct ViscosityRowVelocities {
  ViscosityRows rows;
  const Vec3* linear;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    Vec3 mean = Vec3::Zero();
    for (std::size_t k = rows.offsets[i]; k < rows.offsets[i + 1]; ++k)
      mean += rows.entries[k].forward * linear[rows.first + rows.entries[k].particle];
    const Vec3 relative = linear[rows.first + i] - mean;
    for (std::size_t a = 0; a < rows.axis_count; ++a)
      out[i * rows.axis_count + a] = relative[rows.axes[a]];
  }
};

// Particle i's velocity change from its own rows' impulses and minus w_ji times each
// neighbour's, gathered in its list's order. With the number of axes N known, each axis's sum
// is a local of its own, not a component of a vector picked at run time: no store to a variable
// place in every entry's update.
template <std::size_t N>
struct ViscosityImpulses {
  ViscosityRows rows;
  const Real* gamma;
  Vec3* linear;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    Real p[N];
    for (std::size_t a = 0; a < N; ++a) p[a] = gamma[i * N + a];
    for (std::size_t k = rows.offsets[i]; k < rows.offsets[i + 1]; ++k) {
      const ViscosityEntry& e = rows.entries[k];
      const Real* g = &gamma[e.particle * N];
      for (std::size_t a = 0; a < N; ++a) p[a] -= e.backward * g[a];
    }
    Vec3 impulse = Vec3::Zero();
    for (std::size_t a = 0; a < N; ++a) impulse[rows.axes[a]] = p[a];
    linear[rows.first + i] += rows.inverse_mass * impulse;
  }
};

// Particle i's rows' inverse effective mass plus their compliance.
struct ViscosityDiagonal {
  ViscosityRows rows;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    Real d = 1;
    for (std::size_t k = rows.offsets[i]; k < rows.offsets[i + 1]; ++k)
      d += rows.entries[k].forward * rows.entries[k].forward;
    for (std::size_t a = 0; a < rows.axis_count; ++a)
      out[i * rows.axis_count + a] = rows.inverse_mass * d + rows.compliance;
  }
};

}  // namespace sluice
