// MPI and hypre for one process. MPI may start once in a process's life and stop once, so one
// object owns both: the program's main (a test binary's environment), which hands it to the
// solvers that need it. It starts them when the first hypre solve asks (a single process's
// MPI_Init costs about half a second, which a run without hypre should not pay) and stops
// them when it ends. Under mpirun, where the program started MPI itself, it starts hypre only.
#pragma once

namespace sluice {

class HypreSession {
 public:
  HypreSession() = default;
  ~HypreSession() { finish(); }
  HypreSession(const HypreSession&) = delete;
  HypreSession& operator=(const HypreSession&) = delete;

  // Starts MPI (unless it runs already) and hypre; again, nothing.
  void start();
  // Stops hypre, and MPI if this session started it; again, or before start, nothing. A start
  // after it throws std::logic_error: MPI cannot start twice in a process.
  void finish();
  bool started() const { return hypre_started_; }  // and not finished

 private:
  bool hypre_started_ = false;
  bool mpi_started_here_ = false;
  bool finished_ = false;
};

}  // namespace sluice
