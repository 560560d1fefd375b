// A file replaced whole or not at all: written to PATH.tmp, then renamed over PATH by
// commit(). If commit() is not reached (an exception), the temporary is removed and PATH is
// left as it was. Output frames commit as they are; checkpoints commit durably, flushing the
// file to the disk before the rename and the folder after it, so that a power cut leaves
// either the old checkpoint or the new one.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace sluice::io {

enum class Commit { kRename, kDurable };

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Each throws std::runtime_error "cannot write 'PATH': STEP: REASON".
  void write(const void* data, std::size_t bytes);
  void write(std::string_view text) { write(text.data(), text.size()); }
  void commit(Commit how = Commit::kRename);

 private:
  [[noreturn]] void fail(const std::string& step, int error) const;

  std::string path_;
  std::string tmp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

}  // namespace sluice::io
