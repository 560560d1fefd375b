// The particle level set (Enright, Fedkiw, Ferziger & Mitchell, JCP 183, 2002): marker
// particles on both sides of the surface, carried by the flow, remember where the water was.
// Where the grid's level set has smeared the surface away (thin sheets, sharp corners), a
// particle that finds itself on the wrong side by more than its radius has escaped, and its
// sphere puts the surface back.
#pragma once

#include <vector>

#include "sluice/fluid/mac/mac_grid.hpp"

namespace sluice {

template <int D>
class ParticleLevelSet {
 public:
  // `per_cell` particles of each sign in every cell within `band` cells of the surface.
  explicit ParticleLevelSet(int per_cell, Real band = 3) : per_cell_(per_cell), band_(band) {}

  // Adds particles to the cells of the band that hold fewer than `per_cell`, drawn towards a
  // random level of their side, and drops those that have left the band.
  void reseed(const MacGrid<D>& grid, const CellField& phi);
  // Moves every particle with the flow (midpoint rule).
  void advect(const MacGrid<D>& grid, const FaceField<D>& u, Real dt);
  // Rebuilds phi near the escaped particles from their spheres; returns how many escaped.
  std::size_t correct(const MacGrid<D>& grid, CellField& phi) const;
  // After reinitialisation: each particle's radius from its distance to the surface, and the
  // particles still escaped by more than 1.5 radii dropped.
  void adjust_radii(const MacGrid<D>& grid, const CellField& phi);
  // After phi was raised by `shift` everywhere (now `phi`): each particle moved along the
  // normal so that it keeps its level, and no sphere takes the shift back.
  void follow_shift(const MacGrid<D>& grid, const CellField& phi, Real shift);

  std::size_t size() const { return markers_.size(); }
  // Positions and signs, for the output and the tests.
  std::vector<Vec<D>> positions() const;
  std::vector<int> signs() const;

  // Checkpoints: the markers in their order and the seed of the next reseed.
  void archive_state(StateArchive& a) { a(markers_, seed_counter_); }

 private:
  struct Marker {
    Vec<D> x;
    Real radius;
    int sign;  // +1 in the air, -1 in the water
    void archive_state(StateArchive& a) { a(x, radius, sign); }
  };
  int per_cell_;
  Real band_;
  std::vector<Marker> markers_;
  unsigned long seed_counter_ = 0;
};

}  // namespace sluice
