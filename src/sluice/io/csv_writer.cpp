#include "sluice/io/csv_writer.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace sluice::io {

namespace {

// RFC 4180 quoting, only where a field needs it.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

CsvWriter::CsvWriter(std::string path, std::vector<std::string> header, CsvStart start)
    : path_(std::move(path)), columns_(header.size()) {
  if (start == CsvStart::kContinue && !std::filesystem::is_regular_file(path_)) {
    throw std::runtime_error(fmt::format("cannot continue '{}': the file is missing", path_));
  }
  file_.reset(std::fopen(path_.c_str(), start == CsvStart::kNew ? "w" : "a"));
  if (!file_) {
    throw std::runtime_error(fmt::format("cannot open '{}': {}", path_, std::strerror(errno)));
  }
  if (start == CsvStart::kContinue) return;
  std::string line;
  for (size_t i = 0; i < header.size(); ++i) {
    if (i > 0) line += ',';
    line += csv_field(header[i]);
  }
  write_line(line);
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_) {
    throw std::invalid_argument(fmt::format("CSV '{}': row has {} values, header has {} columns",
                                            path_, values.size(), columns_));
  }
  std::string line;
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0) line += ',';
    fmt::format_to(std::back_inserter(line), "{:.9g}", values[i]);
  }
  write_line(line);
}

void CsvWriter::flush() {
  if (std::fflush(file_.get()) != 0) {
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path_, std::strerror(errno)));
  }
}

void CsvWriter::archive_state(StateArchive& a) {
  flush();
  std::uint64_t length = std::filesystem::file_size(path_);
  const std::uint64_t present = length;
  a(length);
  if (!a.reading()) return;
  if (present < length) {
    throw std::runtime_error(
        fmt::format("cannot continue '{}': it holds {} bytes, the checkpoint recorded {}", path_,
                    present, length));
  }
  // Appending writes at the end, wherever the stream's position is.
  if (::ftruncate(::fileno(file_.get()), static_cast<off_t>(length)) != 0) {
    throw std::runtime_error(fmt::format("cannot cut '{}': {}", path_, std::strerror(errno)));
  }
}

void CsvWriter::write_line(const std::string& line) {
  if (std::fputs(line.c_str(), file_.get()) == EOF || std::fputc('\n', file_.get()) == EOF) {
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path_, std::strerror(errno)));
  }
  flush();
}

}  // namespace sluice::io
