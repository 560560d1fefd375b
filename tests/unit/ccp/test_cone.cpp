// The friction cone's projection and the contact frame (ccp/cone.hpp).
#include "sluice/ccp/cone.hpp"

#include <gtest/gtest.h>

namespace sluice {
namespace {

TEST(Cone, InsideIsKeptAndThePolarConeGoesToTheApex) {
  Real n = 2, u = 0.3, v = -0.4;  // |t| = 0.5 <= 0.5 * 2
  project_on_cone(n, u, v, 0.5, 0);
  EXPECT_EQ(n, 2);
  EXPECT_EQ(u, 0.3);
  n = -1, u = 0.1, v = 0;  // 0.5 * 0.1 <= 1: polar
  project_on_cone(n, u, v, 0.5, 0);
  EXPECT_EQ(n, 0);
  EXPECT_EQ(u, 0);
}

TEST(Cone, OutsideLandsOnTheSurfaceAlongItsNormal) {
  const Real mu = 0.6;
  const Vec3 x(1.0, 2.0, -1.0);
  Real n = x[0], u = x[1], v = x[2];
  project_on_cone(n, u, v, mu, 0);
  const Vec3 p(n, u, v);
  EXPECT_NEAR(std::hypot(u, v), mu * n, 1e-14);  // on the surface
  EXPECT_NEAR((x - p).dot(p), 0, 1e-14);         // the step is normal to it
  // Idempotent.
  project_on_cone(n, u, v, mu, 0);
  EXPECT_NEAR((Vec3(n, u, v) - p).norm(), 0, 1e-15);
}

TEST(Cone, FrictionlessAndCohesive) {
  Real n = -0.2, u = 1, v = 1;
  project_on_cone(n, u, v, 0, 0);
  EXPECT_EQ(n, 0);
  EXPECT_EQ(u, 0);
  n = -0.2, u = 0, v = 0;
  project_on_cone(n, u, v, 0, 0.5);  // a cohesion of 0.5 lets it pull with 0.2
  EXPECT_EQ(n, -0.2);
  n = -0.7;
  project_on_cone(n, u, v, 0.3, 0.5);
  EXPECT_EQ(n, -0.5);
}

TEST(Cone, TangentsCompleteARightHandedFrame) {
  for (const Vec3& n :
       {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.6, 0.8, 0), Vec3(1, 2, 3).normalized()}) {
    Vec3 u, v;
    tangent_basis(n, u, v);
    EXPECT_NEAR(u.norm(), 1, 1e-15);
    EXPECT_NEAR(v.norm(), 1, 1e-15);
    EXPECT_NEAR(u.dot(n), 0, 1e-15);
    EXPECT_NEAR(v.dot(n), 0, 1e-15);
    EXPECT_NEAR(n.cross(u).dot(v), 1, 1e-15);
  }
}

}  // namespace
}  // namespace sluice
