// Where a run's loops run (`--device`, `Simulation(device=...)`): the CPU, a GPU, or the GPU's
// code emulated on the CPU. The choice is the model's `device` key; a model that runs only on the
// CPU has no such key, so the choice is checked against the models first.
#pragma once

#include <string>

#include "sluice/io/case_config.hpp"

namespace sluice {

// cpu, gpu or emulated.
bool is_device_name(const std::string& device);

// Throws InputError naming `option` when `device` is none of cpu, gpu and emulated, or when the
// case's model does not run on it ("--device: the gpu device runs the wcsph model only, not
// 'mac'").
void check_device(const io::CaseConfig& config, const std::string& device,
                  const std::string& option);

// Whether putting the case on `device` sets its model's `device` key: always but for the CPU,
// which a model that runs only there has no key for (and which a case that names another
// device is put back on).
bool sets_model_device(const io::CaseConfig& config, const std::string& device);

}  // namespace sluice
