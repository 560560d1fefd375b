#include "sluice/io/csv_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sluice::io {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  return cells;
}

}  // namespace

std::optional<std::size_t> CsvTable::column(const std::string& name) const {
  const auto found = std::find(columns.begin(), columns.end(), name);
  if (found == columns.end()) return std::nullopt;
  return static_cast<std::size_t>(found - columns.begin());
}

std::vector<double> CsvTable::values(std::size_t index) const {
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& row : rows) out.push_back(row[index]);
  return out;
}

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the file");
  CsvTable table;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": the file is empty");
  table.columns = split(line);
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != table.columns.size()) {
      throw std::runtime_error(fmt::format("{}:{}: {} values for {} columns", path, number,
                                           cells.size(), table.columns.size()));
    }
    std::vector<double> row(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      // strtod, not from_chars: it reads "inf" and "nan" as sluice writes them.
      char* end = nullptr;
      row[c] = std::strtod(cells[c].c_str(), &end);
      if (cells[c].empty() || end != cells[c].c_str() + cells[c].size()) {
        throw std::runtime_error(fmt::format("{}:{}: '{}' is not a number (column {})", path,
                                             number, cells[c], table.columns[c]));
      }
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace sluice::io
