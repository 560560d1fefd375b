// The particle base's output and its check for a run gone wrong.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>
#include <type_traits>

#include "sluice/core/errors.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/fluid/particle_check.hpp"
#include "sluice/fluid/particle_fluid.hpp"

namespace sluice {

// The particles as points with every field marked for output, viewed where the set keeps it,
// and the body of each body particle.
template <int D>
FluidView ParticleFluid<D>::view_of(const ParticleSet<D>& ps) const {
  const std::size_t n = ps.size();
  FluidView view;
  view.positions = FieldView::of("position", D, n ? ps.position.front().data() : nullptr, n);
  ps.for_each_field([&](const FieldLabel& label, const auto& values) {
    if (!label.output) return;
    using Components = FieldComponents<typename std::decay_t<decltype(values)>::value_type>;
    const auto* first = reinterpret_cast<const typename Components::type*>(values.data());
    if constexpr (std::is_same_v<typename Components::type, std::int32_t>) {
      view.fields.push_back(FieldView::of(label.name, first, n));
    } else {
      view.fields.push_back(FieldView::of(label.name, Components::width, first, n));
    }
  });
  if (body_count_ > 0) {
    std::vector<std::int32_t> body(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::int32_t k = ps.body_point[i];
      body[i] = k < 0 ? -1 : static_cast<std::int32_t>(body_points_[k].body);
    }
    view.fields.push_back(FieldView::holding("body", std::move(body)));
  }
  return view;
}

template <int D>
ParticleSet<D> ParticleFluid<D>::owned_particles(bool (*keep)(const FieldLabel&)) const {
  const auto& ps = state_.particles;
  ParticleSet<D> out;
  out.assign_fields(ps, keep);
  std::vector<std::uint32_t> own;
  const std::int32_t* kinds = counted_kinds();
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (kinds[i] >= 0) own.push_back(static_cast<std::uint32_t>(i));
  }
  out.keep(own);
  return out;
}

namespace {
template <int D>
ParticleCheck<D> checker(const ParticleState<D>& s) {
  const auto& ps = s.particles;
  ParticleCheck<D> c{ps.position.front().data(),
                     ps.velocity.front().data(),
                     ps.density.data(),
                     ps.pressure.data(),
                     reinterpret_cast<const std::int32_t*>(ps.kind.data()),
                     {},
                     {}};
  for (int a = 0; a < D; ++a) {
    const int a3 = D == 3 ? a : 2 * a;
    c.escape_min[a] = s.escape_box.min[a3];
    c.escape_max[a] = s.escape_box.max[a3];
  }
  return c;
}
}  // namespace

template <int D>
std::optional<std::string> ParticleFluid<D>::check(const StepClock& clock) const {
  // On a device the check runs there; the host's copy names the particle.
  if (device_ && !device_->any_problem()) return std::nullopt;
  refresh_host();
  std::string problem;
  if (state_.particles.size() > 0) {
    const ParticleCheck<D> problem_of = checker(state_);
    const std::int32_t* counted = counted_kinds();  // a ghost's owner checks it
    // The first bad particle by index, found in parallel; the same on any thread count.
    const double first = -exec::Default::max_of(state_.particles.size(), [&](std::size_t i) {
      return counted[i] >= 0 && problem_of(i) != ParticleProblem::kNone
                 ? -static_cast<double>(i)
                 : -std::numeric_limits<double>::infinity();
    });
    if (!std::isfinite(first)) return first_problem(problem);
    const auto i = static_cast<std::size_t>(first);
    const Vec3 x = to_3d<D>(state_.particles.position[i]);
    problem = diverged_at(clock.step, clock.time) +
              fmt::format("particle {}{} at ({:.4g}, {:.4g}, {:.4g}): {}", i,
                          ranks_.split() ? fmt::format(" of rank {}", ranks_.rank()) : "", x[0],
                          x[1], x[2], particle_problem_text(problem_of(i)));
  }
  return first_problem(problem);
}

template <int D>
std::optional<std::string> ParticleFluid<D>::first_problem(const std::string& problem) const {
  // The first rank's problem, on every rank, so that all stop together.
  const int rank = ranks_.first_rank_where(!problem.empty());
  if (rank < 0) return std::nullopt;
  return ranks_.broadcast(problem, rank);
}

template <int D>
FluidView ParticleFluid<D>::view() const {
  refresh_host();
  if (!exchange_) return view_of(state_.particles);
  auto own = std::make_shared<ParticleSet<D>>(owned_particles(shown_in_frames));
  FluidView view = view_of(*own);
  view.keeps = std::move(own);
  return view;
}

// What a frame shows, the model's fields marked for output included.
template <int D>
void ParticleFluid<D>::remember_good(double time) {
  last_good_time_ = time;
  if (device_) {  // kept on the device
    device_->remember();
    if (device_->time_stages) device_->finish();
    return;
  }
  refresh_host();
  if (exchange_) {
    last_good_ = owned_particles(shown_in_frames);
  } else {
    last_good_.assign_fields(state_.particles, shown_in_frames);
  }
}

// On a device the last good state is there: the view holds the host's copy of it.
template <int D>
FluidView ParticleFluid<D>::last_good_view() const {
  if (!device_) return view_of(last_good_);
  auto good = std::make_shared<ParticleSet<D>>(state_.particles);
  device_->download_remembered(*good);
  FluidView view = view_of(*good);
  view.keeps = std::move(good);
  return view;
}

// The class is instantiated in particle_fluid.cpp; these are its members defined here.
template FluidView ParticleFluid<2>::view_of(const ParticleSet<2>&) const;
template FluidView ParticleFluid<2>::view() const;
template std::optional<std::string> ParticleFluid<2>::check(const StepClock&) const;
template void ParticleFluid<2>::remember_good(double);
template FluidView ParticleFluid<2>::last_good_view() const;
template FluidView ParticleFluid<3>::view_of(const ParticleSet<3>&) const;
template FluidView ParticleFluid<3>::view() const;
template std::optional<std::string> ParticleFluid<3>::check(const StepClock&) const;
template void ParticleFluid<3>::remember_good(double);
template FluidView ParticleFluid<3>::last_good_view() const;

}  // namespace sluice
