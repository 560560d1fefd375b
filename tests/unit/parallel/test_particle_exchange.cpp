#include "sluice/parallel/particle_exchange.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sluice/parallel/communicator.hpp"

namespace sluice {
namespace {

// A process alone: everything it holds is its own, and the exchange leaves it as it was (the
// runs on several ranks are tests/mpi's).
TEST(ParticleExchange, OneRankKeepsEveryParticleAndTakesNoGhost) {
  ParticleSet<2> ps;
  const auto owned = ps.add_int_field({"owned_kind", "1", false});
  for (int i = 0; i < 6; ++i)
    ps.add(Vec<2>(0.1 * i, 0.0), Vec<2>::Zero(), 1000, 1, static_cast<ParticleKind>(i % 3));
  ParticleExchange<2> exchange(Communicator::alone(), Decomposition(), 0.3, owned);
  exchange.start(ps);
  ASSERT_EQ(ps.size(), 6u);
  for (std::size_t i = 0; i < ps.size(); ++i)
    EXPECT_EQ(ps[owned][i], static_cast<std::int32_t>(ps.kind[i]));
  ps.position[2] = Vec<2>(5.0, 0.0);  // far away: still this rank's, the only one
  exchange.exchange(ps);
  EXPECT_EQ(ps.size(), 6u);
  EXPECT_EQ(exchange.last().sent, 0u);
  EXPECT_EQ(exchange.last().received, 0u);
  EXPECT_EQ(exchange.last().ghosts, 0u);
  EXPECT_EQ(exchange.gone(), std::vector<bool>(6, false));
  EXPECT_EQ(ps.position[2][0], 5.0);
}

// A periodic axis on one rank: particles within the halo's depth of a side come back, shifted
// by the span, beyond the other as ghosts (every field copied, the position shifted); a
// particle that left through a side comes in through the other, a body's excepted;
// refresh() brings the ghosts' fields up to date, their positions shifted again.
TEST(ParticleExchange, APeriodicAxisWrapsFluidAndCopiesEachSideBeyondTheOther) {
  ParticleSet<2> ps;
  const auto owned = ps.add_int_field({"owned_kind", "1", false});
  const auto tag = ps.add_scalar_field({"tag", "1"});
  // Along x in [0, 1): near the lower side, the middle, near the upper side; then a wall
  // particle near the lower side.
  for (const double x : {0.05, 0.5, 0.95}) {
    ps.add(Vec<2>(x, 0.2), Vec<2>::Zero(), 1000, 1, ParticleKind::kFluid);
    ps[tag].back() = x;
  }
  ps.add(Vec<2>(0.15, -0.1), Vec<2>::Zero(), 1000, 1, ParticleKind::kWall);
  ps[tag].back() = -1;
  ps.add(Vec<2>(0.5, 0.6), Vec<2>::Zero(), 1000, 1, ParticleKind::kBody);
  ps[tag].back() = -2;
  ParticleExchange<2> exchange(Communicator::alone(), Decomposition(), 0.2, owned);
  exchange.join_sides(PeriodicSpan{0, 0.0, 1.0});
  exchange.start(ps);
  // The two fluid particles near a side and the wall particle, each imaged once.
  ASSERT_EQ(ps.size(), 8u);
  EXPECT_EQ(exchange.last().ghosts, 3u);
  const auto ghost_at = [&](double x) {
    for (std::size_t i = 5; i < ps.size(); ++i) {
      if (std::abs(ps.position[i][0] - x) < 1e-12) return static_cast<int>(i);
    }
    return -1;
  };
  const int upper_image = ghost_at(1.05), lower_image = ghost_at(-0.05),
            wall_image = ghost_at(1.15);
  ASSERT_GE(upper_image, 0);
  ASSERT_GE(lower_image, 0);
  ASSERT_GE(wall_image, 0);
  EXPECT_EQ(ps[tag][static_cast<std::size_t>(upper_image)], 0.05);
  EXPECT_EQ(ps[owned][static_cast<std::size_t>(upper_image)], -1);
  EXPECT_EQ(ps.kind[static_cast<std::size_t>(wall_image)], ParticleKind::kWall);
  EXPECT_EQ(ps.position[static_cast<std::size_t>(wall_image)][1], -0.1);

  // The owners change; refresh() copies their tags and positions, shifted.
  ps[tag][0] = 7;
  ps.position[0][0] = 0.07;
  exchange.refresh(ps[tag], ps.position);
  EXPECT_EQ(ps[tag][static_cast<std::size_t>(upper_image)], 7);
  EXPECT_NEAR(ps.position[static_cast<std::size_t>(upper_image)][0], 1.07, 1e-12);
  EXPECT_NEAR(ps.position[static_cast<std::size_t>(lower_image)][0], -0.05, 1e-12);

  // The particle near the upper side moves past it, the wall particle (an open boundary's
  // buffer particle, say) past the lower one, and the body's particle past the upper one: the
  // first two wrap round; a body's particle stays where its body puts it.
  ps.position[2][0] = 1.02;
  ps.position[3][0] = -0.01;
  ps.position[4][0] = 1.01;
  exchange.exchange(ps);
  EXPECT_NEAR(ps.position[2][0], 0.02, 1e-12);
  EXPECT_NEAR(ps.position[3][0], 0.99, 1e-12);
  EXPECT_EQ(ps.position[4][0], 1.01);
  for (std::size_t i = 5; i < 8; ++i) EXPECT_TRUE(exchange.gone()[i]);  // last exchange's ghosts
}

TEST(Communicator, AProcessAloneIsItsOwnAnswer) {
  const Communicator alone = Communicator::alone();
  EXPECT_EQ(alone.rank(), 0);
  EXPECT_EQ(alone.size(), 1);
  EXPECT_FALSE(alone.split());
  EXPECT_EQ(alone.min(2.5), 2.5);
  EXPECT_EQ(alone.max(2.5), 2.5);
  EXPECT_EQ(alone.sum(2.5), 2.5);
  EXPECT_EQ(alone.first_rank_where(true), 0);
  EXPECT_EQ(alone.first_rank_where(false), -1);
  EXPECT_EQ(alone.broadcast("text", 0), "text");
  const std::vector<std::vector<unsigned char>> out{{1, 2, 3}};
  EXPECT_EQ(alone.exchange(out), out);
  const std::vector<double> values{1.0, 2.0};
  EXPECT_EQ(alone.gather_all(values), values);
  EXPECT_THROW(alone.exchange({{1}, {2}}), std::logic_error);
}

}  // namespace
}  // namespace sluice
