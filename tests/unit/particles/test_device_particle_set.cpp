// The device's copy of a particle set over the host backend (the emulated device): it mirrors
// whatever fields the host's set has, reorders them all, and remembers what it is asked to.
#include "sluice/particles/device_particle_set.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>
#include <vector>

#include "sluice/exec/host_backend.hpp"

namespace sluice {
namespace {

using EmulatedSet = DeviceParticleSet<2, exec::HostBackend>;

// Five particles, each field's values telling particles apart; a model's field of each type.
ParticleSet<2> numbered_set() {
  ParticleSet<2> ps;
  const auto n = ps.add_int_field({"n", "1", true});
  const auto s = ps.add_scalar_field({"s", "Pa"});
  const auto v = ps.add_vector_field({"v", "m/s", true});
  for (int i = 0; i < 5; ++i) {
    ps.add(Vec<2>(i, 10 + i), Vec<2>(20 + i, 30 + i), 40 + i, 50 + i,
           i % 2 ? ParticleKind::kWall : ParticleKind::kFluid);
    ps.pressure.back() = 60 + i;
    ps.body_point.back() = i - 1;
    ps[n].back() = 70 + i;
    ps[s].back() = 80 + i;
    ps[v].back() = Vec<2>(90 + i, 100 + i);
  }
  return ps;
}

TEST(DeviceParticleSet, ComesBackAsItWent) {
  const ParticleSet<2> host = numbered_set();
  EmulatedSet device;
  device.upload(host);
  ASSERT_EQ(device.size(), 5u);
  ParticleSet<2> back = host;
  for (auto& x : back.position) x.setZero();
  device.download(back);
  EXPECT_EQ(back.position, host.position);
  EXPECT_EQ(back.velocity, host.velocity);
  EXPECT_EQ(back.kind, host.kind);
  EXPECT_EQ(device.components<Real>("v")[2 * 3 + 1], 103);
  EXPECT_EQ(device.components<std::int32_t>("n")[4], 74);
  EXPECT_THROW(device.components<Real>("n"), std::logic_error);
}

TEST(DeviceParticleSet, GatherReordersEveryFieldAsTheHostsReorderDoes) {
  ParticleSet<2> host = numbered_set();
  EmulatedSet device;
  device.upload(host);
  const std::vector<std::uint32_t> order{3, 0, 4, 1, 2};
  device.gather(order.data());
  host.reorder(order);
  ParticleSet<2> back = numbered_set();
  device.download(back);
  std::vector<double> expected, got;
  auto numbers = [](const ParticleSet<2>& ps, std::vector<double>& out) {
    ps.for_each_field([&](const FieldLabel&, const auto& values) {
      for (const auto& x : values) {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, Vec<2>>) {
          out.insert(out.end(), {x[0], x[1]});
        } else {
          out.push_back(static_cast<double>(x));
        }
      }
    });
  };
  numbers(host, expected);
  numbers(back, got);
  EXPECT_EQ(got, expected);
}

TEST(DeviceParticleSet, RemembersTheFieldsItIsAskedToKeep) {
  const ParticleSet<2> host = numbered_set();
  EmulatedSet device;
  device.upload(host);
  device.remember(shown_in_frames);
  device.components<Real>("position")[0] = -1;  // a step after the good state
  device.components<Real>("v")[0] = -1;
  device.components<Real>("s")[0] = -1;
  ParticleSet<2> good = host;
  good.components<Real>("s")[0] = 7;  // not kept: the host's own value stays
  device.download_remembered(good);
  EXPECT_EQ(good.position[0][0], 0);  // kept: positions always, "v" is shown in frames
  EXPECT_EQ(good.components<Real>("v")[0], 90);
  EXPECT_EQ(good.components<Real>("s")[0], 7);
}

TEST(DeviceParticleSet, CountsTheBytesOfItsFields) {
  const ParticleSet<2> host = numbered_set();
  // Fields: position, velocity, v (2 reals each), pressure, density, mass, s (one each):
  // 10 reals; kind, body_point, n: 3 integers. Remembered (shown in frames): position,
  // velocity, pressure, density, v (8 reals), kind, body_point, n. Gather scratch: one
  // array of each width, 2 + 1 reals, and one of integers.
  const double expected = (10 + 8 + 3) * sizeof(Real) + (3 + 3 + 1) * sizeof(std::int32_t);
  EXPECT_EQ(device_bytes_per_particle(host, shown_in_frames), expected);
}

}  // namespace
}  // namespace sluice
