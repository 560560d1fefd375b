// The case's solid layers (`model.solids`, seed 002's concrete and granular beds) among the
// particles: a fixed layer becomes wall particles on a lattice of its own spacing; a free
// layer's grains are already there, as the case's bodies (free_solid_grains).
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <utility>
#include <vector>

#include "sluice/core/errors.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

// The bodies of a layer's grains, [first, end) in the case's bodies (empty for a fixed layer).
using GrainBodies = std::pair<std::size_t, std::size_t>;

// Adds each fixed layer's particles to `ps` as walls, their spacing in `solid_spacing`; a fluid
// block that overlaps a layer is an input error. Returns each layer's grain bodies: the free
// layers' grains come after the case's own bodies, in layer order.
template <int D>
std::vector<GrainBodies> add_solid_layers(const std::vector<SolidLayerConfig>& layers,
                                          const io::CaseConfig& config, ParticleSet<D>& ps,
                                          FieldHandle<Real> solid_spacing) {
  std::vector<GrainBodies> grain_bodies;
  std::size_t grains = 0;
  for (const SolidLayerConfig& layer : layers) {
    if (layer.free) grains += solid_layer_points<D>(layer, config).size();
  }
  std::size_t next_grain = config.bodies.size() - grains;
  for (const SolidLayerConfig& layer : layers) {
    const Real spacing = layer.spacing_ratio * config.spacing;
    const std::vector<Vec<D>> points = solid_layer_points<D>(layer, config);
    grain_bodies.emplace_back(next_grain, layer.free ? next_grain + points.size() : next_grain);
    next_grain = grain_bodies.back().second;
    for (const auto& block : config.fluid.blocks) {
      if (block.box.overlaps(layer.box, 0)) {
        throw InputError(config.file(), layer.line, layer.key,
                         fmt::format("the solid layer overlaps the fluid block '{}'", block.name));
      }
    }
    if (layer.free) continue;
    const Real mass = layer.density * std::pow(spacing, D);
    for (const Vec<D>& x : points) {
      ps.add(x, Vec<D>::Zero(), layer.density, mass, ParticleKind::kWall);
      ps[solid_spacing].back() = spacing;
    }
  }
  return grain_bodies;
}

}  // namespace sluice
