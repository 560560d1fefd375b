#include "sluice/linear/hypre_session.hpp"

#include <stdexcept>

#ifdef SLUICE_WITH_HYPRE
#include <HYPRE.h>
#include <HYPRE_utilities.h>
#include <mpi.h>
#endif

namespace sluice {

void HypreSession::start() {
  if (hypre_started_) return;
  if (finished_) throw std::logic_error("hypre's session has ended: MPI cannot start again");
#ifdef SLUICE_WITH_HYPRE
  int running = 0;
  MPI_Initialized(&running);
  if (!running) {
    MPI_Init(nullptr, nullptr);
    mpi_started_here_ = true;
  }
  HYPRE_Init();
#endif
  hypre_started_ = true;
}

void HypreSession::finish() {
  if (!hypre_started_) return;
  hypre_started_ = false;
  finished_ = true;
#ifdef SLUICE_WITH_HYPRE
  HYPRE_Finalize();
  if (mpi_started_here_) MPI_Finalize();
#endif
}

}  // namespace sluice
