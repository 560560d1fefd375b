#include "sluice/io/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace sluice::io {

namespace {

void sync_folder(const std::filesystem::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // the rename has happened; a folder that cannot be synced is no error
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
  file_ = std::fopen(tmp_.c_str(), "wb");
  if (file_ == nullptr) fail("open " + tmp_, errno);
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_) std::remove(tmp_.c_str());
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  if (bytes > 0 && std::fwrite(data, 1, bytes, file_) != bytes) fail("write " + tmp_, errno);
}

void AtomicFile::commit(Commit how) {
  if (how == Commit::kDurable) {
    if (std::fflush(file_) != 0) fail("write " + tmp_, errno);
    if (::fsync(::fileno(file_)) != 0) fail("fsync " + tmp_, errno);
  }
  // fclose flushes the buffer, so a full disk shows up here.
  if (std::fclose(std::exchange(file_, nullptr)) != 0) fail("close " + tmp_, errno);
  std::error_code error;
  std::filesystem::rename(tmp_, path_, error);
  if (error) {
    throw std::runtime_error(
        fmt::format("cannot write '{}': rename {}: {}", path_, tmp_, error.message()));
  }
  committed_ = true;
  if (how == Commit::kDurable) sync_folder(std::filesystem::path(path_).parent_path());
}

void AtomicFile::fail(const std::string& step, int error) const {
  throw std::runtime_error(
      fmt::format("cannot write '{}': {}: {}", path_, step, std::strerror(error)));
}

}  // namespace sluice::io
