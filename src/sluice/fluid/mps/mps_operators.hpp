// The MPS discrete operators at particle i over its neighbours (Koshizuka & Oka 1996), with
// the weight w and the full-lattice constants n0 and lambda (kernels/mps_weight.hpp):
//   number density  n_i = sum_j w_ij
//   Laplacian       <lap f>_i = 2d / (lambda n0) sum_j (f_j - f_i) w_ij
//   divergence      <div u>_i = d / n0 sum_j (u_j - u_i) . r_ij / |r_ij|^2 w_ij
//   gradient        <grad p>_i = d / n0 sum_j (p_j - p^_i) r_ij / |r_ij|^2 w_ij, with p^_i the
//                   smallest p among i and its neighbours, so the pressure force only repels;
//                   by default d / n0 is replaced by the inverse of the corrective matrix
//                   C_i = sum_j w_ij r_ij r_ij^T / |r_ij|^2 (Khayyer & Gotoh 2011), without
//                   which the repulsive bias of p^ lets a still tank's pressure sag by 10 %.
//                   Where i's neighbourhood is one-sided (near a free surface) the caller may
//                   measure against p_i instead of p^_i: see MpsParameters::minimum_density.
// Here r_ij = r_j - r_i. `include(j)` picks the neighbours an operator sums over (the dummy
// wall layers count in the number density only).
#pragma once

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "sluice/core/host_device.hpp"
#include "sluice/fluid/mps/neighbour_view.hpp"
#include "sluice/kernels/mps_weight.hpp"

namespace sluice {

template <int D>
class NeighbourList;  // neighbour_list.hpp, for the host's constructors

// Over plain arrays (positions, the neighbour list's view), so that a loop body on the host or on
// a device applies them the same way (mps_loop_bodies.hpp).
template <int D>
class MpsOperators {
 public:
  MpsOperators(const std::vector<Vec<D>>& positions, const NeighbourList<D>& neighbours,
               MpsWeight weight, MpsLatticeConstants lattice, bool gradient_correction = true)
      : MpsOperators(positions.data(), neighbours.view(), weight, lattice, weight, lattice,
                     gradient_correction) {}
  // With a Laplacian of its own, wider radius (Koshizuka & Oka 1996: 2.1 l0 for the number
  // density and the gradient, 4.0 l0 for the Laplacian).
  MpsOperators(const std::vector<Vec<D>>& positions, const NeighbourList<D>& neighbours,
               MpsWeight weight, MpsLatticeConstants lattice, MpsWeight laplacian_weight,
               MpsLatticeConstants laplacian_lattice, bool gradient_correction)
      : MpsOperators(positions.data(), neighbours.view(), weight, lattice, laplacian_weight,
                     laplacian_lattice, gradient_correction) {}
  MpsOperators(const Vec<D>* positions, NeighbourView neighbours, MpsWeight weight,
               MpsLatticeConstants lattice, MpsWeight laplacian_weight,
               MpsLatticeConstants laplacian_lattice, bool gradient_correction)
      : corrected_(gradient_correction),
        x_(positions),
        neighbours_(neighbours),
        w_(weight),
        laplacian_w_(laplacian_weight),
        lattice_(lattice),
        laplacian_factor_(2.0 * D / (laplacian_lattice.lambda * laplacian_lattice.n0)),
        vector_factor_(D / lattice.n0) {}

  SLUICE_HOST_DEVICE const MpsLatticeConstants& lattice() const { return lattice_; }
  SLUICE_HOST_DEVICE const NeighbourView& neighbours() const { return neighbours_; }
  SLUICE_HOST_DEVICE const Vec<D>& position(std::size_t i) const { return x_[i]; }
  // w_ij, the weight of j in i's number density.
  SLUICE_HOST_DEVICE Real weight(std::size_t i, std::size_t j) const {
    return w_((x_[j] - x_[i]).norm());
  }
  // The coefficient of (f_j - f_i) in the Laplacian: 2d / (lambda n0) w_ij.
  SLUICE_HOST_DEVICE Real laplacian_coefficient(std::size_t i, std::size_t j) const {
    return laplacian_factor_ * laplacian_w_((x_[j] - x_[i]).norm());
  }

  // The number density and how many neighbours lie within r_e.
  template <class Include>
  SLUICE_HOST_DEVICE Real number_density(std::size_t i, Include&& include, int& count) const {
    Real n = 0;
    count = 0;
    neighbours_.for_each(i, [&](std::size_t j) {
      if (!include(j)) return;
      const Real w = w_((x_[j] - x_[i]).norm());
      if (w <= 0) return;
      n += w;
      ++count;
    });
    return n;
  }

  template <class T, class Include>
  SLUICE_HOST_DEVICE T laplacian(std::size_t i, const T* f, Include&& include) const {
    T sum = f[i] - f[i];  // zero of the field's type
    neighbours_.for_each(i, [&](std::size_t j) {
      if (include(j)) sum += (f[j] - f[i]) * laplacian_w_((x_[j] - x_[i]).norm());
    });
    return laplacian_factor_ * sum;
  }
  template <class T, class Include>
  T laplacian(std::size_t i, const std::vector<T>& f, Include&& include) const {
    return laplacian(i, f.data(), include);
  }

  template <class Include>
  SLUICE_HOST_DEVICE Real divergence(std::size_t i, const Vec<D>* u, Include&& include) const {
    Real sum = 0;
    neighbours_.for_each(i, [&](std::size_t j) {
      if (!include(j)) return;
      const Vec<D> r = x_[j] - x_[i];
      const Real r2 = r.squaredNorm();
      const Real w = w_(std::sqrt(r2));
      if (w > 0) sum += (u[j] - u[i]).dot(r) / r2 * w;
    });
    return vector_factor_ * sum;
  }
  template <class Include>
  Real divergence(std::size_t i, const std::vector<Vec<D>>& u, Include&& include) const {
    return divergence(i, u.data(), include);
  }

  // `plain`: the d / n0 form even where the corrective matrix is on (free-surface particles,
  // whose one-sided neighbourhood the matrix would turn into an outsized push). `minimum`:
  // measured against p^_i; else against p_i.
  template <class Include>
  SLUICE_HOST_DEVICE Vec<D> gradient(std::size_t i, const Real* p, Include&& include,
                                     bool plain = false, bool minimum = true) const {
    Real lowest = p[i];
    if (minimum)
      neighbours_.for_each(i, [&](std::size_t j) {
        if (include(j) && w_((x_[j] - x_[i]).norm()) > 0) lowest = std::min(lowest, p[j]);
      });
    Vec<D> sum = Vec<D>::Zero();
    Eigen::Matrix<Real, D, D> moment = Eigen::Matrix<Real, D, D>::Zero();
    neighbours_.for_each(i, [&](std::size_t j) {
      if (!include(j)) return;
      const Vec<D> r = x_[j] - x_[i];
      const Real r2 = r.squaredNorm();
      const Real w = w_(std::sqrt(r2));
      if (w <= 0) return;
      sum += ((p[j] - lowest) * w / r2) * r;
      moment += (w / r2) * r * r.transpose();
    });
    // The corrective matrix: exact for a linear field on any particle arrangement, where
    // the plain d / n0 is exact on the full lattice only. A particle with too few neighbours
    // to span every direction keeps the plain form.
    if (corrected_ && !plain &&
        std::abs(moment.determinant()) > 1e-3 * std::pow(lattice_.n0 / D, D))
      return moment.inverse() * sum;
    return vector_factor_ * sum;
  }
  template <class Include>
  Vec<D> gradient(std::size_t i, const std::vector<Real>& p, Include&& include, bool plain = false,
                  bool minimum = true) const {
    return gradient(i, p.data(), include, plain, minimum);
  }

 private:
  bool corrected_;
  const Vec<D>* x_;
  NeighbourView neighbours_;
  MpsWeight w_, laplacian_w_;
  MpsLatticeConstants lattice_;
  Real laplacian_factor_;
  Real vector_factor_;
};

}  // namespace sluice
