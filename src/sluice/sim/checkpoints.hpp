// A run's checkpoints in OUT/checkpoints/ (docs/output.md#checkpoints): each written at the end
// of a step as step_NNNNNNNNNN.ckpt (io/checkpoint_file.hpp), the newest two kept; and, for
// `sluice run --resume`, the newest one that reads back whole and belongs to the case.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sluice/io/case_config.hpp"
#include "sluice/io/checkpoint_file.hpp"
#include "sluice/parallel/communicator.hpp"

namespace sluice {

// How many checkpoints a run keeps: the newest may be the one a kill cut short.
inline constexpr std::size_t kCheckpointsKept = 2;

class CheckpointFolder {
 public:
  // OUT/checkpoints; on several ranks, each rank's OUT/checkpoints/rank_R_of_N (a resume on
  // another number of ranks reads every writing rank's: pieces_written_on_another_count).
  explicit CheckpointFolder(const std::string& out_dir, const Communicator& ranks = {});

  const std::string& path() const { return folder_; }
  const std::string& root() const { return root_; }  // OUT/checkpoints
  int ranks() const { return ranks_; }               // of the run that writes or reads it
  // Writes the checkpoint of `header.step` atomically, then removes all but the newest
  // kCheckpointsKept (and any temporary file a killed run left).
  void write(const io::CheckpointHeader& header, std::string_view state) const;
  // The checkpoint files, newest (highest step) first.
  std::vector<std::string> files() const;
  // Removes every checkpoint, every rank's too: a new run into the folder must not leave an
  // older run's to be resumed (or to outrank its own). The first rank alone calls it.
  void clear() const;
  // Removes the checkpoints of runs on another number of ranks than this one's (those a resume
  // on this number split anew, once this run holds its own). The first rank alone calls it.
  void remove_other_counts() const;

 private:
  int ranks_;
  std::string root_;
  std::string folder_;
};

// What a checkpoint of this case, model and build records (time and step aside).
io::CheckpointHeader checkpoint_header(const io::CaseConfig& config, int dimension);

// The newest checkpoint in the folder that reads back whole, of a step no later than
// `latest_step` when one is given; each damaged or partial one newer than it is skipped with a
// line to `warn`. Throws InputError when there is none, or when it is of another case, model,
// dimension or sluice version than `expected`.
io::Checkpoint newest_checkpoint(const CheckpointFolder& folder,
                                 const io::CheckpointHeader& expected,
                                 const std::function<void(const std::string&)>& warn,
                                 std::optional<long long> latest_step = std::nullopt);

// The newest checkpoint that every rank holds whole, of one step on all (collective): a run
// killed while its ranks were writing a checkpoint leaves the ranks that had finished one step
// ahead, and resumes from the step before. One rank alone: newest_checkpoint.
io::Checkpoint newest_checkpoint_of_every_rank(const CheckpointFolder& folder,
                                               const io::CheckpointHeader& expected,
                                               const std::function<void(const std::string&)>& warn,
                                               const Communicator& ranks);

// A run resumed on another number of ranks than wrote its checkpoints (the folder holds
// none of this run's number): each writing rank's piece of the newest step that every one of
// them holds whole, the first rank's first; every rank of this run reads them all. None where
// the folder holds this run's own (newest_checkpoint_of_every_rank reads those) or no
// checkpoint at all. Throws InputError where no step reads back whole on every writing rank,
// or checkpoints of several numbers of ranks are there.
std::vector<io::Checkpoint> pieces_written_on_another_count(
    const CheckpointFolder& folder, const io::CheckpointHeader& expected,
    const std::function<void(const std::string&)>& warn);

}  // namespace sluice
