// Reading back a CSV file that sluice wrote (probes.csv, loads.csv, bodies/NAME.csv): a header
// of column names, then rows of numbers.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sluice::io {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;  // each as long as `columns`

  // The index of the column named `name`, if there is one.
  std::optional<std::size_t> column(const std::string& name) const;
  // The values of column `index`, one per row.
  std::vector<double> values(std::size_t index) const;
};

// Throws std::runtime_error naming the file (and the line) when it cannot be read, or a row is
// not as many numbers as the header has names.
CsvTable read_csv_table(const std::string& path);

}  // namespace sluice::io
