// The state archive: each kind of value read back bit for bit, and a state of another layout
// refused by name.
#include "sluice/core/state_archive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sluice/core/types.hpp"

namespace sluice {
namespace {

struct Pair {
  int id = 0;
  Vec3 normal = Vec3::Zero();
};
void archive_state(StateArchive& a, Pair& p) {
  a(p.id, p.normal);
}

struct Everything {
  double number = 0;
  long count = 0;
  bool flag = false;
  std::string text;
  Vec3 vector = Vec3::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::VectorXd dynamic;
  std::vector<double> numbers;
  std::vector<bool> flags;
  std::vector<Pair> pairs;
  std::array<std::vector<char>, 2> faces;
  std::optional<std::string> failure;
  std::unordered_map<std::uint64_t, std::array<double, 3>> impulses;
  std::map<int, double> table;

  void archive_state(StateArchive& a) {
    a.section("everything");
    a(number, count, flag, text, vector, rotation, dynamic, numbers, flags, pairs, faces, failure,
      impulses, table);
  }
};

Everything filled() {
  Everything e;
  e.number = std::nextafter(0.1, 1.0);  // not a round number: its last bit must survive
  e.count = -7;
  e.flag = true;
  e.text = "kick_drift";
  e.vector = Vec3(1e-300, -0.0, std::numeric_limits<double>::infinity());
  e.rotation = Eigen::Quaterniond(0.5, -0.5, 0.5, 0.5);
  e.dynamic = Eigen::VectorXd::LinSpaced(5, -1, 1);
  e.numbers = {1.0 / 3, 2.0 / 3};
  e.flags = {true, false, true};
  e.pairs = {{3, Vec3::UnitX()}, {9, Vec3::UnitZ()}};
  e.faces = {std::vector<char>{1, 0}, std::vector<char>{0, 0, 1}};
  e.failure = "a message";
  e.impulses = {{42, {1, 2, 3}}, {7, {4, 5, 6}}, {1000, {7, 8, 9}}};
  e.table = {{1, 0.5}, {-2, 0.25}};
  return e;
}

TEST(StateArchive, EveryKindReadsBackBitForBit) {
  Everything original = filled();
  StateArchive out;
  original.archive_state(out);

  Everything copy;
  copy.failure.reset();
  StateArchive in(out.bytes());
  copy.archive_state(in);
  in.finish();
  EXPECT_EQ(std::memcmp(&copy.number, &original.number, sizeof(double)), 0);
  EXPECT_EQ(copy.count, original.count);
  EXPECT_EQ(copy.flag, original.flag);
  EXPECT_EQ(copy.text, original.text);
  EXPECT_EQ(copy.vector, original.vector);
  EXPECT_TRUE(std::signbit(copy.vector.y()));
  EXPECT_EQ(copy.rotation.coeffs(), original.rotation.coeffs());
  EXPECT_EQ(copy.dynamic, original.dynamic);
  EXPECT_EQ(copy.numbers, original.numbers);
  EXPECT_EQ(copy.flags, original.flags);
  ASSERT_EQ(copy.pairs.size(), 2u);
  EXPECT_EQ(copy.pairs[1].id, 9);
  EXPECT_EQ(copy.pairs[1].normal, Vec3::UnitZ());
  EXPECT_EQ(copy.faces, original.faces);
  EXPECT_EQ(copy.failure, original.failure);
  EXPECT_EQ(copy.impulses, original.impulses);
  EXPECT_EQ(copy.table, original.table);
}

// An unordered map's bytes follow its keys, not its buckets: two maps of the same entries
// inserted in other orders write the same bytes (checkpoints of equal states compare equal).
TEST(StateArchive, UnorderedMapWrittenInKeyOrder) {
  std::unordered_map<std::uint64_t, double> one, two;
  for (std::uint64_t k = 0; k < 100; ++k) one[k * 7919] = double(k);
  for (std::uint64_t k = 100; k-- > 0;) two[k * 7919] = double(k);
  StateArchive a, b;
  a(one);
  b(two);
  EXPECT_EQ(a.bytes(), b.bytes());
}

TEST(StateArchive, SectionOfAnotherNameIsRefusedByName) {
  StateArchive out;
  out.section("wcsph");
  StateArchive in(out.bytes());
  try {
    in.section("mps");
    FAIL() << "no error";
  } catch (const StateArchiveError& e) {
    EXPECT_STREQ(e.what(), "the checkpoint holds the part 'wcsph' where this case has 'mps'");
  }
}

TEST(StateArchive, StateCutShortIsRefused) {
  Everything original = filled();
  StateArchive out;
  original.archive_state(out);
  const std::string cut = out.bytes().substr(0, out.bytes().size() - 3);
  Everything copy;
  StateArchive in(cut);
  EXPECT_THROW(copy.archive_state(in), StateArchiveError);
}

TEST(StateArchive, BytesLeftOverAreRefused) {
  StateArchive out;
  double x = 1, y = 2;
  out(x, y);
  StateArchive in(out.bytes());
  in(x);
  EXPECT_THROW(in.finish(), StateArchiveError);
}

// A count that promises more entries than bytes remain fails before allocating them.
TEST(StateArchive, ImpossibleCountIsRefusedBeforeAllocating) {
  StateArchive out;
  std::uint64_t huge = std::uint64_t(1) << 60;
  out(huge);
  std::vector<double> values;
  StateArchive in(out.bytes());
  EXPECT_THROW(in(values), StateArchiveError);
  EXPECT_TRUE(values.empty());
}

TEST(StateArchive, ExpectedValueThatDiffersIsNamed) {
  StateArchive out;
  out.expect(std::uint64_t(12), "number of bodies");
  StateArchive in(out.bytes());
  try {
    in.expect(std::uint64_t(13), "number of bodies");
    FAIL() << "no error";
  } catch (const StateArchiveError& e) {
    EXPECT_STREQ(e.what(), "the checkpoint's number of bodies differs from this case's");
  }
}

}  // namespace
}  // namespace sluice
