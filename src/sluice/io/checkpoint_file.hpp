// A checkpoint file: the whole state of a run at the end of a step (core/state_archive.hpp),
// with what identifies it. The format is our own binary, not HDF5: a checkpoint is read back
// only by sluice, whole and bit for bit, and what matters is that a file cut short or with
// any byte changed is recognised; here one CRC-32 (zlib's) covers every byte, where HDF5
// checksums its metadata but not its raw data (unless chunked with Fletcher-32), and the
// state is written in one pass with no extra library. Layout, all little-endian
// (docs/output.md#checkpoints):
//   8 bytes "SLUICECP" | u32 format version | u64 body length | body | u32 CRC-32 of all before
// The body is the header (CheckpointHeader, archived) and then the state's bytes.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sluice::io {

inline constexpr std::uint32_t kCheckpointFormat = 1;

// A file that is no readable checkpoint (cut short, changed, of another format).
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CheckpointHeader {
  std::string sluice_version;  // of the build that wrote it
  std::string case_name;
  std::string model;  // the fluid model's name, or "bodies-alone"
  int dimension = 0;
  std::uint32_t case_identity = 0;  // CaseConfig::identity's checksum
  double time = 0;                  // simulated time [s]
  std::int64_t step = 0;
};

struct Checkpoint {
  std::string path;  // the file it was read from
  CheckpointHeader header;
  std::string state;
};

// CRC-32 (zlib) of some bytes.
std::uint32_t crc32_of(std::string_view bytes);

// Writes the file atomically and durably: PATH.tmp, fsync, rename over PATH, fsync of the
// folder. Throws std::runtime_error naming the path on failure (PATH is then left as it was).
void write_checkpoint(const std::string& path, const CheckpointHeader& header,
                      std::string_view state);
// Reads and verifies a checkpoint. Throws CheckpointError saying what is wrong with it.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace sluice::io
