#include "sluice/core/state_archive.hpp"

#include <fmt/format.h>

namespace sluice {

void StateArchive::section(std::string_view name) {
  std::string stored(name);
  value(stored);
  if (reading_ && stored != name) {
    throw StateArchiveError(
        fmt::format("the checkpoint holds the part '{}' where this case has '{}'", stored, name));
  }
}

void StateArchive::finish() const {
  if (reading_ && read_ != input_.size()) {
    throw StateArchiveError(fmt::format("the checkpoint holds {} bytes more than this case's state",
                                        input_.size() - read_));
  }
}

void StateArchive::bytes_of(void* data, std::size_t size) {
  if (size == 0) return;
  if (!reading_) {
    output_.append(static_cast<const char*>(data), size);
    return;
  }
  if (size > input_.size() - read_) {
    throw StateArchiveError("the checkpoint's state ends before this case's does");
  }
  std::memcpy(data, input_.data() + read_, size);
  read_ += size;
}

std::size_t StateArchive::checked_count(std::uint64_t count, std::size_t least_bytes_each) const {
  if (count > (input_.size() - read_) / least_bytes_each) {
    throw StateArchiveError(
        fmt::format("the checkpoint's state counts {} entries where fewer bytes remain", count));
  }
  return static_cast<std::size_t>(count);
}

}  // namespace sluice
