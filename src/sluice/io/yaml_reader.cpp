#include "sluice/io/yaml_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace sluice::io {

int line_of(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const auto& candidate : candidates) {
    const size_t d = edit_distance(word, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

MapReader::MapReader(std::shared_ptr<const YamlSource> source, const YAML::Node& node,
                     std::string path, int line)
    : source_(std::move(source)), node_(node), path_(std::move(path)), line_(line) {
  if (!node_.IsMap()) {
    const int at = io::line_of(node_) > 0 ? io::line_of(node_) : line_;
    const std::string file = file_for(path_);
    throw InputError(file, line_for(file, at), path_.empty() ? "(top level)" : path_,
                     "expected a mapping of keys to values");
  }
  // yaml-cpp keeps duplicate keys and lookups see only the first: report the second.
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    if (seen.insert(key).second) continue;
    const std::string full = path_of(key);
    const std::string file = file_for(full);
    throw InputError(file, line_for(file, io::line_of(entry.first)), full,
                     fmt::format("appears twice (first on line {})", key_line(key)));
  }
}

std::string MapReader::path_of(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

std::string MapReader::file_for(const std::string& full_path) const {
  // List entries are named a.b[0] in messages and a.b.0 on the command line.
  std::string dotted;
  for (const char c : full_path) {
    if (c == '[') {
      dotted += '.';
    } else if (c != ']') {
      dotted += c;
    }
  }
  for (const auto& p : source_->overridden_paths) {
    if (dotted == p || dotted.rfind(p + ".", 0) == 0) return "--set " + p;
  }
  return source_->file;
}

int MapReader::line_for(const std::string& file, int line) {
  return file.rfind("--set ", 0) == 0 ? 0 : line;
}

int MapReader::key_line(const std::string& key) const {
  for (const auto& entry : node_) {
    if (entry.first.Scalar() == key && io::line_of(entry.first) > 0) {
      return io::line_of(entry.first);
    }
  }
  return line_;
}

bool MapReader::has(const std::string& key) const {
  asked_.insert(key);
  const YAML::Node child = node_[key];
  return child.IsDefined() && !child.IsNull();
}

int MapReader::line_of(const std::string& key) const {
  const YAML::Node child = node_[key];
  if (child.IsDefined()) {
    const int line = io::line_of(child);
    if (line > 0) return line;
  }
  return line_;
}

std::pair<std::string, int> MapReader::place_of(const std::string& key) const {
  const std::string file = file_for(path_of(key));
  return {file, line_for(file, line_of(key))};
}

std::string MapReader::optional_choice(const std::string& key, const std::string& fallback,
                                       const std::string& what,
                                       const std::vector<std::string>& choices) {
  const std::string value = optional<std::string>(key, fallback);
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    fail_choice(key, what, value, choices);
  }
  return value;
}

std::string unknown_choice(const std::string& what, const std::string& value,
                           const std::vector<std::string>& choices) {
  std::string problem = fmt::format("unknown {} '{}'; expected one of: ", what, value);
  for (std::size_t k = 0; k < choices.size(); ++k) problem += (k ? ", " : "") + choices[k];
  const std::string guess = closest_match(value, choices);
  if (!guess.empty()) problem += fmt::format(" (did you mean '{}'?)", guess);
  return problem;
}

void MapReader::fail_choice(const std::string& key, const std::string& what,
                            const std::string& value,
                            const std::vector<std::string>& choices) const {
  fail(key, unknown_choice(what, value, choices));
}

void MapReader::fail(const std::string& key, const std::string& problem) const {
  const auto [file, line] = place_of(key);
  throw InputError(file, line, path_of(key), problem);
}

void MapReader::fail_here(const std::string& problem) const {
  const std::string file = file_for(path_);
  throw InputError(file, line_for(file, line_), path_.empty() ? "(top level)" : path_, problem);
}

void MapReader::fail_missing(const std::string& key) const {
  if (node_[key].IsDefined()) {  // "key:" with nothing after it
    const std::string full = path_of(key);
    const std::string file = file_for(full);
    throw InputError(file, line_for(file, key_line(key)), full, "has no value");
  }
  // Closer than closest_match's threshold, so that a missing 'min' is not blamed on 'max'.
  const size_t near = std::max<size_t>(1, key.size() / 4);
  for (const auto& entry : node_) {
    const std::string present = entry.first.Scalar();
    if (asked_.count(present) || edit_distance(present, key) > near) continue;
    const std::string full = path_of(present);
    const std::string file = file_for(full);
    throw InputError(file, line_for(file, key_line(present)), full,
                     fmt::format("unknown key (did you mean '{}'?)", key));
  }
  fail(key, "missing required key");
}

namespace {
template <class T>
const char* type_name();
template <>
const char* type_name<double>() {
  return "a number";
}
template <>
const char* type_name<int>() {
  return "an integer";
}
template <>
const char* type_name<bool>() {
  return "true or false";
}
template <>
const char* type_name<std::string>() {
  return "a text value";
}
}  // namespace

template <class T>
T MapReader::required(const std::string& key) {
  if (!has(key)) fail_missing(key);
  used_.insert(key);
  const YAML::Node child = node_[key];
  if constexpr (std::is_same_v<T, Vec3>) {
    const int dim = source_->dimension;
    if (!child.IsSequence() || (child.size() != 3 && static_cast<int>(child.size()) != dim)) {
      fail(key, dim == 2 ? "expected a vector [x, z] (or [x, y, z] with y ignored)"
                         : "expected a vector [x, y, z]");
    }
    Vec3 v = Vec3::Zero();
    for (size_t i = 0; i < child.size(); ++i) {
      double value = 0;
      if (!YAML::convert<double>::decode(child[i], value) || !std::isfinite(value)) {
        fail(key, fmt::format("component {} is not a number", i + 1));
      }
      v[static_cast<int>(i)] = value;
    }
    if (child.size() == 2) v = Vec3(v[0], 0.0, v[1]);
    if (dim == 2) v[1] = 0;  // 2D: the x-z plane; a given y is ignored everywhere
    return v;
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    if (!child.IsSequence()) fail(key, "expected a list of text values");
    std::vector<std::string> out;
    for (const auto& item : child) {
      if (!item.IsScalar()) fail(key, "expected a list of text values");
      out.push_back(item.as<std::string>());
    }
    return out;
  } else {
    T value{};
    if (!child.IsScalar() || !YAML::convert<T>::decode(child, value)) {
      fail(key, fmt::format("expected {}, got '{}'", type_name<T>(),
                            child.IsScalar() ? child.Scalar() : std::string("a collection")));
    }
    if constexpr (std::is_same_v<T, double>) {
      if (!std::isfinite(value)) fail(key, "expected a finite number");
    }
    return value;
  }
}

template double MapReader::required<double>(const std::string&);
template int MapReader::required<int>(const std::string&);
template bool MapReader::required<bool>(const std::string&);
template std::string MapReader::required<std::string>(const std::string&);
template Vec3 MapReader::required<Vec3>(const std::string&);
template std::vector<std::string> MapReader::required<std::vector<std::string>>(const std::string&);

double MapReader::required_positive(const std::string& key) {
  const double value = required<double>(key);
  if (!(value > 0)) fail(key, fmt::format("must be greater than zero, got {}", value));
  return value;
}

double MapReader::optional_positive(const std::string& key, double fallback) {
  return has(key) ? required_positive(key) : fallback;
}

double MapReader::optional_non_negative(const std::string& key, double fallback) {
  if (!has(key)) return fallback;
  const double value = required<double>(key);
  if (value < 0) fail(key, fmt::format("must not be negative, got {}", value));
  return value;
}

MapReader MapReader::map(const std::string& key) {
  if (!has(key)) fail_missing(key);
  used_.insert(key);
  return MapReader(source_, node_[key], path_of(key), line_of(key));
}

YAML::Node MapReader::node(const std::string& key) {
  used_.insert(key);
  return node_[key];
}

std::vector<MapReader> MapReader::list_of_maps(const std::string& key) {
  std::vector<MapReader> out;
  if (!has(key)) return out;
  used_.insert(key);
  const YAML::Node list = node_[key];
  if (!list.IsSequence()) fail(key, "expected a list");
  for (size_t i = 0; i < list.size(); ++i) {
    const int line = io::line_of(list[i]) > 0 ? io::line_of(list[i]) : line_of(key);
    out.emplace_back(source_, list[i], fmt::format("{}[{}]", path_of(key), i), line);
  }
  return out;
}

std::string MapReader::key_name(const YAML::Node& key) const {
  if (key.IsScalar()) return key.Scalar();
  const std::string file = file_for(path_);
  const int line = line_for(file, io::line_of(key) > 0 ? io::line_of(key) : line_);
  const char* what = key.IsSequence() ? "a list" : key.IsMap() ? "a mapping" : "nothing";
  throw InputError(file, line, path_.empty() ? "(top level)" : path_,
                   fmt::format("a key must be a name, found {}", what));
}

void MapReader::finish() const {
  std::vector<std::string> known(asked_.begin(), asked_.end());
  for (const auto& entry : node_) {
    const std::string key = key_name(entry.first);
    if (used_.count(key)) continue;
    const std::string full = path_of(key);
    const std::string file = file_for(full);
    const int line = line_for(file, key_line(key));
    // An optional key given with no value: has() took it for absent.
    if (asked_.count(key) && entry.second.IsNull()) {
      throw InputError(file, line, full, "has no value (remove the key to use its default)");
    }
    std::string problem = "unknown key";
    const std::string suggestion = closest_match(key, known);
    if (!suggestion.empty()) problem += fmt::format(" (did you mean '{}'?)", suggestion);
    throw InputError(file, line, full, problem);
  }
}

std::string apply_override(YAML::Node& root, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw InputError("--set " + assignment, 0, "",
                     "expected KEY.PATH=VALUE, for example model.artificial_viscosity=0.05");
  }
  const std::string path = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  YAML::Node value;
  try {
    value = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError("--set " + path, 0, path, "value is not valid YAML: " + e.msg);
  }
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  for (const auto& part : parts) {
    if (part.empty()) throw InputError("--set " + path, 0, path, "empty key in path");
  }
  auto prefix = [&](size_t n) {  // the first n parts, dotted
    std::string out;
    for (size_t i = 0; i < n; ++i) out += (i ? "." : "") + parts[i];
    return out;
  };
  auto list_index = [&](const YAML::Node& list, size_t i) {
    size_t index = 0;
    const std::string& part = parts[i];
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
    if (error != std::errc() || end != part.data() + part.size()) {
      throw InputError("--set " + path, 0, path,
                       fmt::format("'{}' is a list: '{}' is not an entry number", prefix(i), part));
    }
    if (index >= list.size()) {
      throw InputError(
          "--set " + path, 0, path,
          fmt::format("no list entry {} in '{}' ({} entries)", index, prefix(i), list.size()));
    }
    return index;
  };
  // yaml-cpp nodes are handles: walk down by reassigning a handle, never by copying values.
  std::vector<YAML::Node> chain{root};
  size_t created = parts.size();  // parts[0..created) existed before
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node current = chain.back();
    const std::string& part = parts[i];
    if (current.IsSequence()) {
      chain.push_back(current[list_index(current, i)]);
    } else if (current.IsMap()) {
      if (!current[part].IsDefined() || current[part].IsNull()) {
        current[part] = YAML::Node(YAML::NodeType::Map);
        created = std::min(created, i + 1);
      }
      chain.push_back(current[part]);
    } else {
      throw InputError("--set " + path, 0, path,
                       fmt::format("'{}' is a single value, it has no key '{}'", prefix(i), part));
    }
  }
  YAML::Node parent = chain.back();
  const std::string& last = parts.back();
  if (parent.IsSequence()) {
    parent[list_index(parent, parts.size() - 1)] = value;
  } else if (parent.IsMap()) {
    parent[last] = value;
  } else {
    throw InputError(
        "--set " + path, 0, path,
        fmt::format("'{}' is a single value, it has no key '{}'", prefix(parts.size() - 1), last));
  }
  return prefix(created);
}

}  // namespace sluice::io
