// The processes of a run that mpirun started, as the engine sees them: a rank, a count, the
// reductions that agree on one value (the time step, the bodies' loads, the probes) and the
// exchange of particles between ranks. A process that mpirun did not start (or a build without
// MPI) is one rank alone, and every call is its own answer with no MPI call made.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace sluice {

// Starts MPI at the top of main where mpirun started the process (its environment says so), so
// that every later part finds it running; ends it when main returns. A process that mpirun did
// not start does not pay MPI's start-up (hypre's solver starts it there when first asked).
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  [[maybe_unused]] bool started_here_ = false;  // used where MPI is built in
};

class Communicator {
 public:
  Communicator() = default;  // this process alone
  // Every rank of the run (MPI_COMM_WORLD) where MPI runs; this process alone otherwise.
  static Communicator world();
  // This process alone, whatever runs around it (a test's reference run).
  static Communicator alone() { return Communicator(0, 1); }

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool split() const { return size_ > 1; }

  // Collective (every rank calls them, in the same order). Waits until every rank is here.
  void barrier() const;
  // Each value over the ranks.
  double min(double value) const;
  double max(double value) const;
  double sum(double value) const;
  void sum(std::span<double> values) const;  // element by element, in place
  void max(std::span<double> values) const;
  // The lowest rank where `holds` is true, or -1.
  int first_rank_where(bool holds) const;
  // `text` as the rank `root` has it, on every rank.
  std::string broadcast(const std::string& text, int root) const;
  // Each rank sends outgoing[r] to rank r (outgoing has size() entries); returns what each rank
  // sent to this one, by rank (its own part copied).
  std::vector<std::vector<unsigned char>> exchange(
      const std::vector<std::vector<unsigned char>>& outgoing) const;
  // Every rank's `values`, one after another by rank, on every rank.
  std::vector<double> gather_all(std::span<const double> values) const;
  // Every rank's `bytes`, by rank, on every rank.
  std::vector<std::string> gather_all(const std::string& bytes) const;
  // Stops every rank of the run with `code` (MPI_Abort): for a failure on one rank while others
  // wait in a collective call. Returns only where the run is one rank.
  void abort(int code) const;

 private:
  Communicator(int rank, int size) : rank_(rank), size_(size) {}
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace sluice
