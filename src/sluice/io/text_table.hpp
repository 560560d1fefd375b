// A table of text cells, the header row first, written as CSV (cells quoted where they hold a
// comma, a quote or a line break) or as a Markdown table.
#pragma once

#include <string>
#include <vector>

namespace sluice::io {

using TextTable = std::vector<std::vector<std::string>>;

std::string table_csv(const TextTable& rows);
std::string table_markdown(const TextTable& rows);

}  // namespace sluice::io
