// The particles' traffic between ranks at each step's neighbour stage, in the shape of Cabana's
// distributor and halo plans: the ghosts of the last step go (with the neighbour sort); the
// particles that left this rank's region go to the rank whose region they entered (migration);
// then every rank whose region comes within the halo's depth of a particle gets a copy of it, a
// ghost, which the model reads as a neighbour and never counts (its `owned_kind` is -1). Every
// field travels, the model's own too, so a ghost is its owner's particle as the neighbour stage
// found it; a stage after it that changes a field a later one reads at the ghosts (MPS's pressure,
// solved over the ranks) brings them up to date with refresh(), the halo plan's gather.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "sluice/core/stage_timer.hpp"
#include "sluice/core/state_archive.hpp"
#include "sluice/parallel/communicator.hpp"
#include "sluice/parallel/decomposition.hpp"
#include "sluice/parallel/rcb_partition.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

// What the last exchange moved.
struct ExchangeCounts {
  std::size_t sent = 0;      // particles that left for another rank
  std::size_t received = 0;  // and those that came in
  std::size_t ghosts = 0;    // copies of other ranks' particles now held
};

// What the exchanges took over a run, on this rank.
struct ExchangeTotals {
  long exchanges = 0;
  double migrated = 0, ghosts = 0;  // particles, summed over the exchanges
  // Waiting for the other ranks to reach the exchange (their work is larger), then the
  // exchange's own parts.
  double wait_seconds = 0, migration_seconds = 0, halo_seconds = 0, balance_seconds = 0;
  int balances = 0;  // the times the regions moved
};

// Balancing on counted work: every `interval` exchanges the ranks compare their work, and where
// the busiest has more than `tolerance` times the mean the regions are drawn anew with an equal
// share of it each: slabs by shift balancing (LAMMPS's `balance shift`), their cuts moved along
// the axis; boxes by Zoltan's RCB over the particles where they now stand. A particle's work is
// counted, not timed, so that a run (and a resumed one) takes the same cuts on any machine: a fluid
// particle's is 1, any other's `other_work` (its loops are a wall's extrapolation or nothing).
struct BalancePolicy {
  int interval = 50;
  double tolerance = 1.1;
  double other_work = 0.1;
  double work(bool fluid) const { return fluid ? 1.0 : other_work; }
  int bins_per_rank = 64;  // the histogram of work along the axis the cuts are placed on
};

// Two sides of the domain joined (a periodic axis): along `axis` (of the particles' D axes) a
// particle that leaves [lo, hi) through one side comes back through the other, and a particle
// within the halo's depth of one side is seen, as a ghost shifted by the span's length, beyond
// the other. The ghosts travel as any others (to this rank too), so that a model reads a
// periodic neighbour as it reads another rank's.
struct PeriodicSpan {
  int axis = 0;
  Real lo = 0, hi = 0;
  Real length() const { return hi - lo; }
};

template <int D>
class ParticleExchange {
 public:
  // `owned_kind` is a field of the set: a particle's kind where this rank owns it, -1 for a
  // ghost.
  ParticleExchange(Communicator ranks, Decomposition regions, Real halo_depth,
                   FieldHandle<std::int32_t> owned_kind, BalancePolicy balance = {})
      : ranks_(ranks),
        regions_(std::move(regions)),
        depth_(halo_depth),
        owned_kind_(owned_kind),
        balance_(balance) {}

  // Joins the two sides along `span.axis` (before start()): particles (a body's excepted) wrap
  // round, and those within the halo's depth of a side are copied beyond the other.
  void join_sides(const PeriodicSpan& span) { periodic_ = span; }

  // From the whole case, which every rank built alike: keeps this rank's region and takes its
  // ghosts.
  void start(ParticleSet<D>& ps) {
    std::vector<std::uint32_t> keep;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (regions_.owner(ps.position[i]) == ranks_.rank())
        keep.push_back(static_cast<std::uint32_t>(i));
    }
    ps.keep(keep);
    auto& owned = ps[owned_kind_];
    for (std::size_t i = 0; i < ps.size(); ++i) owned[i] = static_cast<std::int32_t>(ps.kind[i]);
    counts_ = {};
    gone_.assign(ps.size(), false);
    take_ghosts(ps);
  }

  // Moves the regions where the work calls for it (every balance interval), sends away what
  // left this rank's region and takes in what entered it, and takes the ghosts anew. The ghosts of
  // the last exchange and the particles sent away stay in the set, marked in gone(): the neighbour
  // sort that follows drops them (one copy of the set, not two).
  // With `also_gone` (sized to the set), the particles it marks go too (those that left the
  // domain through an outlet), neither sent nor copied.
  void exchange(ParticleSet<D>& ps, const std::vector<bool>* also_gone = nullptr) {
    ++totals_.exchanges;
    gone_.assign(ps.size(), false);
    if (also_gone != nullptr && also_gone->size() == ps.size()) gone_ = *also_gone;
    add_seconds(totals_.wait_seconds, [&] { ranks_.barrier(); });
    if (++since_balance_ >= balance_.interval) {
      since_balance_ = 0;
      add_seconds(totals_.balance_seconds, [&] { balance(ps); });
    }
    add_seconds(totals_.migration_seconds, [&] { migrate(ps); });
    add_seconds(totals_.halo_seconds, [&] { take_ghosts(ps); });
    totals_.migrated += static_cast<double>(counts_.sent);
    totals_.ghosts += static_cast<double>(counts_.ghosts);
  }

  // The neighbour sort after the exchange reordered the set (its particle k was order[k] of
  // the `old_size` before it): refresh()'s plan follows the particles.
  void follow(const std::vector<std::uint32_t>& order, std::size_t old_size) {
    constexpr std::uint32_t kDropped = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> now(old_size, kDropped);
    for (std::size_t k = 0; k < order.size(); ++k) now[order[k]] = static_cast<std::uint32_t>(k);
    for (auto* plan : {&sent_, &received_}) {
      for (auto& indices : *plan) {
        for (std::uint32_t& i : indices) i = now[i];
      }
    }
  }

  // Collective: each ghost's `fields` (arrays over the set, an entry a particle) set to its
  // owner's values now, as the last exchange's plan copied it.
  template <class... T>
  void refresh(std::vector<T>&... fields) const {
    // As ParticleSet::pack moves them: an entry's bytes (reals, integers, fixed-size vectors).
    constexpr std::size_t bytes = (sizeof(T) + ...);
    const auto at = [](auto& field, std::uint32_t i) {
      return reinterpret_cast<unsigned char*>(field.data()) + sizeof(field[0]) * i;
    };
    // A periodic ghost's position is its owner's shifted by the span's length.
    const auto copy_out = [&](auto& field, std::uint32_t i, Real shift, unsigned char*& out) {
      using Entry = std::decay_t<decltype(field[0])>;
      if constexpr (std::is_same_v<Entry, Vec<D>>) {
        if (shift != 0 && static_cast<const void*>(&field) == positions_) {
          Vec<D> x = field[i];
          x[periodic_->axis] += shift;
          std::memcpy(out, &x, sizeof(Entry));
          out += sizeof(Entry);
          return;
        }
      }
      std::memcpy(out, at(field, i), sizeof(Entry));
      out += sizeof(Entry);
    };
    std::vector<std::vector<unsigned char>> outgoing(sent_.size());
    for (std::size_t r = 0; r < sent_.size(); ++r) {
      outgoing[r].resize(sent_[r].size() * bytes);
      unsigned char* out = outgoing[r].data();
      for (std::size_t k = 0; k < sent_[r].size(); ++k) {
        const std::uint32_t i = sent_[r][k];
        const Real shift = sent_shift_[r].empty() ? 0 : sent_shift_[r][k];
        (copy_out(fields, i, shift, out), ...);
      }
    }
    const std::vector<std::vector<unsigned char>> incoming = ranks_.exchange(outgoing);
    for (std::size_t r = 0; r < received_.size(); ++r) {
      const unsigned char* in = incoming[r].data();
      for (const std::uint32_t i : received_[r]) {
        ((std::memcpy(at(fields, i), in, sizeof(T)), in += sizeof(T)), ...);
      }
    }
  }

  // Collective: Zoltan's RCB boxes over the particles of the set for which take(i) holds (each
  // particle taken on one rank only), weighted by their counted work.
  template <class Take>
  static Decomposition rcb_of(const Communicator& ranks, const ParticleSet<D>& ps,
                              const BalancePolicy& balance, Take&& take) {
    std::vector<double> points, work;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!take(i)) continue;
      for (int a = 0; a < D; ++a) points.push_back(ps.position[i][a]);
      work.push_back(balance.work(ps.is_fluid(i)));
    }
    return rcb_boxes(ranks, D, points, work);
  }

  const Decomposition& regions() const { return regions_; }
  Real depth() const { return depth_; }
  const ExchangeCounts& last() const { return counts_; }
  const ExchangeTotals& totals() const { return totals_; }
  // Whether each particle of the set is to go (see exchange()); after start(), none.
  const std::vector<bool>& gone() const { return gone_; }

  // Checkpoints: the regions (slabs' cuts or boxes), where balancing has moved them, and the
  // exchanges since the last balance.
  void archive_state(StateArchive& a) {
    std::vector<double> regions = regions_.regions();
    a(regions, since_balance_);
    if (a.reading()) regions_ = regions_.with_regions(regions);
  }
  // Reads past what archive_state wrote, keeping nothing (a checkpoint written on another
  // number of ranks, whose cuts are drawn anew).
  static void skip_archived_state(StateArchive& a) {
    std::vector<double> regions;
    int since_balance = 0;
    a(regions, since_balance);
  }

 private:
  // Sends away the particles this rank owns that left its region, and takes in those that
  // entered it; marks the ones sent, and the last exchange's ghosts, gone.
  void migrate(ParticleSet<D>& ps) {
    const std::size_t ranks = static_cast<std::size_t>(ranks_.size());
    std::vector<std::vector<std::uint32_t>> leaving(ranks);
    const auto& owned = ps[owned_kind_];
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (owned[i] < 0) {
        gone_[i] = true;
        continue;
      }
      if (gone_[i]) continue;
      // Every particle but a body's (the bodies place theirs) comes round: fluid, and an open
      // boundary's buffer particles beside the periodic sides.
      if (periodic_ && owned[i] != static_cast<std::int32_t>(ParticleKind::kBody))
        wrap(ps.position[i]);
      const int r = regions_.owner(ps.position[i]);
      if (r == ranks_.rank()) continue;
      leaving[static_cast<std::size_t>(r)].push_back(static_cast<std::uint32_t>(i));
      gone_[i] = true;
    }
    counts_ = {};
    for (const auto& l : leaving) counts_.sent += l.size();
    counts_.received = append(ps, ranks_.exchange(packed(ps, leaving)));
    gone_.resize(ps.size(), false);
  }

  // The work of the particles this rank owns, or of those in each bin of [lo, hi) along the
  // axis (`bins` non-empty).
  double owned_work(const ParticleSet<D>& ps, double lo, double hi,
                    std::vector<double>* bins) const {
    const auto& owned = ps[owned_kind_];
    double total = 0;
    const double scale = bins ? static_cast<double>(bins->size()) / (hi - lo) : 0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (owned[i] < 0) continue;
      const double work = balance_.work(owned[i] == 0);
      total += work;
      if (bins) {
        const double at = (ps.position[i][regions_.slabs().axis()] - lo) * scale;
        const auto k = static_cast<std::size_t>(std::clamp(at, 0.0, double(bins->size() - 1)));
        (*bins)[k] += work;
      }
    }
    return total;
  }

  // Draws the regions anew with equal shares of the work where the busiest rank has more than
  // the tolerance over the mean.
  void balance(const ParticleSet<D>& ps) {
    const double mine = owned_work(ps, 0, 1, nullptr);
    const double total = ranks_.sum(mine);
    if (!(ranks_.max(mine) > balance_.tolerance * total / ranks_.size())) return;
    if (regions_.is_slabs() && !shift_cuts(ps, total)) return;
    if (!regions_.is_slabs()) regions_ = rcb_of_owned(ps);
    ++totals_.balances;
  }

  // Zoltan's RCB boxes over the particles this rank owns, weighted by their work.
  Decomposition rcb_of_owned(const ParticleSet<D>& ps) const {
    const auto& owned = ps[owned_kind_];
    return rcb_of(ranks_, ps, balance_, [&](std::size_t i) { return owned[i] >= 0; });
  }

  // Slabs: the cuts moved to equal shares of the `total` work, from a histogram of the work
  // along the axis (summed over the ranks), each cut interpolated within its bin. False where
  // the particles stand in one plane across the axis (nothing to cut).
  bool shift_cuts(const ParticleSet<D>& ps, double total) {
    const int axis = regions_.slabs().axis();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const auto& owned = ps[owned_kind_];
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (owned[i] < 0) continue;
      lo = std::min(lo, double(ps.position[i][axis]));
      hi = std::max(hi, double(ps.position[i][axis]));
    }
    lo = ranks_.min(lo);
    hi = ranks_.max(hi);
    if (!(hi > lo)) return false;
    std::vector<double> bins(static_cast<std::size_t>(balance_.bins_per_rank * ranks_.size()));
    owned_work(ps, lo, hi, &bins);
    ranks_.sum(bins);
    std::vector<double> cuts;
    const double width = (hi - lo) / static_cast<double>(bins.size());
    double before = 0;  // the work in the bins below bin k
    std::size_t k = 0;
    for (int r = 1; r < ranks_.size(); ++r) {
      const double share = total * r / ranks_.size();
      while (k + 1 < bins.size() && before + bins[k] < share) before += bins[k++];
      const double into = bins[k] > 0 ? std::clamp((share - before) / bins[k], 0.0, 1.0) : 0.0;
      cuts.push_back(lo + width * (static_cast<double>(k) + into));
    }
    regions_ = Decomposition(SlabDecomposition(axis, std::move(cuts)));
    return true;
  }

  // A particle past a periodic side, brought back through the other.
  void wrap(Vec<D>& x) const {
    Real& c = x[periodic_->axis];
    if (c >= periodic_->hi) c -= periodic_->length();
    if (c < periodic_->lo) c += periodic_->length();
    if (c >= periodic_->hi) c = periodic_->lo;  // rounding put a point just below lo on hi
  }

  // Appends to the set the copies of the other ranks' particles within the halo's depth, and
  // with a periodic axis the copies, shifted, of every rank's particles within it of a side
  // (this rank's own too).
  void take_ghosts(ParticleSet<D>& ps) {
    const std::size_t before = ps.size();
    const auto ranks = static_cast<std::size_t>(ranks_.size());
    // By rank: the plain copies, and those shifted up and down by the periodic span.
    constexpr int kShifts = 3;
    std::vector<std::vector<std::uint32_t>> copies[kShifts];
    for (auto& c : copies) c.resize(ranks);
    const Real shifts[kShifts] = {0, periodic_ ? periodic_->length() : 0,
                                  periodic_ ? -periodic_->length() : 0};
    const auto& own = ps[owned_kind_];
    for (std::size_t i = 0; i < before; ++i) {
      if (own[i] < 0 || gone_[i]) continue;
      const auto index = static_cast<std::uint32_t>(i);
      regions_.for_each_rank_near(ps.position[i], depth_, ranks_.rank(), [&](int r) {
        copies[0][static_cast<std::size_t>(r)].push_back(index);
      });
      if (!periodic_) continue;
      const Real c = ps.position[i][periodic_->axis];
      const int shift = c < periodic_->lo + depth_ ? 1 : c >= periodic_->hi - depth_ ? 2 : 0;
      if (shift == 0) continue;
      Vec<D> image = ps.position[i];
      image[periodic_->axis] += shifts[shift];
      regions_.for_each_rank_near(image, depth_, -1, [&](int r) {
        copies[shift][static_cast<std::size_t>(r)].push_back(index);
      });
    }
    // One exchange for the plain copies and one for each shift (a packed buffer holds one
    // field after another, so a buffer's particles share theirs). refresh()'s plan: each rank's
    // copies, plain then shifted, with each one's shift (none without a periodic axis), and
    // where each rank's landed here, in the same order.
    positions_ = &ps.position;
    counts_.ghosts = 0;
    sent_.assign(ranks, {});
    received_.assign(ranks, {});
    sent_shift_.assign(ranks, {});
    for (int k = 0; k < (periodic_ ? kShifts : 1); ++k) {
      std::vector<std::vector<unsigned char>> outgoing(ranks);
      for (std::size_t r = 0; r < ranks; ++r) {
        const std::vector<std::uint32_t>& which = copies[k][r];
        sent_[r].insert(sent_[r].end(), which.begin(), which.end());
        if (periodic_) sent_shift_[r].resize(sent_[r].size(), shifts[k]);
        if (!which.empty()) pack_shifted(ps, which, shifts[k], outgoing[r]);
      }
      const std::vector<std::vector<unsigned char>> incoming = ranks_.exchange(outgoing);
      auto next = static_cast<std::uint32_t>(ps.size());
      counts_.ghosts += append(ps, incoming);
      for (std::size_t r = 0; r < ranks; ++r) {
        for (std::size_t n = incoming[r].size() / ps.bytes_per_particle(); n > 0; --n)
          received_[r].push_back(next++);
      }
    }
    auto& owned = ps[owned_kind_];
    for (std::size_t i = before; i < ps.size(); ++i) owned[i] = -1;
    gone_.resize(ps.size(), false);
  }

  // The particles `which` packed (appended to `buffer`) with their positions moved by `shift`
  // along the periodic axis; put back as they were after.
  void pack_shifted(ParticleSet<D>& ps, const std::vector<std::uint32_t>& which, Real shift,
                    std::vector<unsigned char>& buffer) const {
    if (shift == 0) return ps.pack(which, buffer);
    std::vector<Real> kept(which.size());
    for (std::size_t k = 0; k < which.size(); ++k) {
      Real& c = ps.position[which[k]][periodic_->axis];
      kept[k] = c;
      c += shift;
    }
    ps.pack(which, buffer);
    for (std::size_t k = 0; k < which.size(); ++k) ps.position[which[k]][periodic_->axis] = kept[k];
  }

  std::vector<std::vector<unsigned char>> packed(
      const ParticleSet<D>& ps, const std::vector<std::vector<std::uint32_t>>& which) const {
    std::vector<std::vector<unsigned char>> out(which.size());
    for (std::size_t r = 0; r < which.size(); ++r) {
      if (!which[r].empty()) ps.pack(which[r], out[r]);
    }
    return out;
  }

  // Appends what each rank sent, by rank; returns how many particles that was.
  std::size_t append(ParticleSet<D>& ps,
                     const std::vector<std::vector<unsigned char>>& incoming) const {
    const std::size_t bytes = ps.bytes_per_particle();
    std::size_t count = 0;
    for (const auto& buffer : incoming) {
      if (buffer.empty()) continue;
      ps.unpack_append(buffer.data(), buffer.size() / bytes);
      count += buffer.size() / bytes;
    }
    return count;
  }

  Communicator ranks_;
  Decomposition regions_;
  Real depth_;
  FieldHandle<std::int32_t> owned_kind_;
  BalancePolicy balance_;
  int since_balance_ = 0;  // exchanges since the last balance
  ExchangeCounts counts_;
  ExchangeTotals totals_;
  std::vector<bool> gone_;
  // The last take_ghosts' plan, by rank: this rank's particles copied to it, and the ghosts it
  // sent here (indices into the set, which follow() keeps up with the neighbour sort).
  std::vector<std::vector<std::uint32_t>> sent_, received_;
  // With a periodic axis: the span, each copy's shift along it (as sent_), and the set's
  // positions (the field whose refresh() shifts them).
  std::optional<PeriodicSpan> periodic_;
  std::vector<std::vector<Real>> sent_shift_;
  const void* positions_ = nullptr;
};

}  // namespace sluice
