// A floating box's heave in regular waves by linear theory (waves/floating_response): its limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sluice/waves/floating_response.hpp"
#include "sluice/waves/linear_waves.hpp"

namespace sluice::waves {
namespace {

constexpr double kG = 9.81;

TEST(BoxHeaveResponse, AShortBoxOnTheSurfaceRidesTheWave) {
  for (double kh : {0.1, 1.0, 3.0}) {
    const double depth = 0.5, k = kh / depth;
    EXPECT_NEAR(box_heave_response(k, angular_frequency(k, depth, kG), depth, kG, 1e-9, 0), 1.0,
                1e-12);
  }
}

TEST(BoxHeaveResponse, ABoxAWavelengthLongFeelsNoNetForce) {
  const double depth = 0.5, k = 2.0;
  EXPECT_NEAR(box_heave_response(k, angular_frequency(k, depth, kG), depth, kG,
                                 2 * std::numbers::pi / k, 0.1),
              0.0, 1e-12);
}

TEST(BoxHeaveResponse, DeepWaterBoxOfNoBeamFollowsItsPressureAgainstItsInertia) {
  // The pressure's factor exp(-k d) over 1 - omega^2 d / g, which is 1 - k d in deep water.
  const double depth = 50, k = 4.0, draft = 0.1;
  const double omega = angular_frequency(k, depth, kG);
  EXPECT_NEAR(box_heave_response(k, omega, depth, kG, 1e-9, draft),
              std::exp(-k * draft) / (1 - k * draft), 1e-9);
}

TEST(BoxHeaveResponse, AddedMassMovesItAtSecondOrder) {
  // omega^2 d / g = 0.01: an added mass as deep as the draft moves the response by about 1e-4.
  const double depth = 0.5, draft = 0.01, omega = std::sqrt(kG);
  const double k = wavenumber(omega, depth, kG);
  const double without = box_heave_response(k, omega, depth, kG, 0.2, draft);
  const double with = box_heave_response(k, omega, depth, kG, 0.2, draft, draft);
  EXPECT_GT(with, without);
  EXPECT_NEAR(with / without - 1, 1e-4, 5e-6);
}

}  // namespace
}  // namespace sluice::waves
