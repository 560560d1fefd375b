// A CSV table written row by row (probe time series and the like), flushed after every row so
// the file is usable while the run is still going.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "sluice/core/state_archive.hpp"

namespace sluice::io {

// A new table (the file truncated, the header written), or one a resumed run continues.
enum class CsvStart { kNew, kContinue };

class CsvWriter {
 public:
  // Opens (truncates) PATH and writes the header row, e.g. {"time [s]", "p1 pressure [Pa]"};
  // kContinue: opens the existing PATH to append (its length is set by archive_state).
  // Throws std::runtime_error naming the path if it cannot be opened or written.
  CsvWriter(std::string path, std::vector<std::string> header, CsvStart start = CsvStart::kNew);

  // Writes one row printed with "{:.9g}". Throws std::invalid_argument if the number of values
  // differs from the header, std::runtime_error if the write fails.
  void row(const std::vector<double>& values);
  void flush();

  // Checkpoints: the file's length. Read back, the file is cut to that length (the rows a
  // killed run wrote after the checkpoint go); a file shorter than that throws.
  void archive_state(StateArchive& a);

 private:
  struct Closer {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };

  void write_line(const std::string& line);

  std::string path_;
  size_t columns_;
  std::unique_ptr<std::FILE, Closer> file_;
};

}  // namespace sluice::io
