#include "sluice/rigid/rigid_system.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace sluice {
namespace {

// A linear spring of stiffness k between the centres of bodies 0 and 1 (rest length 0), asking
// for sub-steps of a twentieth of its period.
class Spring final : public BodyInteraction {
 public:
  explicit Spring(double k) : k_(k) {}
  void evaluate(const std::vector<SystemBody>& bodies, double, std::vector<Vec3>& force,
                std::vector<Vec3>&) override {
    const Vec3 stretch = bodies[1].state.position - bodies[0].state.position;
    force[0] += k_ * stretch;
    force[1] -= k_ * stretch;
    energy_ = 0.5 * k_ * stretch.squaredNorm();
    ++evaluations;
  }
  double stable_step(const std::vector<SystemBody>& bodies, double dt) override {
    const double reduced = 1 / (1 / bodies[0].state.mass + 1 / bodies[1].state.mass);
    return std::min(dt, 2 * std::numbers::pi * std::sqrt(reduced / k_) / 20);
  }
  double stored_energy() const override { return energy_; }
  int evaluations = 0;

 private:
  double k_;
  double energy_ = 0;
};

SystemBody free_body(const Vec3& position) {
  SystemBody body;
  body.state.position = position;
  return body;
}

TEST(RigidSystem, FreeFallIsExactInOneStepWithoutInteraction) {
  RigidSystem system(Vec3(0, 0, -9.81));
  system.add(free_body(Vec3::Zero()));
  EXPECT_EQ(system.advance(0.1), 1);
  EXPECT_NEAR(system.bodies()[0].state.position[2], -0.5 * 9.81 * 0.01, 1e-15);
  EXPECT_NEAR(system.bodies()[0].state.velocity[2], -0.981, 1e-15);
}

TEST(RigidSystem, SubCyclesAsTheInteractionAsksAndKeepsItsEnergy) {
  RigidSystem system(Vec3::Zero());
  Spring spring(100.0);  // two unit masses: period 2 pi sqrt(0.5 / 100) = 0.444 s
  system.set_interaction(&spring);
  system.add(free_body(Vec3(-0.05, 0, 0)));
  system.add(free_body(Vec3(0.05, 0, 0)));
  const double start = 0.5 * 100 * 0.01;  // the spring's, at rest
  const int substeps = system.advance(0.1);
  EXPECT_EQ(substeps, static_cast<int>(std::ceil(0.1 / spring.stable_step(system.bodies(), 0.1))));
  EXPECT_EQ(spring.evaluations, substeps + 1);  // once to start, once per sub-step
  double worst = 0;
  for (int k = 0; k < 40; ++k) {
    system.advance(0.1);
    worst = std::max(worst, std::abs(system.energy().total() - start) / start);
  }
  std::printf("spring, 20 sub-steps a period: energy within %.3g %% over 9 periods\n", 100 * worst);
  EXPECT_LT(worst, 0.05);
  // Equal and opposite: the centre of mass stays put.
  EXPECT_NEAR((system.bodies()[0].state.position + system.bodies()[1].state.position).norm(), 0,
              1e-12);
}

TEST(RigidSystem, FixedAndPrescribedBodies) {
  RigidSystem system(Vec3(0, 0, -9.81));
  SystemBody wall = free_body(Vec3(1, 2, 3));
  wall.fixed = true;
  SystemBody paddle = free_body(Vec3::Zero());
  paddle.fixed = true;
  paddle.prescribed = [](double time, RigidBody& state) {
    state.position = Vec3(std::sin(time), 0, 0);
    state.velocity = Vec3(std::cos(time), 0, 0);
  };
  system.add(wall);
  system.add(paddle);
  for (int k = 0; k < 10; ++k) system.advance(0.05);
  EXPECT_EQ(system.bodies()[0].state.position, Vec3(1, 2, 3));
  EXPECT_NEAR(system.bodies()[1].state.position[0], std::sin(0.5), 1e-12);
  EXPECT_EQ(system.energy().kinetic, 0);  // fixed and prescribed bodies carry none
}

// A division that gives this process body 0 only, and after the step brings body 1 to where
// `theirs` says the other process moved it.
class FirstBodyHere final : public BodySharing {
 public:
  std::vector<bool> bodies_here(const std::vector<SystemBody>& bodies, const std::vector<Joint>&,
                                BodyInteraction*, double) override {
    std::vector<bool> here(bodies.size(), false);
    here[0] = true;
    return here;
  }
  void gather(std::vector<SystemBody>& bodies, std::vector<Vec3>&, std::vector<Vec3>&,
              BodyInteraction*) override {
    before_gather = bodies[1].state.position;
    bodies[1].state = theirs;
  }
  RigidBody theirs;
  Vec3 before_gather = Vec3::Constant(-1);
};

TEST(RigidSystem, AdvancesOnlyTheBodiesItsDivisionGivesIt) {
  RigidSystem alone(Vec3(0, 0, -9.81)), shared(Vec3(0, 0, -9.81));
  FirstBodyHere division;
  division.theirs.position = Vec3(7, 8, 9);
  shared.set_sharing(&division);
  for (RigidSystem* system : {&alone, &shared}) {
    system->add(free_body(Vec3::Zero()));
    system->add(free_body(Vec3(1, 0, 0)));
    system->advance(0.1);
  }
  // Body 0 falls as alone; body 1 was left where it stood, then took the gathered state.
  EXPECT_EQ(shared.bodies()[0].state.position, alone.bodies()[0].state.position);
  EXPECT_EQ(shared.bodies()[0].state.velocity, alone.bodies()[0].state.velocity);
  EXPECT_EQ(division.before_gather, Vec3(1, 0, 0));
  EXPECT_EQ(shared.bodies()[1].state.position, Vec3(7, 8, 9));
}

}  // namespace
}  // namespace sluice
