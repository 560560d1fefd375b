// Seed 002's measure of how well a solid layer holds the fluid back: the share of the fluid
// particles that started above a layer and never passed it (the run's `held_back_fraction`).
// A particle has passed a layer once it is below the layer's pass level: a fixed layer's
// bottom, or the lowest centre of a free layer's grains as they lie now (a bed on the floor has
// no bottom to pass: what gets between its grains' centres went through its pores).
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "sluice/coupling/body_points.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"
#include "sluice/fluid/penalty_sph/solid_layers.hpp"
#include "sluice/parallel/communicator.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

template <int D>
class LayerPassage {
 public:
  // Its two fields: which layers a particle started above (a bit each), and whether it passed
  // one of them (written to frames).
  void add_fields(ParticleSet<D>& ps) {
    layers_above_ = ps.add_int_field({"layers_above", "1"});
    passed_ = ps.add_int_field({"passed_solid", "1", true});
  }

  // Marks the fluid particles that start above each layer's top.
  void start(ParticleSet<D>& ps, const std::vector<SolidLayerConfig>& layers,
             std::vector<GrainBodies> grain_bodies) {
    layers_ = &layers;
    grain_bodies_ = std::move(grain_bodies);
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!ps.is_fluid(i)) continue;
      const Real up = ps.position[i][kUpAxis<D>];
      for (std::size_t k = 0; k < layers.size(); ++k) {
        if (up > layers[k].box.max[2]) ps[layers_above_][i] |= 1 << k;
      }
      if (ps[layers_above_][i] != 0) ++above_count_;
    }
  }

  // The layers' pass levels as their grains (body particles of `points`) lie now, over every
  // rank's.
  void update_levels(const ParticleSet<D>& ps, const BodyPoints& points,
                     const Communicator& ranks) {
    const std::vector<SolidLayerConfig>& layers = *layers_;
    pass_level_.resize(layers.size());
    for (std::size_t k = 0; k < layers.size(); ++k) {
      pass_level_[k] =
          layers[k].free ? std::numeric_limits<Real>::infinity() : Real(layers[k].box.min[2]);
    }
    if (points.size() == 0) return;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::int32_t point = ps.body_point[i];
      if (point < 0) continue;
      const std::size_t body = points[std::size_t(point)].body;
      for (std::size_t k = 0; k < grain_bodies_.size(); ++k) {
        if (body >= grain_bodies_[k].first && body < grain_bodies_[k].second) {
          pass_level_[k] = std::min(pass_level_[k], ps.position[i][kUpAxis<D>]);
        }
      }
    }
    for (Real& level : pass_level_) level = static_cast<Real>(ranks.min(level));
  }

  // Marks fluid particle i where it is below the level of a layer it started above.
  void record(ParticleSet<D>& ps, std::size_t i) const {
    for (std::size_t k = 0; k < pass_level_.size(); ++k) {
      const bool started_above = ps[layers_above_][i] & (1 << k);
      if (started_above && ps.position[i][kUpAxis<D>] < pass_level_[k]) ps[passed_][i] = 1;
    }
  }

  // Whether any fluid particle started above a layer (else there is no fraction to give).
  bool measured() const { return above_count_ > 0; }

  // Over the fluid particles that `kinds` counts (a ghost's -1), on every rank.
  double held_back_fraction(const ParticleSet<D>& ps, const std::int32_t* kinds,
                            const Communicator& ranks) const {
    double passed = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) passed += kinds[i] == 0 ? ps[passed_][i] : 0;
    return 1.0 - ranks.sum(passed) / static_cast<double>(above_count_);
  }

 private:
  const std::vector<SolidLayerConfig>* layers_ = nullptr;  // the model's parameters'
  std::vector<GrainBodies> grain_bodies_;                  // per layer
  std::vector<Real> pass_level_;                           // per layer [m]
  FieldHandle<std::int32_t> layers_above_, passed_;
  long above_count_ = 0;
};

}  // namespace sluice
