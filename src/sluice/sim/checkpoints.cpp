#include "sluice/sim/checkpoints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "sluice/core/build_info.hpp"
#include "sluice/core/errors.hpp"

namespace sluice {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPrefix = "step_";
constexpr std::string_view kSuffix = ".ckpt";

bool all_digits(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The step in a checkpoint's file name, or -1 for another file.
long long step_of(const std::string& name) {
  if (name.size() <= kPrefix.size() + kSuffix.size() || !name.starts_with(kPrefix) ||
      !name.ends_with(kSuffix)) {
    return -1;
  }
  const std::string digits =
      name.substr(kPrefix.size(), name.size() - kPrefix.size() - kSuffix.size());
  if (!all_digits(digits)) return -1;
  return std::stoll(digits);
}

// The checkpoint files in `folder`, newest (highest step) first.
std::vector<std::string> checkpoint_files(const std::string& folder) {
  std::vector<std::pair<long long, std::string>> found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const long long step = step_of(entry.path().filename().string());
    if (step >= 0) found.emplace_back(step, entry.path().string());
  }
  std::sort(found.begin(), found.end(), std::greater<>());
  std::vector<std::string> paths;
  for (auto& [step, path] : found) paths.push_back(std::move(path));
  return paths;
}

// Where rank `rank` of a run on `ranks` keeps its checkpoints under OUT/checkpoints (`root`).
std::string rank_folder(const std::string& root, int rank, int ranks) {
  return ranks > 1 ? fmt::format("{}/rank_{}_of_{}", root, rank, ranks) : root;
}

// The numbers of ranks whose checkpoints are in OUT/checkpoints (`root`), ascending: K for
// folders rank_R_of_K that hold one, 1 for checkpoints in the root itself.
std::vector<int> rank_counts_that_wrote(const std::string& root) {
  std::vector<int> counts;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(root, error)) {
    const std::string name = entry.path().filename().string();
    if (step_of(name) >= 0) counts.push_back(1);
    const auto of = name.find("_of_");
    if (entry.is_directory() && name.starts_with("rank_") && of != std::string::npos &&
        !checkpoint_files(entry.path().string()).empty()) {
      const std::string count = name.substr(of + 4);
      if (all_digits(count)) counts.push_back(std::stoi(count));
    }
  }
  std::sort(counts.begin(), counts.end());
  counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
  return counts;
}

}  // namespace

CheckpointFolder::CheckpointFolder(const std::string& out_dir, const Communicator& ranks)
    : ranks_(ranks.size()),
      root_(out_dir + "/checkpoints"),
      folder_(rank_folder(root_, ranks.rank(), ranks.size())) {}

std::vector<std::string> CheckpointFolder::files() const {
  return checkpoint_files(folder_);
}

void CheckpointFolder::remove_other_counts() const {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(root_, error)) {
    const std::string name = entry.path().filename().string();
    if (ranks_ > 1 && step_of(name) >= 0) fs::remove(entry.path(), error);
    if (entry.is_directory() && name.starts_with("rank_") &&
        !name.ends_with(fmt::format("_of_{}", ranks_)))
      fs::remove_all(entry.path(), error);
  }
}

void CheckpointFolder::clear() const {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(root_, error)) {
    const std::string name = entry.path().filename().string();
    if (step_of(name) >= 0) fs::remove(entry.path(), error);
    if (entry.is_directory() && name.rfind("rank_", 0) == 0) fs::remove_all(entry.path(), error);
  }
}

void CheckpointFolder::write(const io::CheckpointHeader& header, std::string_view state) const {
  std::error_code error;
  fs::create_directories(folder_, error);
  if (error) {
    throw std::runtime_error(fmt::format("cannot create '{}': {}", folder_, error.message()));
  }
  io::write_checkpoint(fmt::format("{}/{}{:010d}{}", folder_, kPrefix, header.step, kSuffix),
                       header, state);
  const std::vector<std::string> all = files();
  for (std::size_t k = kCheckpointsKept; k < all.size(); ++k) fs::remove(all[k], error);
  for (const auto& entry : fs::directory_iterator(folder_, error)) {
    if (entry.path().extension() == ".tmp") fs::remove(entry.path(), error);
  }
}

io::CheckpointHeader checkpoint_header(const io::CaseConfig& config, int dimension) {
  io::CheckpointHeader h;
  h.sluice_version = sluice_version();
  h.case_name = config.name;
  h.model = config.has_fluid() ? config.model_name : "bodies-alone";
  h.dimension = dimension;
  h.case_identity = io::crc32_of(config.identity);
  return h;
}

namespace {

// newest_checkpoint's search, with none found as no value (a rank of several must not stop
// alone: the others learn it in the next reduction).
std::optional<io::Checkpoint> find_newest(const std::vector<std::string>& files,
                                          const io::CheckpointHeader& expected,
                                          const std::function<void(const std::string&)>& warn,
                                          std::optional<long long> latest_step) {
  for (const std::string& path : files) {
    if (latest_step && step_of(fs::path(path).filename().string()) > *latest_step) continue;
    io::Checkpoint checkpoint;
    try {
      checkpoint = io::read_checkpoint(path);
    } catch (const io::CheckpointError& e) {
      warn(fmt::format("skipping the checkpoint {}", e.what()));
      continue;
    }
    const io::CheckpointHeader& h = checkpoint.header;
    const auto refuse = [&](const std::string& what) {
      throw InputError(path, 0, "", "cannot resume: the checkpoint is " + what);
    };
    if (h.sluice_version != expected.sluice_version) {
      refuse(fmt::format("of sluice {}, this is sluice {}", h.sluice_version,
                         expected.sluice_version));
    }
    if (h.case_name != expected.case_name || h.dimension != expected.dimension) {
      refuse(fmt::format("of the {}D case '{}', not of the {}D case '{}'", h.dimension, h.case_name,
                         expected.dimension, expected.case_name));
    }
    if (h.model != expected.model) {
      refuse(fmt::format("of the model '{}', this case runs '{}'", h.model, expected.model));
    }
    if (h.case_identity != expected.case_identity) {
      refuse(
          fmt::format("of another version of the case '{}' (keys other than end_time and "
                      "checkpoint_interval, or --set values, differ)",
                      h.case_name));
    }
    return checkpoint;
  }
  return std::nullopt;
}

void refuse_if_empty(const CheckpointFolder& folder, const std::vector<std::string>& files) {
  if (!files.empty()) return;
  throw InputError(folder.path(), 0, "",
                   "no checkpoint to resume from (the case's checkpoint_interval turns them on)");
}

}  // namespace

io::Checkpoint newest_checkpoint(const CheckpointFolder& folder,
                                 const io::CheckpointHeader& expected,
                                 const std::function<void(const std::string&)>& warn,
                                 std::optional<long long> latest_step) {
  const std::vector<std::string> files = folder.files();
  refuse_if_empty(folder, files);
  std::optional<io::Checkpoint> found = find_newest(files, expected, warn, latest_step);
  if (!found)
    throw InputError(folder.path(), 0, "", "no checkpoint reads back whole; cannot resume");
  return std::move(*found);
}

io::Checkpoint newest_checkpoint_of_every_rank(const CheckpointFolder& folder,
                                               const io::CheckpointHeader& expected,
                                               const std::function<void(const std::string&)>& warn,
                                               const Communicator& ranks) {
  if (!ranks.split()) return newest_checkpoint(folder, expected, warn);
  const std::vector<std::string> files = folder.files();
  if (ranks.min(files.empty() ? 0.0 : 1.0) == 0.0) refuse_if_empty(folder, {});
  // Each round the ranks agree on the lowest of their newest steps (no step above it is on
  // every rank); if a rank lacks that very step, those that hold it look below it next round.
  // The ranks' lockstep keeps them at most one checkpoint apart: a round or two settles it.
  std::optional<io::Checkpoint> mine = find_newest(files, expected, warn, std::nullopt);
  for (;;) {
    const double agreed = ranks.min(mine ? double(mine->header.step) : -1.0);
    if (agreed < 0) {
      throw InputError(folder.path(), 0, "",
                       "no checkpoint of one step reads back whole on every rank; cannot resume");
    }
    if (mine && double(mine->header.step) > agreed) {
      mine = find_newest(files, expected, warn, (long long)agreed);
    }
    const bool held_here = mine && double(mine->header.step) == agreed;
    if (ranks.min(held_here ? 1.0 : 0.0) == 1.0) return std::move(*mine);
    if (held_here) mine = find_newest(files, expected, warn, (long long)agreed - 1);
  }
}

std::vector<io::Checkpoint> pieces_written_on_another_count(
    const CheckpointFolder& folder, const io::CheckpointHeader& expected,
    const std::function<void(const std::string&)>& warn) {
  if (!folder.files().empty()) return {};
  std::vector<int> counts = rank_counts_that_wrote(folder.root());
  std::erase(counts, folder.ranks());
  if (counts.empty()) return {};
  if (counts.size() > 1) {
    throw InputError(folder.root(), 0, "",
                     fmt::format("cannot resume: the folder holds checkpoints of runs on {} "
                                 "ranks; remove all but one run's rank_R_of_N folders",
                                 fmt::join(counts, ", ")));
  }
  const int wrote = counts.front();
  std::vector<std::vector<std::string>> files;
  for (int r = 0; r < wrote; ++r)
    files.push_back(checkpoint_files(rank_folder(folder.root(), r, wrote)));
  // The newest step of the first piece's that every piece holds whole.
  for (const std::string& path : files.front()) {
    const long long step = step_of(fs::path(path).filename().string());
    std::vector<io::Checkpoint> pieces;
    for (const auto& piece_files : files) {
      std::optional<io::Checkpoint> piece = find_newest(piece_files, expected, warn, step);
      if (!piece || piece->header.step != step) break;
      pieces.push_back(std::move(*piece));
    }
    if (pieces.size() == files.size()) return pieces;
  }
  throw InputError(folder.root(), 0, "",
                   fmt::format("no checkpoint of one step reads back whole on each of the {} "
                               "ranks that wrote them; cannot resume",
                               wrote));
}

}  // namespace sluice
