// Reading one YAML mapping with validation: every key is looked up by name, its type checked,
// and keys nobody asked for are reported with a "did you mean" suggestion. Every error names
// the file, the line and the full key path.
#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sluice/core/errors.hpp"
#include "sluice/core/types.hpp"

namespace sluice::io {

// What all readers of one case file share: its name, its dimension (to read vectors) and the
// key paths that came from --set on the command line (reported as such in messages).
struct YamlSource {
  std::string file;
  int dimension = 3;
  std::set<std::string> overridden_paths;
};

class MapReader {
 public:
  // `node` must be a mapping; `path` is its dotted key path ("" for the root) and `line` the
  // 1-based line it starts on, used when a key is missing.
  MapReader(std::shared_ptr<const YamlSource> source, const YAML::Node& node, std::string path,
            int line);

  bool has(const std::string& key) const;

  template <class T>
  T required(const std::string& key);

  template <class T>
  T optional(const std::string& key, const T& fallback) {
    return has(key) ? required<T>(key) : fallback;
  }

  // A number that must be > 0.
  double required_positive(const std::string& key);
  double optional_positive(const std::string& key, double fallback);
  // A number that must be >= 0.
  double optional_non_negative(const std::string& key, double fallback);

  // A nested mapping or sequence, marked as used.
  MapReader map(const std::string& key);
  YAML::Node node(const std::string& key);
  std::vector<MapReader> list_of_maps(const std::string& key);

  // Reports the first key that was never read, suggesting the closest key asked for.
  void finish() const;
  // The text of a key of this mapping, or an InputError when it is not one (a list, a mapping,
  // or nothing, as `{[a]: 1}` or `{!x : 1}` write).
  std::string key_name(const YAML::Node& key) const;

  // A text that must be one of `choices`; `what` names it in the message of fail_choice.
  std::string optional_choice(const std::string& key, const std::string& fallback,
                              const std::string& what, const std::vector<std::string>& choices);

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
  // "unknown WHAT 'value'; expected one of: a, b, c (did you mean 'a'?)"
  [[noreturn]] void fail_choice(const std::string& key, const std::string& what,
                                const std::string& value,
                                const std::vector<std::string>& choices) const;
  // Fails at the mapping itself (for problems that involve several keys).
  [[noreturn]] void fail_here(const std::string& problem) const;

  std::string path_of(const std::string& key) const;
  // Where messages about `key` point: the file and line, or "--set a.b" and 0 for a value given
  // on the command line.
  std::pair<std::string, int> place_of(const std::string& key) const;
  int line_of(const std::string& key) const;
  int line() const { return line_; }
  const std::string& path() const { return path_; }
  const YamlSource& source() const { return *source_; }

 private:
  std::string file_for(const std::string& full_path) const;
  // The line to report with `file`: none for a value given by --set.
  static int line_for(const std::string& file, int line);
  // Line of the key itself (not of its value), or of the mapping when the key is absent.
  int key_line(const std::string& key) const;
  // A required key is missing: blames a present, unread key that is a near miss of it.
  [[noreturn]] void fail_missing(const std::string& key) const;

  std::shared_ptr<const YamlSource> source_;
  YAML::Node node_;
  std::string path_;
  int line_;
  mutable std::set<std::string> used_;   // keys read
  mutable std::set<std::string> asked_;  // keys looked up, present or not (for suggestions)
};

// 1-based line of a node, 0 when the node has no position (made by --set).
int line_of(const YAML::Node& node);

// "unknown WHAT 'value'; expected one of: a, b, c (did you mean 'a'?)"
std::string unknown_choice(const std::string& what, const std::string& value,
                           const std::vector<std::string>& choices);

// Closest of `candidates` to `word` by edit distance, or "" when none is close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

// Edit distance (Levenshtein) between two words.
std::size_t edit_distance(const std::string& a, const std::string& b);

// Applies "a.b.c=value" to the tree (creating maps as needed; a number selects a list entry).
// Returns the dotted path of the outermost node it created or replaced: everything below it
// came from the command line. Throws InputError for a malformed override.
std::string apply_override(YAML::Node& root, const std::string& assignment);

}  // namespace sluice::io
