// The coupler's explicit co-simulation: the bodies advance with the fluid's last load held,
// the fluid then receives their motion, and the loads it returns are held for the next step.
#include "sluice/coupling/coupler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sluice/contact/contact_body_builder.hpp"

namespace sluice {
namespace {

// A fluid that pushes every body up with a fixed force and remembers what it was told.
class ConstantPush final : public FluidExchange {
 public:
  explicit ConstantPush(Vec3 force) : force_(force) {}
  void receive_body_motion(const std::vector<BodyKinematics>& motion) override {
    received = motion;
    ++exchanges;
  }
  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override {
    return std::vector<Wrench>(motion.size(), Wrench{force_, Vec3::Zero()});
  }
  std::vector<BodyKinematics> received;
  int exchanges = 0;

 private:
  Vec3 force_;
};

MultibodySystem one_free_block(double mass) {
  MultibodySystem system(0.01, Vec3(0, 0, -10));
  ContactBody block;
  block.state.mass = mass;
  block.state.position = Vec3(0, 0, 1);
  system.add(std::move(block));
  return system;
}

TEST(Coupler, HoldsTheLastLoadAndHandsOverTheMotion) {
  MultibodySystem system = one_free_block(2.0);
  ConstantPush fluid(Vec3(0, 0, 5));  // a quarter of the weight
  Coupler coupler(system, 1, &fluid, true);
  // First step: no load collected yet, so the block falls freely.
  coupler.advance_bodies(0.1);
  EXPECT_EQ(fluid.exchanges, 1);
  EXPECT_NEAR(fluid.received[0].velocity[2], -1.0, 1e-12);
  EXPECT_NEAR(fluid.received[0].acceleration[2], -10.0, 1e-12);
  // Then the push is held: the block accelerates at -10 + 5 / 2.
  coupler.collect_loads();
  EXPECT_EQ(coupler.fluid_force()[0], Vec3(0, 0, 5));
  coupler.advance_bodies(0.1);
  EXPECT_NEAR(fluid.received[0].acceleration[2], -7.5, 1e-12);
  EXPECT_NEAR(coupler.motion()[0].position[2], 1 - 0.05 - 0.1 - 0.0375, 1e-12);
  EXPECT_EQ(coupler.most_substeps(), 1);
}

// A fluid that holds the bodies on springs of `stiffness`: it records each exchange's length.
class SpringHeld final : public FluidExchange {
 public:
  explicit SpringHeld(double stiffness) : stiffness_(stiffness) {}
  void receive_body_motion(const std::vector<BodyKinematics>&) override {}
  void advance_with_bodies(double dt) override { pieces.push_back(dt); }
  double boundary_stiffness() const override { return stiffness_; }
  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override {
    return std::vector<Wrench>(motion.size());
  }
  std::vector<double> pieces;

 private:
  double stiffness_;
};

TEST(Coupler, SpringsSplitTheStepForTheLightestBody) {
  // omega = sqrt(5e4 / 1.5e-3) = 5774 rad/s: a step of 0.01 s in pieces of omega h <= 0.25.
  MultibodySystem system = one_free_block(1.5e-3);
  SpringHeld fluid(5e4);
  Coupler coupler(system, 1, &fluid, true, "spring-exchanges");
  const int expected = static_cast<int>(std::ceil(0.01 * std::sqrt(5e4 / 1.5e-3) / 0.25));
  EXPECT_EQ(coupler.exchanges(0.01), expected);
  EXPECT_EQ(expected, 231);
  coupler.advance_bodies(0.01);
  ASSERT_EQ(fluid.pieces.size(), std::size_t(expected));
  double sum = 0;
  for (const double h : fluid.pieces) sum += h;
  EXPECT_NEAR(sum, 0.01, 1e-15);
  EXPECT_EQ(coupler.most_exchanges(), expected);
  // The block fell through all the pieces, as in one step.
  EXPECT_NEAR(coupler.motion()[0].velocity[2], -0.1, 1e-12);
}

// Held loads, the co-simulation of a fluid without springs, take the step in one exchange.
TEST(Coupler, HeldLoadsTakeTheStepInOneExchange) {
  MultibodySystem system = one_free_block(1.5e-3);
  SpringHeld fluid(0);
  Coupler coupler(system, 1, &fluid, true);
  EXPECT_STREQ(coupler.scheme().name(), "held-loads");
  coupler.advance_bodies(0.01);
  EXPECT_EQ(fluid.pieces, std::vector<double>{0.01});
  EXPECT_EQ(coupler.most_exchanges(), 1);
}

// The step's stages as each scheme orders them around the fluid's own.
TEST(CouplingScheme, OrdersTheStepAroundTheFluidsStages) {
  auto names = [](const StageList& stages) {
    std::vector<std::string> out;
    for (const auto& s : stages) out.emplace_back(s->name());
    return out;
  };
  auto fluid_stage = [](const char* name) {
    StageList list;
    list.push_back(make_stage<const StepClock>(name, [](const StepClock&) {}));
    return list;
  };
  MultibodySystem system = one_free_block(1.0);
  ConstantPush fluid(Vec3(0, 0, 1));
  for (const std::string scheme : {"held-loads", "spring-exchanges", "monolithic"}) {
    Coupler coupler(system, 1, &fluid, true, scheme);
    EXPECT_EQ(names(coupler.assemble_step(fluid_stage("move"), fluid_stage("forces"), true, true)),
              (std::vector<std::string>{"move", "bodies", "forces", "body_loads"}))
        << scheme;
    // The loads were taken once already, for the first step.
    EXPECT_EQ(coupler.fluid_force()[0], Vec3(0, 0, 1)) << scheme;
    // Without bodies, only the monolithic scheme keeps the bodies' solve (a granular fluid's).
    const std::vector<std::string> alone =
        names(coupler.assemble_step(fluid_stage("move"), fluid_stage("forces"), false, true));
    const std::vector<std::string> with_solve = {"move", "bodies", "forces"};
    const std::vector<std::string> without = {"move", "forces"};
    EXPECT_EQ(alone, scheme == "monolithic" ? with_solve : without) << scheme;
  }
  EXPECT_THROW(make_coupling_scheme("implicit"), std::invalid_argument);
}

TEST(Coupler, NoSpringsOrNoFreeBodyMeansOneExchange) {
  MultibodySystem system = one_free_block(1.5e-3);
  SpringHeld soft(0);
  EXPECT_EQ(Coupler(system, 1, &soft, true).exchanges(0.01), 1);
  system.bodies()[0].fixed = true;
  SpringHeld stiff(5e4);
  EXPECT_EQ(Coupler(system, 1, &stiff, true).exchanges(0.01), 1);
}

TEST(Coupler, WithoutSubCyclingTheFluidTakesTheSolidStep) {
  // A ball resting on a floor: its contact needs steps far below a millisecond.
  MultibodySystem system(0.01, Vec3(0, 0, -10));
  const double radius = 0.05;
  ContactBody ball =
      make_contact_body(sample_sphere_body(radius, 0.01, 0, 3),
                        sphere_mass_properties(radius, 1000.0), ContactMaterial{}, radius, false);
  ball.spherical = true;
  ball.state.position = Vec3(0, 0, radius);
  system.add(std::move(ball));
  system.add(make_floor_patch(0.2, 0.01, ContactMaterial{}));
  ConstantPush fluid(Vec3::Zero());
  Coupler cycled(system, 1, &fluid, true), lockstep(system, 1, &fluid, false);
  const TimeStep fluid_step{1e-3, "the fluid"};
  EXPECT_EQ(cycled.time_step(fluid_step).dt, 1e-3);
  EXPECT_STREQ(cycled.time_step(fluid_step).limit, "the fluid");
  EXPECT_LT(lockstep.time_step(fluid_step).dt, 0.5e-3);
  EXPECT_EQ(lockstep.time_step(fluid_step).dt, system.solid_step(1e-3));
  EXPECT_STREQ(lockstep.time_step(fluid_step).limit,
               "a contact's period (contact.subcycling is off)");
}

// The monolithic scheme: a fluid whose surface at z = 0.5 bodies cannot sink through adds a
// unilateral row for each body whose bottom reaches it to every velocity-level solve, which the
// bodies' solver meets at every sub-step together with gravity.
class HardSurface final : public FluidExchange {
 public:
  void add_to_problem(CcpProblem& problem, double) override {
    rows.clear();
    for (std::size_t b = 0; b < motion_.size(); ++b) {
      if (motion_[b].position[2] - 0.05 > 0.5) continue;  // its bottom is above the surface
      ConstraintRow r;
      r.a = b;
      r.linear_a = Vec3::UnitZ();
      r.lower = 0;
      rows.add_row(r);
    }
    problem.add(rows);
  }
  void receive_body_motion(const std::vector<BodyKinematics>& motion) override { motion_ = motion; }
  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override {
    return std::vector<Wrench>(motion.size());
  }
  RowGroup rows;

 private:
  std::vector<BodyKinematics> motion_;
};

TEST(Coupler, MonolithicRowsHoldABodyOnTheSurface) {
  MultibodySystem system = one_free_block(2.0);  // at z = 1, g = 10
  HardSurface fluid;
  Coupler coupler(system, 1, &fluid, true, "monolithic");
  const double dt = 1e-3;
  double lowest = 1;
  for (int step = 0; step < 1000; ++step) {
    coupler.advance_bodies(dt);
    lowest = std::min(lowest, coupler.motion()[0].position[2]);
  }
  // It fell 0.45 m in 0.3 s and then rests. The rows come from the motion at a step's start,
  // so it sinks in by up to one step's fall (3 mm), and no further.
  const double v_impact = std::sqrt(2 * 10 * 0.45);
  EXPECT_GT(lowest, 0.55 - 1.01 * v_impact * dt);
  EXPECT_NEAR(coupler.motion()[0].position[2], lowest, 1e-9);
  // Its velocity at the step's end is the second half kick's, - g dt / 2.
  EXPECT_NEAR(coupler.motion()[0].velocity[2], -0.5 * 10 * dt, 1e-9);
  ASSERT_EQ(fluid.rows.size(), 1u);
  // Resting: the row's impulse per step carries the weight.
  EXPECT_NEAR(fluid.rows.rows()[0].impulse / dt, 2.0 * 10, 1e-6);
}

}  // namespace
}  // namespace sluice
