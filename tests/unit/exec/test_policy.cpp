// Both execution policies, in one binary: every index visited exactly once, and the same
// maximum, whatever the policy and the number of threads.
#include "sluice/exec/policy.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

namespace sluice {
namespace {

template <class Policy>
class ExecutionPolicy : public ::testing::Test {};
using Policies = ::testing::Types<exec::Serial, exec::OpenMP>;
TYPED_TEST_SUITE(ExecutionPolicy, Policies);

TYPED_TEST(ExecutionPolicy, VisitsEveryIndexOnce) {
  for (std::size_t n : {0u, 1u, 255u, 256u, 257u, 10000u}) {
    std::vector<std::atomic<int>> plain(n), balanced(n);
    TypeParam::for_each(n, [&](std::size_t i) { ++plain[i]; });
    TypeParam::for_each_balanced(n, [&](std::size_t i) { ++balanced[i]; });
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(plain[i], 1) << n << " " << i;
      ASSERT_EQ(balanced[i], 1) << n << " " << i;
    }
  }
}

TYPED_TEST(ExecutionPolicy, MaximumAsTheSerialLoop) {
  const auto value = [](std::size_t i) { return std::sin(0.37 * static_cast<double>(i)) * i; };
  const int before = omp_get_max_threads();
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(TypeParam::max_of(1000, value), exec::Serial::max_of(1000, value));
    EXPECT_EQ(TypeParam::max_of(0, value), -std::numeric_limits<double>::infinity());
  }
  omp_set_num_threads(before);
}

// Sums over fixed blocks: bit for bit the serial loop's, on any number of threads (the
// values span 8 orders of magnitude, so another order of addition would round differently).
TYPED_TEST(ExecutionPolicy, SumAsTheSerialLoop) {
  const auto value = [](std::size_t i) { return std::sin(0.37 * static_cast<double>(i)) * i * i; };
  const int before = omp_get_max_threads();
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    for (std::size_t n : {std::size_t(0), std::size_t(10), std::size_t(50000)}) {
      EXPECT_EQ(TypeParam::sum_of(n, value), exec::Serial::sum_of(n, value)) << n;
    }
  }
  omp_set_num_threads(before);
  double plain = 0;
  for (std::size_t i = 0; i < 10; ++i) plain += value(i);
  EXPECT_EQ(exec::Serial::sum_of(10, value), plain);
}

}  // namespace
}  // namespace sluice
