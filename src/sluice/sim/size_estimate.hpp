// How large a case is before anything is built: particles (or grid cells) counted from the
// geometry, and the memory they need. A spacing typed a hundred times too small would otherwise
// allocate for minutes before failing; the estimate refuses it at once.
#pragma once

#include <string>

#include "sluice/exec/gpu_devices.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/models/shipped_models.hpp"

namespace sluice {

struct SizeEstimate {
  std::string element_name;  // "particles" or "cells"
  double elements = 0;       // an upper bound: fluid blocks, wall layers, bodies' volumes
  double bytes = 0;          // elements times the model's measured bytes per element
};

// Counts without allocating (a double: a bad spacing may give more than 2^64), with the model's
// size as `models` (or sluice's shipped models) register it.
SizeEstimate estimate_size(const io::CaseConfig& config, const ModelRegistry& models);
SizeEstimate estimate_size(const io::CaseConfig& config);

// The machine's physical memory in bytes (0 when it cannot be read).
double machine_memory_bytes();

// "15.5 GB": bytes in the largest unit that keeps them above 1.
std::string readable_bytes(double bytes);

// Throws InputError at the case's `spacing` when the estimate exceeds `available` bytes.
void refuse_if_it_cannot_fit(const io::CaseConfig& config, const SizeEstimate& estimate,
                             double available);

// Whether the case runs its model on a GPU (model.device: gpu, or `--device gpu`) and the model
// has a GPU run.
bool runs_on_a_gpu(const io::CaseConfig& config, const ModelRegistry& models);
bool runs_on_a_gpu(const io::CaseConfig& config);  // with sluice's shipped models

// Throws InputError at the case's `spacing` when the estimate's elements need more of the
// GPU's memory (the model's device_bytes_per_element) than `gpu` has free; nothing when its free
// memory is unknown (0) or the model has no GPU run.
void refuse_if_the_gpu_cannot_hold(const io::CaseConfig& config, const SizeEstimate& estimate,
                                   const exec::DeviceMemory& gpu, const ModelRegistry& models);
void refuse_if_the_gpu_cannot_hold(const io::CaseConfig& config, const SizeEstimate& estimate,
                                   const exec::DeviceMemory& gpu);  // with the shipped models

// Both, against this machine: its memory, and its GPU's where the case runs on one.
void refuse_if_it_cannot_fit_here(const io::CaseConfig& config, const SizeEstimate& estimate);

}  // namespace sluice
