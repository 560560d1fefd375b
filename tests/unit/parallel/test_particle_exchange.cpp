#include "sluice/parallel/particle_exchange.hpp"

#include <gtest/gtest.h>

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
