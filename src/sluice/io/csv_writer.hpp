// A CSV table written row by row (probe time series and the like), flushed after every row so
// the file is usable while the run is still going.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace sluice::io {

class CsvWriter {
 public:
  // Opens (truncates) PATH and writes the header row, e.g. {"time [s]", "p1 pressure [Pa]"}.
  // Throws std::runtime_error naming the path if it cannot be opened or written.
  CsvWriter(std::string path, std::vector<std::string> header);

  // Writes one row printed with "{:.9g}". Throws std::invalid_argument if the number of values
  // differs from the header, std::runtime_error if the write fails.
  void row(const std::vector<double>& values);
  void flush();

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
