// A named part of the time step, run on a context (the step's clock, or a model's state).
// Stages run in order, each timed on its own.
#pragma once

#include <memory>
#include <utility>
#include <vector>

namespace sluice {

// Where the run is: the time at the start of the step being taken, its length and its number.
struct StepClock {
  double time = 0;
  double dt = 0;
  long step = 0;
};

// The interface of a stage.
template <class Context>
class Stage {
 public:
  virtual ~Stage() = default;
  virtual const char* name() const = 0;
  virtual void run(Context& context) = 0;
};

// A stage made of a name and a function; enough for most stages.
template <class Context, class Fn>
class FunctionStage final : public Stage<Context> {
 public:
  FunctionStage(const char* name, Fn fn) : name_(name), fn_(std::move(fn)) {}
  const char* name() const override { return name_; }
  void run(Context& context) override { fn_(context); }

 private:
  const char* name_;
  Fn fn_;
};

template <class Context, class Fn>
std::unique_ptr<Stage<Context>> make_stage(const char* name, Fn fn) {
  return std::make_unique<FunctionStage<Context, Fn>>(name, std::move(fn));
}

// The stages of a time step, in the order they run.
using StepStage = Stage<const StepClock>;
using StageList = std::vector<std::unique_ptr<StepStage>>;

}  // namespace sluice
