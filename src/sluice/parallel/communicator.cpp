#include "sluice/parallel/communicator.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#ifdef SLUICE_WITH_MPI
#include <mpi.h>
#endif

namespace sluice {

namespace {
#ifdef SLUICE_WITH_MPI
// OpenMPI's launcher (and PMIx's) tell a process it is one of several through its environment.
bool started_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

bool mpi_running() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

int as_count(std::size_t bytes) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error("MPI: a message of over 2 GiB; run on more ranks");
  return static_cast<int>(bytes);
}
#endif
}  // namespace

MpiSession::MpiSession() {
#ifdef SLUICE_WITH_MPI
  if (started_by_mpirun() && !mpi_running()) {
    // Threads (OpenMP) run between MPI calls, never in them.
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    started_here_ = true;
  }
#endif
}

MpiSession::~MpiSession() {
#ifdef SLUICE_WITH_MPI
  if (started_here_ && mpi_running()) MPI_Finalize();
#endif
}

Communicator Communicator::world() {
#ifdef SLUICE_WITH_MPI
  if (mpi_running()) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return Communicator(rank, size);
  }
#endif
  return alone();
}

void Communicator::barrier() const {
#ifdef SLUICE_WITH_MPI
  if (split()) check(MPI_Barrier(MPI_COMM_WORLD), "a barrier");
#endif
}

namespace {
enum class Reduction { kMin, kMax, kSum };

// Each of `values` over the ranks, in place (nothing to do on one rank).
void reduce(bool split, std::span<double> values, Reduction how) {
#ifdef SLUICE_WITH_MPI
  if (!split || values.empty()) return;
  const MPI_Op op = how == Reduction::kMin ? MPI_MIN : how == Reduction::kMax ? MPI_MAX : MPI_SUM;
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), as_count(values.size()), MPI_DOUBLE, op,
                      MPI_COMM_WORLD),
        "a reduction");
#else
  (void)split, (void)values, (void)how;
#endif
}
}  // namespace

double Communicator::min(double value) const {
  reduce(split(), {&value, 1}, Reduction::kMin);
  return value;
}

double Communicator::max(double value) const {
  reduce(split(), {&value, 1}, Reduction::kMax);
  return value;
}

double Communicator::sum(double value) const {
  reduce(split(), {&value, 1}, Reduction::kSum);
  return value;
}

void Communicator::sum(std::span<double> values) const {
  reduce(split(), values, Reduction::kSum);
}

void Communicator::max(std::span<double> values) const {
  reduce(split(), values, Reduction::kMax);
}

int Communicator::first_rank_where(bool holds) const {
  const double mine = holds ? rank_ : std::numeric_limits<double>::infinity();
  const double first = min(mine);
  return first == std::numeric_limits<double>::infinity() ? -1 : static_cast<int>(first);
}

std::string Communicator::broadcast(const std::string& text, int root) const {
#ifdef SLUICE_WITH_MPI
  if (split()) {
    std::uint64_t length = text.size();
    check(MPI_Bcast(&length, 1, MPI_UINT64_T, root, MPI_COMM_WORLD), "a broadcast");
    std::string out = rank_ == root ? text : std::string(length, '\0');
    check(MPI_Bcast(out.data(), as_count(length), MPI_CHAR, root, MPI_COMM_WORLD), "a broadcast");
    return out;
  }
#endif
  (void)root;
  return text;
}

std::vector<std::vector<unsigned char>> Communicator::exchange(
    const std::vector<std::vector<unsigned char>>& outgoing) const {
  if (outgoing.size() != static_cast<std::size_t>(size_))
    throw std::logic_error("Communicator::exchange: one outgoing buffer per rank");
  if (!split()) return outgoing;
#ifdef SLUICE_WITH_MPI
  const auto n = static_cast<std::size_t>(size_);
  std::vector<int> send_counts(n), receive_counts(n), send_offsets(n), receive_offsets(n);
  std::vector<unsigned char> send;
  for (std::size_t r = 0; r < n; ++r) {
    send_offsets[r] = as_count(send.size());
    send_counts[r] = as_count(outgoing[r].size());
    send.insert(send.end(), outgoing[r].begin(), outgoing[r].end());
  }
  check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT,
                     MPI_COMM_WORLD),
        "the exchange's counts");
  std::size_t total = 0;
  for (std::size_t r = 0; r < n; ++r) {
    receive_offsets[r] = as_count(total);
    total += static_cast<std::size_t>(receive_counts[r]);
  }
  std::vector<unsigned char> received(total);
  check(
      MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, received.data(),
                    receive_counts.data(), receive_offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
      "the exchange");
  std::vector<std::vector<unsigned char>> incoming(n);
  for (std::size_t r = 0; r < n; ++r) {
    const auto begin = received.begin() + receive_offsets[r];
    incoming[r].assign(begin, begin + receive_counts[r]);
  }
  return incoming;
#else
  return outgoing;
#endif
}

#ifdef SLUICE_WITH_MPI
namespace {
// Every rank's `count` items of `type` (`size` bytes each), one after another by rank, with
// each rank's count.
std::vector<unsigned char> gather_items(const void* data, std::size_t count, MPI_Datatype type,
                                        std::size_t size, std::vector<int>& counts) {
  const int mine = as_count(count);
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  counts.assign(static_cast<std::size_t>(ranks), 0);
  check(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD),
        "a gather's counts");
  std::vector<int> offsets(counts.size());
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    offsets[r] = as_count(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  as_count(total * size);
  std::vector<unsigned char> out(total * size);
  check(MPI_Allgatherv(data, mine, type, out.data(), counts.data(), offsets.data(), type,
                       MPI_COMM_WORLD),
        "a gather");
  return out;
}
}  // namespace
#endif

std::vector<double> Communicator::gather_all(std::span<const double> values) const {
  if (!split()) return {values.begin(), values.end()};
#ifdef SLUICE_WITH_MPI
  std::vector<int> counts;
  const std::vector<unsigned char> bytes =
      gather_items(values.data(), values.size(), MPI_DOUBLE, sizeof(double), counts);
  std::vector<double> out(bytes.size() / sizeof(double));
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
#else
  return {values.begin(), values.end()};
#endif
}

std::vector<std::string> Communicator::gather_all(const std::string& bytes) const {
  if (!split()) return {bytes};
#ifdef SLUICE_WITH_MPI
  std::vector<int> counts;
  const std::vector<unsigned char> all =
      gather_items(bytes.data(), bytes.size(), MPI_BYTE, 1, counts);
  std::vector<std::string> out;
  std::size_t offset = 0;
  for (const int count : counts) {
    out.emplace_back(reinterpret_cast<const char*>(all.data()) + offset,
                     static_cast<std::size_t>(count));
    offset += static_cast<std::size_t>(count);
  }
  return out;
#else
  return {bytes};
#endif
}

void Communicator::abort(int code) const {
#ifdef SLUICE_WITH_MPI
  if (split()) MPI_Abort(MPI_COMM_WORLD, code);
#else
  (void)code;
#endif
}

}  // namespace sluice
