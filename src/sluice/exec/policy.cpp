#include "sluice/exec/policy.hpp"

#include <omp.h>

namespace sluice::exec {

void set_thread_count(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

int thread_count() {
  return omp_get_max_threads();
}

}  // namespace sluice::exec
