// A cone complementarity problem (CCP), the velocity-level step of contact, friction and joints
// (Anitescu & Tasora, Comput. Optim. Appl. 47, 2010): impulses gamma, each block in its cone
// (a contact's friction cone) or within its bounds (a joint row, a motor), minimising
//   f(gamma) = 1/2 gamma^T N gamma + r^T gamma,  N = D^T M^-1 D + E,  r = D^T v* - target,
// where v* are the bodies' velocities predicted without the impulses and E the diagonal
// compliance of regularised rows (zero for contacts and joints). Its gradient N gamma + r
// is the rows' velocities after the impulses less what they ask for; the solution meets every
// row in the complementarity sense. N is never formed: a product with it is one pass of the
// groups' impulses onto the bodies and one pass back (matrix-free, as in Mazhar et al. 2015).
#pragma once

#include <span>
#include <vector>

#include "sluice/ccp/ccp_bodies.hpp"
#include "sluice/ccp/constraint_group.hpp"

namespace sluice {

class CcpProblem {
 public:
  CcpBodies bodies;  // with the predicted velocities v*

  // Adds a group of unknowns (not owned: it must outlive the solve).
  void add(ConstraintGroup& group);
  void clear_groups();
  std::size_t size() const { return size_; }
  // The groups in order, and each one's first unknown.
  const std::vector<ConstraintGroup*>& groups() const { return groups_; }
  const std::vector<std::size_t>& offsets() const { return offsets_; }

  // g = D^T u + E gamma - target for the velocities u = v* + M^-1 D gamma, which it also
  // returns (E: the compliance of regularised rows, zero for the others).
  void gradient(std::span<const Real> gamma, std::span<Real> g, BodyVelocities& u) const;
  void project(std::span<Real> gamma) const;
  void diagonal(std::span<Real> out) const;
  void warm_start(std::span<Real> gamma) const;
  void store(std::span<const Real> gamma);

 private:
  std::vector<ConstraintGroup*> groups_;
  std::vector<std::size_t> offsets_;
  std::size_t size_ = 0;
};

}  // namespace sluice
