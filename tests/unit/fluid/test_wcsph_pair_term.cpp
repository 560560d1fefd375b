// The WCSPH pair term conserves momentum: what j adds to m_i a_i is minus what i adds to
// m_j a_j, for pressure, artificial and laminar viscosity together; a particle adds nothing
// to itself. The fluid's force on a body particle uses this very term (wcsph_model.hpp).
#include "sluice/fluid/wcsph/wcsph_pair_term.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {
namespace {

TEST(WcsphPairTerm, EqualAndOppositeAndNothingOnItself) {
  const double dx = 0.01;
  const WendlandC2<3> kernel(1.5 * dx);
  WcsphPairConstants k;
  k.eta2 = static_cast<float>(0.01 * kernel.h * kernel.h);
  k.two_alpha_c0_h = static_cast<float>(2 * 0.1 * 20 * kernel.h);
  k.diffusion = static_cast<float>(-2 * 0.1 * kernel.h * 20);
  k.hydrostatic = {0, 0, static_cast<float>(1000 / 400.0 * 9.81)};
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    PackedParticles packed;
    packed.resize(2, 2);
    double mass[2], laminar[2];
    for (int i = 0; i < 2; ++i) {
      const double rho = 1000 * (1 + 0.02 * unit(random));
      const double pressure = 2000 * (1 + unit(random));
      mass[i] = 1000 * dx * dx * dx;
      for (int a = 0; a < 3; ++a) {
        packed.position[a][i] = static_cast<float>(1.2 * dx * unit(random));
        packed.velocity[a][i] = packed.viscous_velocity[a][i] = static_cast<float>(unit(random));
      }
      packed.density[i] = static_cast<float>(rho);
      packed.pressure[i] = static_cast<float>(pressure);
      packed.pressure_term[i] = static_cast<float>(pressure / (rho * rho));
      packed.volume[i] = static_cast<float>(mass[i] / rho);
      packed.fluid[i] = packed.viscous_weight[i] = 1;
      laminar[i] = 2 * 1e-3 * 1000 / rho;  // a viscous fluid: 2 nu rho0 / rho_i
    }
    const auto view = packed.view();
    float a[2][3] = {}, drho[2] = {};
    for (int i = 0; i < 2; ++i) {
      const auto own = own_particle(view, i, static_cast<float>(laminar[i]));
      add_wcsph_pair_term(view, own, 1 - i, k, kernel, a[i][0], a[i][1], a[i][2], drho[i]);
      float self[3] = {}, self_drho = 0;
      add_wcsph_pair_term(view, own, i, k, kernel, self[0], self[1], self[2], self_drho);
      EXPECT_EQ(self[0], 0.0f);
      EXPECT_EQ(self[1], 0.0f);
      EXPECT_EQ(self[2], 0.0f);
      EXPECT_EQ(self_drho, 0.0f);
    }
    for (int c = 0; c < 3; ++c) {
      const double f01 = mass[0] * a[0][c], f10 = mass[1] * a[1][c];
      const double scale = std::max(std::abs(f01), 1e-30);
      worst = std::max(worst, std::abs(f01 + f10) / scale);
    }
  }
  std::printf("WCSPH pair term: m_i a_ij + m_j a_ji within %.2g of m_i a_ij\n", worst);
  EXPECT_LT(worst, 2e-5);  // single precision, terms of both signs
}

}  // namespace
}  // namespace sluice
