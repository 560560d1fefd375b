#include "sluice/particles/particle_set.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include <string>
#include <type_traits>

namespace sluice {
namespace {

// A number that tells particle i's value in a field apart from every other particle's.
double tag(std::size_t i, int field) {
  return 100.0 * field + static_cast<double>(i);
}

// Three particles of each kind, every field (engine and model, of every type) filled with tags.
ParticleSet<3> tagged_set() {
  ParticleSet<3> ps;
  const auto id = ps.add_int_field({"cluster", "1", true});
  const auto phi = ps.add_scalar_field({"phi", "Pa", false});
  const auto g = ps.add_vector_field({"gradient", "Pa/m", true});
  for (std::size_t i = 0; i < 12; ++i) {
    ps.add(Vec3::Constant(tag(i, 0)), Vec3::Constant(tag(i, 1)), tag(i, 2), tag(i, 3),
           static_cast<ParticleKind>(i % 4));
    ps.pressure.back() = tag(i, 4);
    ps.body_point.back() = static_cast<std::int32_t>(tag(i, 5));
    ps[id].back() = static_cast<std::int32_t>(tag(i, 6));
    ps[phi].back() = tag(i, 7);
    ps[g].back() = Vec3::Constant(tag(i, 8));
  }
  return ps;
}

// The first number a particle carries in a field, whatever its type.
template <class T>
double first_number(const T& value) {
  if constexpr (std::is_arithmetic_v<T>) {
    return static_cast<double>(value);
  } else if constexpr (std::is_enum_v<T>) {
    return static_cast<double>(static_cast<std::int32_t>(value));
  } else {
    return value[0];
  }
}

TEST(ParticleSet, ReorderKeepsEveryField) {
  const ParticleSet<3> before = tagged_set();
  ParticleSet<3> after = before;
  const std::vector<std::uint32_t> order{5, 0, 11, 3, 7, 1, 9, 2, 10, 4, 8, 6};
  after.reorder(order);
  std::vector<std::string> seen;
  std::vector<const void*> original;
  before.for_each_field(
      [&](const FieldLabel&, const auto& values) { original.push_back(&values); });
  std::size_t f = 0;
  after.for_each_field([&](const FieldLabel& label, const auto& values) {
    const auto& old = *static_cast<const std::decay_t<decltype(values)>*>(original[f++]);
    ASSERT_EQ(values.size(), order.size()) << label.name;
    for (std::size_t k = 0; k < order.size(); ++k) {
      EXPECT_EQ(first_number(values[k]), first_number(old[order[k]])) << label.name << " " << k;
    }
    seen.push_back(label.name);
  });
  EXPECT_EQ(seen, (std::vector<std::string>{"position", "velocity", "pressure", "density", "mass",
                                            "kind", "body_point", "cluster", "phi", "gradient"}));
}

TEST(ParticleSet, KeepHoldsThoseNamedInTheirOrderAndLeavesEmptiedFieldsEmpty) {
  const ParticleSet<3> from = tagged_set();
  ParticleSet<3> kept;
  kept.assign_fields(from, [](const FieldLabel& label) { return label.name != "mass"; });
  const std::vector<std::uint32_t> which{7, 2, 11};
  kept.keep(which);
  ASSERT_EQ(kept.size(), which.size());
  for (std::size_t k = 0; k < which.size(); ++k) {
    EXPECT_EQ(kept.position[k], from.position[which[k]]);
    EXPECT_EQ(kept.kind[k], from.kind[which[k]]);
    EXPECT_EQ(kept.body_point[k], from.body_point[which[k]]);
  }
  EXPECT_TRUE(kept.mass.empty());
}

TEST(ParticleSet, NewFieldsStartAtZeroAndNewParticlesToo) {
  ParticleSet<2> ps;
  ps.add(Vec<2>(1, 2), Vec<2>::Zero(), 1000, 1, ParticleKind::kFluid);
  const auto v = ps.add_vector_field({"v", "m/s"});
  const auto n = ps.add_int_field({"n", "1"});
  EXPECT_EQ(ps[v][0], Vec<2>::Zero());
  EXPECT_EQ(ps[n][0], 0);
  ps[v][0] = Vec<2>(3, 4);
  ps.add(Vec<2>(1, 2), Vec<2>::Zero(), 1000, 1, ParticleKind::kDummy);
  EXPECT_EQ(ps[v][1], Vec<2>::Zero());
  EXPECT_FALSE(ps.is_fluid(1));
}

TEST(ParticleSet, AssignFieldsCopiesWhatIsKeptAndEmptiesTheRest) {
  const ParticleSet<3> from = tagged_set();
  ParticleSet<3> to = from;
  to.assign_fields(from, [](const FieldLabel& label) { return label.output; });
  EXPECT_EQ(to.velocity, from.velocity);
  EXPECT_TRUE(to.position.empty());
  EXPECT_TRUE(to.mass.empty());
  to.for_each_field([&](const FieldLabel& label, const auto& values) {
    EXPECT_EQ(values.size(), label.output ? from.size() : 0u) << label.name;
    if (!label.output) {
      EXPECT_EQ(values.capacity(), 0u) << label.name << ": memory not given back";
    }
  });
}

TEST(ParticleSet, AssignFieldsGivesAnEmptySetTheSameFields) {
  const ParticleSet<3> from = tagged_set();
  ParticleSet<3> to;
  to.assign_fields(from, [](const FieldLabel& label) { return label.name != "mass"; });
  std::vector<std::string> names, from_names;
  to.for_each_field([&](const FieldLabel& label, const auto& values) {
    names.push_back(label.name);
    EXPECT_EQ(values.size(), label.name == "mass" ? 0u : from.size()) << label.name;
  });
  from.for_each_field(
      [&](const FieldLabel& label, const auto&) { from_names.push_back(label.name); });
  EXPECT_EQ(names, from_names);
}

TEST(ParticleSet, ComponentsAreTheFieldsValuesByName) {
  ParticleSet<3> ps = tagged_set();
  EXPECT_EQ(ps.components<Real>("velocity"), ps.velocity.front().data());
  EXPECT_EQ(ps.components<Real>("velocity")[3 * 4 + 2], tag(4, 1));  // particle 4's z
  EXPECT_EQ(ps.components<Real>("phi")[7], tag(7, 7));
  EXPECT_EQ(ps.components<std::int32_t>("kind")[6], 2);  // ParticleKind's integer
  EXPECT_EQ(ps.components<std::int32_t>("cluster")[5], static_cast<std::int32_t>(tag(5, 6)));
  EXPECT_THROW(ps.components<Real>("kind"), std::logic_error);
  EXPECT_THROW(ps.components<Real>("no such field"), std::logic_error);
  // Three vectors, four scalars, three integers: 9 + 4 reals, 3 integers.
  EXPECT_EQ(ps.bytes_per_particle(), 13 * sizeof(Real) + 3 * sizeof(std::int32_t));
}

TEST(ParticleSet, PackedParticlesUnpackIntoASetOfTheSameFields) {
  const ParticleSet<3> from = tagged_set();
  ParticleSet<3> to = from;
  const std::vector<std::uint32_t> which{11, 2, 7};
  std::vector<unsigned char> buffer{42};  // packing appends to what the buffer holds
  from.pack(which, buffer);
  ASSERT_EQ(buffer.size(), 1 + which.size() * from.bytes_per_particle());
  to.unpack_append(buffer.data() + 1, which.size());
  ASSERT_EQ(to.size(), from.size() + which.size());
  // The set's own particles are as they were; the appended ones are copies of the packed
  // ones, every field.
  std::vector<const void*> fields_of_from;
  from.for_each_field(
      [&](const FieldLabel&, const auto& values) { fields_of_from.push_back(&values); });
  std::size_t f = 0;
  to.for_each_field([&](const FieldLabel& label, const auto& values) {
    const auto& old = *static_cast<const std::decay_t<decltype(values)>*>(fields_of_from.at(f++));
    for (std::size_t i = 0; i < from.size(); ++i) {
      EXPECT_EQ(first_number(values[i]), first_number(old[i])) << label.name << " " << i;
    }
    for (std::size_t k = 0; k < which.size(); ++k) {
      EXPECT_TRUE(values[from.size() + k] == old[which[k]]) << label.name << " " << k;
    }
  });
  EXPECT_EQ(f, fields_of_from.size());
}

}  // namespace
}  // namespace sluice
