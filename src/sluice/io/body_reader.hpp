// Reading the `bodies` list of a case file and the contact materials of walls.
#pragma once

#include <vector>

#include "sluice/io/body_config.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/yaml_reader.hpp"

namespace sluice::io {

// What reading a body needs from the rest of the case.
struct BodyContext {
  std::string case_file;  // a mesh's or motion table's path is taken relative to its folder
  double gravity = 0;     // its magnitude [m/s^2] (a wavemaker's waves)
  double floor = 0;       // the domain's lowest z (a wavemaker's water depth is above it)
};

// Reads one entry of `bodies` (loading its mesh or motion table). Throws InputError naming the
// file, line and key.
BodyConfig read_body(MapReader& body, std::size_t index, const BodyContext& context);

// Reads one entry of `joints` (docs/case-format.md, "Joints"); its bodies are checked by name
// when the bodies are built.
JointConfig read_joint(MapReader& joint, std::size_t index);

// Reads the `contact` mapping's velocity-level step settings (`complementarity`).
void read_velocity_step(MapReader& contact, ContactConfig& config);

// Reads an optional `material` mapping (young, poisson, restitution, friction) over `fallback`.
ContactMaterial read_material(MapReader& owner, const ContactMaterial& fallback);

// The pose table of a prescribed motion: a CSV file with a header naming its columns among
// time, x, y, z, rx_deg, ry_deg, rz_deg (time required; missing columns are zero), one row per
// pose, strictly increasing in time. Problems are reported at `key` of `owner`.
std::vector<PoseSample> read_pose_table(const std::string& path, const MapReader& owner,
                                        const std::string& key);

}  // namespace sluice::io
