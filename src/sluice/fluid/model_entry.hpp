// What sluice knows of a fluid model, as one registry entry: how to build it from a case, what
// it changes in the case first, how its memory grows, and where its loops run. Each model's
// folder returns its own entry (wcsph_entry<D>() ...); fluid/model_registry.hpp finds them by name.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/linear/hypre_session.hpp"
#include "sluice/parallel/communicator.hpp"

namespace sluice {

// What the process lends a model beyond its case and its bodies: the session of MPI and hypre
// in which hypre's solvers run (null in a process without one: linear/sparse_solver.hpp).
struct ModelServices {
  HypreSession* hypre = nullptr;
  // The run's ranks (mpirun); none: this process alone.
  const Communicator* ranks = nullptr;
  bool split() const { return ranks != nullptr && ranks->split(); }
};

// Reads the model's parameters from the case (throws InputError) and builds it, ready to step.
using FluidFactory = std::function<std::unique_ptr<FluidSystem>(
    const io::CaseConfig&, const BodyGeometry&, const ModelServices&)>;

// What a model changes in the case before anything is built: bodies it adds to the case's own
// (penalty-sph: the grains of its free solid layers), the contact method it needs (granular).
// Throws InputError.
using CasePreparation = std::function<void(io::CaseConfig&)>;

// What a model's memory grows with, to size a case before anything is built (sim/size_estimate).
struct ModelSize {
  std::string element_name = "particles";
  // Resident memory per element, measured (docs/output.md); unknown: the largest of those shipped.
  double bytes_per_element = 6000;
  // The elements of a case where they are not the particles of its geometry (a grid's cells);
  // empty: the particles of its fluid blocks, wall layers and bodies.
  std::function<double(const io::CaseConfig&)> elements;
  // Memory per element of the model's device run, by dimension: a GPU's, or on the emulated
  // device host memory beside the host's own copy; empty where the model has no device run.
  std::function<double(int dimension)> device_bytes_per_element;
};

// Everything sluice knows of a model: how to build it, what it changes in the case, its size,
// where its loops can run ("cpu", "gpu", "emulated": `model.device`, `--device`), and the
// coupling schemes it supports with bodies (coupling/coupling_scheme.hpp; the first unless the
// case's `coupling.scheme` picks another).
struct ModelEntry {
  FluidFactory make;
  CasePreparation prepare;  // empty: the case as it is
  ModelSize size;
  std::vector<std::string> devices = {"cpu"};
  std::vector<std::string> schemes = {"held-loads"};
  // Whether its particles split over several ranks (ParticleFluid::distribute); empty: it runs
  // on one, and the reason it cannot on more (a run on several ranks is refused with it).
  std::string one_rank_only = "it has no decomposition over ranks";
  // Whether it takes the case's open boundaries (inlets, outlets); a case with one and a model
  // without is refused.
  bool open_boundaries = false;
  // Whether it takes a periodic axis (`type: periodic`); a case with one and a model without is
  // refused.
  bool periodic = false;
  // Whether it takes the case's damping zones; a case with one and a model without is refused.
  bool damping_zones = false;
};

}  // namespace sluice
