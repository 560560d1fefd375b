// What a field is: its name (as output writes it), its unit, and whether frames show it.
#pragma once

#include <string>

namespace sluice {

struct FieldLabel {
  std::string name;
  std::string unit;  // SI: "m", "m/s", "kg/m^3", "Pa", "kg", "1" for a number without unit
  bool output = false;
};

}  // namespace sluice
