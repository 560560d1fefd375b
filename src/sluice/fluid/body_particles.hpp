// A case of bodies alone: no fluid, and the bodies drawn as their surface particles (the
// particle base with no model stages), so that frames show them as they move.
#pragma once

#include <limits>

#include "sluice/fluid/particle_fluid.hpp"

namespace sluice {

template <int D>
class BodyParticles final : public ParticleFluid<D> {
 public:
  BodyParticles(const io::CaseConfig& config, const BodyGeometry& bodies)
      : ParticleFluid<D>(config, 2 * config.spacing, bodies) {}

  void initialize() override {}
  std::string describe() const override { return "no fluid"; }
  // No stages: not even the neighbour sort.
  void append_stages(StageList&, StageList&) override {}
  TimeStep next_time_step() const override { return {}; }

 protected:
  void model_stages(StageList&, StageList&) override {}
  void archive_model(StateArchive&) override {}  // the particles follow the bodies
  void body_point_forces(const std::vector<BodyKinematics>&, std::vector<Vec3>&) const override {}
};

}  // namespace sluice
