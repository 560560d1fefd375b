#include "sluice/sim/device_choice.hpp"

#include <algorithm>
#include <vector>

#include "sluice/core/errors.hpp"
#include "sluice/models/shipped_models.hpp"

namespace sluice {

bool is_device_name(const std::string& device) {
  return device == "cpu" || device == "gpu" || device == "emulated";
}

void check_device(const io::CaseConfig& config, const std::string& device,
                  const std::string& option) {
  if (!is_device_name(device)) {
    throw InputError(option + ": expected cpu, gpu or emulated, got '" + device + "'");
  }
  if (device == "cpu") return;
  const std::vector<std::string> models = shipped_models(config.dimension).names_on(device);
  if (std::find(models.begin(), models.end(), config.model_name) != models.end()) return;
  std::string names;  // "wcsph", "mps and wcsph", "a, b and c"
  for (std::size_t k = 0; k < models.size(); ++k) {
    names += (k == 0 ? "" : k + 1 == models.size() ? " and " : ", ") + models[k];
  }
  throw InputError(option + ": the " + device + " device runs the " + names + " model" +
                   (models.size() == 1 ? "" : "s") + " only, not '" + config.model_name + "'");
}

bool sets_model_device(const io::CaseConfig& config, const std::string& device) {
  return device != "cpu" || static_cast<bool>(config.model["device"]);
}

}  // namespace sluice
