#include "sluice/io/checkpoint_file.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "sluice/core/state_archive.hpp"
#include "sluice/io/atomic_file.hpp"

namespace sluice::io {

namespace {

constexpr std::string_view kMagic = "SLUICECP";
constexpr std::size_t kPrefix = 8 + 4 + 8;  // magic, format, body length
constexpr std::size_t kSuffix = 4;          // CRC-32

void archive_header(StateArchive& a, CheckpointHeader& h) {
  a(h.sluice_version, h.case_name, h.model, h.dimension, h.case_identity, h.time, h.step);
}

template <class T>
void append_raw(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T read_raw(std::string_view bytes, std::size_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

}  // namespace

std::uint32_t crc32_of(std::string_view bytes) {
  uLong crc = crc32(0L, Z_NULL, 0);
  // zlib takes at most 4 GiB at a time.
  while (!bytes.empty()) {
    const std::size_t n = std::min<std::size_t>(bytes.size(), 1u << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(n));
    bytes.remove_prefix(n);
  }
  return static_cast<std::uint32_t>(crc);
}

void write_checkpoint(const std::string& path, const CheckpointHeader& header,
                      std::string_view state) {
  StateArchive archive;
  CheckpointHeader h = header;
  archive_header(archive, h);
  const std::string& head = archive.bytes();
  std::string prefix(kMagic);
  append_raw<std::uint32_t>(prefix, kCheckpointFormat);
  append_raw<std::uint64_t>(prefix, head.size() + state.size());
  uLong crc = crc32_of(prefix);
  crc = crc32_combine(crc, crc32_of(head), static_cast<z_off_t>(head.size()));
  crc = crc32_combine(crc, crc32_of(state), static_cast<z_off_t>(state.size()));
  std::string suffix;
  append_raw<std::uint32_t>(suffix, static_cast<std::uint32_t>(crc));

  AtomicFile file(path);
  for (std::string_view part :
       {std::string_view(prefix), std::string_view(head), state, std::string_view(suffix)}) {
    file.write(part);
  }
  file.commit(Commit::kDurable);
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(fmt::format("{}: cannot open: {}", path, std::strerror(errno)));
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t head = std::min(bytes.size(), kMagic.size());
  if (std::string_view(bytes).substr(0, head) != kMagic.substr(0, head)) {
    throw CheckpointError(fmt::format("{}: not a sluice checkpoint (no SLUICECP header)", path));
  }
  if (bytes.size() < kPrefix) {
    throw CheckpointError(
        fmt::format("{}: {} bytes, cut short within its header", path, bytes.size()));
  }
  const auto format = read_raw<std::uint32_t>(bytes, 8);
  if (format != kCheckpointFormat) {
    throw CheckpointError(fmt::format("{}: checkpoint format {}, this sluice reads format {}", path,
                                      format, kCheckpointFormat));
  }
  const auto body = read_raw<std::uint64_t>(bytes, 12);
  const std::uint64_t expected = kPrefix + body + kSuffix;
  if (body > bytes.size() || bytes.size() != expected) {
    throw CheckpointError(fmt::format("{}: {} bytes where the header promises {} (cut short?)",
                                      path, bytes.size(), expected));
  }
  const std::string_view covered = std::string_view(bytes).substr(0, bytes.size() - kSuffix);
  if (crc32_of(covered) != read_raw<std::uint32_t>(bytes, bytes.size() - kSuffix)) {
    throw CheckpointError(
        fmt::format("{}: checksum mismatch (the file was changed or damaged)", path));
  }
  Checkpoint checkpoint;
  checkpoint.path = path;
  StateArchive archive(covered.substr(kPrefix));
  try {
    archive_header(archive, checkpoint.header);
  } catch (const StateArchiveError& e) {
    throw CheckpointError(fmt::format("{}: {}", path, e.what()));
  }
  checkpoint.state.assign(covered.substr(kPrefix + archive.bytes_read()));
  return checkpoint;
}

}  // namespace sluice::io
