// Wall-clock time spent per named stage of the step, in the order the stages first ran.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace sluice {

// Runs fn() and adds the wall-clock seconds it took to `seconds`.
template <class Fn>
void add_seconds(double& seconds, Fn&& fn) {
  const auto start = std::chrono::steady_clock::now();
  fn();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class StageTimers {
 public:
  struct Entry {
    std::string name;
    double seconds = 0;
  };

  // Index of the stage `name`, created on first use. Look it up once, outside hot loops.
  std::size_t slot(const std::string& name) {
    for (std::size_t k = 0; k < entries_.size(); ++k) {
      if (entries_[k].name == name) return k;
    }
    entries_.push_back({name, 0});
    return entries_.size() - 1;
  }

  template <class Fn>
  void time(std::size_t slot, Fn&& fn) {
    add_seconds(entries_[slot].seconds, fn);
  }

  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace sluice
