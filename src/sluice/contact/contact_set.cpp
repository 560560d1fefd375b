#include "sluice/contact/contact_set.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {

namespace {
const double kSameContact = std::sqrt(0.5);  // cos 45 degrees: pairs of one contact
constexpr double kSameIdentity = 0.5;        // cos 60 degrees: a contact and its successor
}  // namespace

void ContactSet::begin_pass() {
  last_.swap(contacts_);
  contacts_.clear();
  first_normal_.clear();
  body_pair_begin_ = 0;
  // Where each body pair's contacts lie in the last pass (they arrived together).
  last_range_.clear();
  for (std::size_t k = 0; k < last_.size(); ++k) {
    const auto range = last_range_.try_emplace(key(last_[k].a, last_[k].b), k, k).first;
    range->second.second = k + 1;
  }
}

void ContactSet::add(std::size_t a, std::size_t b, const ParticlePair& pair) {
  if (body_pair_begin_ < contacts_.size() &&
      (contacts_[body_pair_begin_].a != a || contacts_[body_pair_begin_].b != b)) {
    body_pair_begin_ = contacts_.size();
  }
  std::size_t slot = body_pair_begin_;
  while (slot < contacts_.size() && first_normal_[slot].dot(pair.normal) < kSameContact) ++slot;
  if (slot == contacts_.size()) {
    contacts_.emplace_back();
    contacts_.back().a = a;
    contacts_.back().b = b;
    first_normal_.push_back(pair.normal);
  }
  Contact& c = contacts_[slot];
  // A pair that only comes near (complementarity's envelope) weighs nothing.
  const double overlap = std::max(pair.overlap, 0.0);
  const double w = overlap * std::sqrt(overlap) * pair.area;
  c.overlap = std::max(c.overlap, pair.overlap);
  c.area += pair.area;
  c.weight += w;
  c.point += w * pair.point;
  c.normal += w * pair.normal;
  c.pairs.push_back(pair);
}

void ContactSet::end_pass() {
  std::vector<bool> taken(last_.size(), false);
  for (Contact& c : contacts_) {
    if (c.weight > 0) {
      c.point /= c.weight;
    } else {  // pairs near but none overlapping: their plain mean
      c.point = c.normal = Vec3::Zero();
      for (const ParticlePair& p : c.pairs) {
        c.point += p.point / double(c.pairs.size());
        c.normal += p.normal;
      }
    }
    c.normal.normalize();
    // The closest-turned contact of the last pass between the same bodies, if any is near.
    std::size_t match = last_.size();
    double best = kSameIdentity;
    const auto range = last_range_.find(key(c.a, c.b));
    const std::size_t begin = range == last_range_.end() ? 0 : range->second.first;
    const std::size_t end = range == last_range_.end() ? 0 : range->second.second;
    for (std::size_t k = begin; k < end; ++k) {
      if (taken[k]) continue;
      const double alignment = last_[k].normal.dot(c.normal);
      if (alignment > best) {
        best = alignment;
        match = k;
      }
    }
    if (match < last_.size()) {
      taken[match] = true;
      c.id = last_[match].id;
      c.tangential = last_[match].tangential;
    } else {
      c.id = next_id_++;
    }
  }
}

}  // namespace sluice
