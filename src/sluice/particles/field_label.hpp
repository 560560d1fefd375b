// What a field is: its name (as output writes it), its unit, and whether frames show it.
#pragma once

#include <string>

namespace sluice {

struct FieldLabel {
  std::string name;
  std::string unit;  // SI: "m", "m/s", "kg/m^3", "Pa", "kg", "1" for a number without unit
  bool output = false;
};

// Whether a frame needs this field: those marked for output, the positions, and the body points
// (for the `body` array). The divergence guard's last good state keeps these.
inline bool shown_in_frames(const FieldLabel& label) {
  return label.output || label.name == "position" || label.name == "body_point";
}

}  // namespace sluice
