// Execution policies: the one place where loops are handed to threads. A loop body is written
// once as a function of the index and run by a policy; no copy of a loop per backend. Serial
// is the reference; OpenMP gives the same answers on any number of threads
// (tests/unit/exec, tests/physics/test_determinism.cpp); a GPU policy would be another struct
// with the same members.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "sluice/exec/sum_block.hpp"

namespace sluice::exec {

// Loops shorter than this run on the calling thread: starting the threads costs more (a few
// microseconds) than the work (the CCP solvers run a dozen short loops an iteration).
inline constexpr long kParallelFrom = 4096;

// OpenMP threads with a static schedule, so each thread gets a contiguous block of the
// cell-sorted particles. Maxima and minima do not depend on the order of reduction; sums
// are taken block by block (kSumBlock), so the answer is the same on any number of threads.
struct OpenMP {
  template <class Body>
  static void for_each(std::size_t n, Body&& body) {
    const long count = static_cast<long>(n);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
  }
  // For loops whose body is a few operations (vector arithmetic): threads only from
  // kParallelFrom indices on.
  template <class Body>
  static void for_each_light(std::size_t n, Body&& body) {
    const long count = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (count >= kParallelFrom)
    for (long i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
  }
  // For loops whose cost varies a lot along the index (pair loops: boundary particles far
  // from the fluid cost nothing): threads take chunks of 256 indices as they finish. Each
  // index is still computed by one thread alone, so results do not depend on the schedule.
  template <class Body>
  static void for_each_balanced(std::size_t n, Body&& body) {
    const long count = static_cast<long>(n);
#pragma omp parallel for schedule(dynamic, 256)
    for (long i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
  }
  template <class Value>
  static double max_of(std::size_t n, Value&& value) {
    double result = -std::numeric_limits<double>::infinity();
    const long count = static_cast<long>(n);
#pragma omp parallel for schedule(static) reduction(max : result) if (count >= kParallelFrom)
    for (long i = 0; i < count; ++i) result = std::max(result, value(static_cast<std::size_t>(i)));
    return result;
  }
  template <class Value>
  static double sum_of(std::size_t n, Value&& value) {
    const long blocks = static_cast<long>((n + kSumBlock - 1) / kSumBlock);
    if (blocks <= 1) return block_sum(0, n, value);
    std::vector<double> partial(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(static)
    for (long k = 0; k < blocks; ++k) {
      const std::size_t begin = static_cast<std::size_t>(k) * kSumBlock;
      partial[static_cast<std::size_t>(k)] =
          block_sum(begin, std::min(n, begin + kSumBlock), value);
    }
    double total = 0;
    for (const double p : partial) total += p;
    return total;
  }

 private:
  template <class Value>
  static double block_sum(std::size_t begin, std::size_t end, Value& value) {
    double sum = 0;
    for (std::size_t i = begin; i < end; ++i) sum += value(i);
    return sum;
  }
};

// One thread, in index order: the reference the OpenMP policy must agree with.
struct Serial {
  template <class Body>
  static void for_each(std::size_t n, Body&& body) {
    for (std::size_t i = 0; i < n; ++i) body(i);
  }
  template <class Body>
  static void for_each_balanced(std::size_t n, Body&& body) {
    for_each(n, body);
  }
  template <class Body>
  static void for_each_light(std::size_t n, Body&& body) {
    for_each(n, body);
  }
  template <class Value>
  static double max_of(std::size_t n, Value&& value) {
    double result = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) result = std::max(result, value(i));
    return result;
  }
  // The same blocks as OpenMP::sum_of, so that both give the same sum.
  template <class Value>
  static double sum_of(std::size_t n, Value&& value) {
    double total = 0;
    for (std::size_t begin = 0; begin < n; begin += kSumBlock) {
      double sum = 0;
      for (std::size_t i = begin; i < std::min(n, begin + kSumBlock); ++i) sum += value(i);
      total += sum;
    }
    return total;
  }
};

using Default = OpenMP;

// Sets the number of threads the OpenMP policy uses (0 leaves the OpenMP default).
void set_thread_count(int threads);
int thread_count();

}  // namespace sluice::exec
