// The block that sums are taken over (exec/policy.hpp), apart so that a device's backend can
// sum in the same blocks without the host's policy.
#pragma once

#include <cstddef>

namespace sluice::exec {

// Sums are taken over fixed blocks of kSumBlock indices, each block in index order, and the
// blocks' sums in block order: the same additions whatever the number of threads.
inline constexpr std::size_t kSumBlock = 4096;

}  // namespace sluice::exec
