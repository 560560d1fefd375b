// Reading `boundaries:` entries (docs/case-format.md, "Open boundaries").
#pragma once

#include "sluice/geometry/axis_box.hpp"
#include "sluice/io/boundary_config.hpp"
#include "sluice/io/yaml_reader.hpp"

namespace sluice::io {

// One entry, index `index` of the list, of a case of `dimension` over `domain`. A speed table's
// path is relative to the case file. Throws InputError naming the key.
BoundaryConfig read_boundary(MapReader& map, std::size_t index, const AxisBox& domain,
                             int dimension, const std::string& case_file);

// One `type: periodic` entry, index `index` of the list, of a case of `dimension`: its axis,
// horizontal. Throws InputError naming the key.
PeriodicAxis read_periodic(MapReader& map, std::size_t index, int dimension);

// The speed table's rows (columns `time`, `speed`), sorted in time; problems name `key` of
// `owner`.
std::vector<std::pair<double, double>> read_speed_table(const std::string& path,
                                                        const MapReader& owner,
                                                        const std::string& key);

// Reads one entry of `damping` (docs/case-format.md, "Damping zones"); its ends must lie in
// the domain. Throws InputError naming the key.
DampingZone read_damping_zone(MapReader& map, std::size_t index, const AxisBox& domain,
                              int dimension);

}  // namespace sluice::io
