// Case file reading: YAML text -> validated CaseConfig. The key layout is documented in
// docs/case-format.md; keep the two in step.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sluice/contact/contact_solvers.hpp"
#include "sluice/io/body_reader.hpp"
#include "sluice/io/boundary_reader.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice::io {

namespace {

const std::vector<std::string> kTankSides = {"x-", "x+", "y-", "y+", "z-", "z+"};

FluidConfig read_fluid(MapReader fluid, const CaseConfig& c) {
  FluidConfig out;
  out.density = fluid.optional_positive("density", out.density);
  out.kinematic_viscosity = fluid.optional_non_negative("viscosity", out.kinematic_viscosity);
  if (!fluid.has("blocks")) fluid.fail("blocks", "missing required key");
  for (auto& block : fluid.list_of_maps("blocks")) {
    FluidBlockConfig b;
    b.line = block.line();
    b.name = block.optional<std::string>("name", fmt::format("block{}", out.blocks.size()));
    b.box = read_box(block, c.dimension);
    b.velocity = block.optional<Vec3>("velocity", Vec3::Zero());
    const std::string outside = fmt::format("fluid block '{}' is not inside the domain", b.name);
    if (!c.domain.contains(b.box.min, c.dimension)) block.fail("min", outside);
    if (!c.domain.contains(b.box.max, c.dimension)) block.fail("max", outside);
    block.finish();
    out.blocks.push_back(b);
  }
  if (out.blocks.empty()) fluid.fail("blocks", "needs at least one fluid block");
  fluid.finish();
  return out;
}

WallConfig read_wall(MapReader& wall, const CaseConfig& c, size_t index) {
  WallConfig w;
  w.line = wall.line();
  const std::string type = wall.required<std::string>("type");
  w.name = wall.optional<std::string>("name", fmt::format("{}{}", type, index));
  if (type == "tank" || type == "box") {
    w.shape = type == "tank" ? WallShape::kTank : WallShape::kBox;
    w.box = read_box(wall, c.dimension);
    if (w.shape == WallShape::kTank) {
      w.open_sides = wall.optional<std::vector<std::string>>("open", {});
      for (const auto& side : w.open_sides) {
        if (std::find(kTankSides.begin(), kTankSides.end(), side) == kTankSides.end()) {
          wall.fail_choice("open", "side", side, kTankSides);
        }
      }
    }
  } else if (type == "plane") {
    w.shape = WallShape::kPlane;
    w.point = wall.required<Vec3>("point");
    w.normal = wall.required<Vec3>("normal");
    if (c.dimension == 2) w.normal[1] = 0;
    if (!(w.normal.norm() > 0)) wall.fail("normal", "must not be the zero vector");
    w.normal.normalize();
  } else {
    wall.fail_choice("type", "wall type", type, {"tank", "box", "plane"});
  }
  w.surface_velocity = wall.optional<Vec3>("surface_velocity", Vec3::Zero());
  w.material = read_material(wall, w.material);
  wall.finish();
  return w;
}

ProbeConfig read_probe(MapReader& probe, size_t index, const CaseConfig& c) {
  const int dimension = c.dimension;
  ProbeConfig p;
  p.line = probe.line();
  const std::string type = probe.required<std::string>("type");
  p.name = probe.optional<std::string>("name", fmt::format("{}{}", type, index));
  if (type == "pressure") {
    p.kind = ProbeKind::kPressure;
    p.point = probe.required<Vec3>("point");
  } else if (type == "water_height") {
    p.kind = ProbeKind::kWaterHeight;
    p.unit = "m";
    p.point = probe.required<Vec3>("point");
  } else if (type == "flux") {
    p.kind = ProbeKind::kBoundaryFlux;
    p.unit = dimension == 2 ? "m^2/s" : "m^3/s";
    const std::string name = probe.required<std::string>("boundary");
    std::vector<std::string> names;
    for (const BoundaryConfig& b : c.boundaries) names.push_back(b.name);
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) {
      if (names.empty()) probe.fail("boundary", "the case has no boundaries");
      probe.fail_choice("boundary", "boundary", name, names);
    }
    p.boundary = static_cast<std::size_t>(found - names.begin());
  } else if (type == "surge_front") {
    p.kind = ProbeKind::kSurgeFront;
    p.unit = "m";
    const std::string axis = probe.optional<std::string>("axis", "x");
    if (axis != "x" && axis != "y") probe.fail("axis", "expected x or y");
    if (axis == "y" && dimension == 2) {
      probe.fail("axis", "a 2D case lies in the x-z plane: the only horizontal axis is x");
    }
    p.axis = axis == "x" ? 0 : 1;
  } else {
    probe.fail_choice("type", "probe type", type,
                      {"pressure", "water_height", "surge_front", "flux"});
  }
  probe.finish();
  return p;
}

// `compare:` maps model names to the --set assignments of their runs. The names are checked
// against the models by `sluice compare`, which knows them.
std::vector<CompareEntry> read_compare(MapReader& top) {
  std::vector<CompareEntry> entries;
  MapReader compare = top.map("compare");
  const YAML::Node all = top.node("compare");
  for (const auto& item : all) {
    CompareEntry entry;
    entry.model = compare.key_name(item.first);
    entry.line = line_of(item.first);
    const YAML::Node settings = compare.node(entry.model);
    if (!settings.IsNull() && !settings.IsMap()) {
      compare.fail(entry.model, "must be a mapping of key paths to values, as --set takes them");
    }
    for (const auto& setting : settings) {
      YAML::Emitter value;
      value << YAML::Flow << setting.second;
      const std::string key = compare.key_name(setting.first);
      entry.settings.push_back(key + "=" + value.c_str());
      entry.sets_model = entry.sets_model || key == "model";
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

// A periodic axis joins its two sides: no other boundary on them, no wall across them (a tank
// open there, no plane wall facing along the axis, no box wall reaching past them).
void check_periodic(const CaseConfig& c) {
  const PeriodicAxis& p = *c.periodic;
  const std::string axis(1, "xyz"[p.axis]);
  for (const BoundaryConfig& b : c.boundaries) {
    if (b.axis == p.axis) {
      throw InputError(c.file(), b.line, b.key + ".side",
                       fmt::format("side {} is joined to the opposite side by {} (periodic)",
                                   b.side_name(), p.key));
    }
  }
  if (!c.bodies.empty()) {
    // A body near a side would need its own image beyond the other (the grid's solid faces,
    // the particle models' body points) and to be carried round: neither is built.
    throw InputError(c.file(), p.line, p.key + ".type",
                     "a case with a periodic axis has no bodies yet");
  }
  const double lo = c.domain.min[p.axis], hi = c.domain.max[p.axis];
  for (std::size_t w = 0; w < c.walls.size(); ++w) {
    const WallConfig& wall = c.walls[w];
    const std::string key = fmt::format("walls[{}]", w);
    if (wall.shape == WallShape::kTank &&
        (!wall.side_open(p.axis, false) || !wall.side_open(p.axis, true))) {
      throw InputError(c.file(), wall.line, key + ".open",
                       fmt::format("the tank closes a side that {} makes periodic: list {}- and "
                                   "{}+ in its open",
                                   p.key, axis, axis));
    }
    if (wall.shape == WallShape::kPlane && std::abs(wall.normal[p.axis]) > 1e-9) {
      throw InputError(c.file(), wall.line, key + ".normal",
                       fmt::format("a plane wall facing along the periodic axis ({}) would not "
                                   "repeat across its sides: its normal must be across {}",
                                   axis, axis));
    }
    if (wall.shape == WallShape::kBox && (wall.box.min[p.axis] < lo || wall.box.max[p.axis] > hi)) {
      throw InputError(c.file(), wall.line, key + (wall.box.min[p.axis] < lo ? ".min" : ".max"),
                       fmt::format("the box reaches past the domain's periodic sides along {} "
                                   "({} to {} m)",
                                   axis, lo, hi));
    }
  }
}

}  // namespace

AxisBox read_box(MapReader& map, int dimension) {
  AxisBox box{map.required<Vec3>("min"), map.required<Vec3>("max")};
  for (int a = 0; a < 3; ++a) {
    if (dimension == 2 && a == 1) continue;
    if (!(box.max[a] > box.min[a])) {
      map.fail("max",
               fmt::format("must be greater than 'min' in every component (axis {})", "xyz"[a]));
    }
  }
  return box;
}

namespace {

// The case's text as YAML prints it, less what a resumed run may change.
std::string identity_of(const YAML::Node& root) {
  if (!root.IsMap()) return {};
  YAML::Node copy = YAML::Clone(root);
  for (const char* key : {"end_time", "checkpoint_interval", "compare"}) copy.remove(key);
  // How the ranks share the bodies changes no answer (sim/island_sharing.hpp).
  if (YAML::Node ranks = copy["ranks"]; ranks.IsMap()) {
    ranks.remove("bodies");
    if (ranks.size() == 0) copy.remove("ranks");
  }
  YAML::Emitter out;
  out << copy;
  return out.c_str();
}

CaseConfig read_root(YAML::Node root, const std::string& file_name,
                     const std::vector<std::string>& overrides) {
  auto source = std::make_shared<YamlSource>();
  source->file = file_name;
  if (root.IsMap()) {
    for (const auto& assignment : overrides) {
      source->overridden_paths.insert(apply_override(root, assignment));
    }
  }

  CaseConfig c;
  c.source = source;
  c.identity = identity_of(root);
  // The dimension decides how vectors are read, so it is read first.
  {
    MapReader probe_dim(source, root, "", 1);
    const int dimension = probe_dim.required<int>("dimension");
    if (dimension != 2 && dimension != 3) probe_dim.fail("dimension", "must be 2 or 3");
    source->dimension = dimension;
    c.dimension = dimension;
  }
  MapReader top(source, root, "", 1);
  top.required<int>("dimension");
  c.name = top.optional<std::string>("name", std::filesystem::path(file_name).stem().string());
  c.spacing = top.required_positive("spacing");
  c.spacing_place = top.place_of("spacing");

  MapReader domain = top.map("domain");
  c.domain = read_box(domain, c.dimension);
  domain.finish();

  c.gravity = top.optional<Vec3>("gravity", c.dimension == 2 ? Vec3(0, 0, -9.81) : c.gravity);
  if (top.has("travel_direction")) {
    const Vec3 travel = top.required<Vec3>("travel_direction");
    const Vec3 across = c.gravity.norm() > 0
                            ? travel - travel.dot(c.gravity.normalized()) * c.gravity.normalized()
                            : travel;
    if (across.norm() <= 1e-9 * std::max(1.0, travel.norm())) {
      top.fail("travel_direction", travel.norm() == 0 ? "must not be zero"
                                                      : "must not be along gravity (it is the "
                                                        "horizontal direction the drag opposes)");
    }
    c.travel_direction = across.normalized();
  }
  c.end_time = top.required_positive("end_time");
  c.output_interval = top.required_positive("output_interval");
  c.probe_interval = top.optional_positive("probe_interval", c.output_interval / 10);

  size_t index = 0;
  for (auto& body : top.list_of_maps("bodies")) {
    c.bodies.push_back(read_body(body, index++, {file_name, c.gravity.norm(), c.domain.min[2]}));
    for (std::size_t k = 0; k + 1 < c.bodies.size(); ++k) {
      if (c.bodies[k].name == c.bodies.back().name) {
        body.fail("name",
                  fmt::format("'{}' is already the name of bodies[{}]", c.bodies[k].name, k));
      }
    }
  }
  index = 0;
  for (auto& joint : top.list_of_maps("joints")) c.joints.push_back(read_joint(joint, index++));
  c.body_interval = top.optional_positive("body_interval", c.probe_interval);
  c.checkpoint_interval = top.optional_non_negative("checkpoint_interval", 0);  // 0: none
  if (top.has("contact")) {
    MapReader contact = top.map("contact");
    // `solver` is the method's older name; both name a solver of the registry.
    for (const char* key : {"method", "solver"}) {
      if (!contact.has(key)) continue;
      const std::string name = contact.optional_choice(key, "penalty", "contact method",
                                                       shipped_contact_solvers().names());
      if (c.contact.method && *c.contact.method != name) {
        contact.fail(key, fmt::format("names another method than contact.method ({}): give one",
                                      *c.contact.method));
      }
      c.contact.method = name;
    }
    c.contact.distance = contact.optional_positive("distance", c.spacing);
    c.contact.substep_fraction =
        contact.optional_positive("substep_fraction", c.contact.substep_fraction);
    if (c.contact.substep_fraction > 0.5) {
      contact.fail("substep_fraction",
                   "must not exceed 0.5 (a sub-step is a fraction of a contact period)");
    }
    c.contact.subcycling = contact.optional<bool>("subcycling", c.contact.subcycling);
    read_velocity_step(contact, c.contact);
    c.contact.line = contact.line();
    contact.finish();
  } else {
    c.contact.distance = c.spacing;
  }
  if (top.has("coupling")) {
    MapReader coupling = top.map("coupling");
    if (coupling.has("scheme")) {
      c.coupling.scheme = coupling.required<std::string>("scheme");
      c.coupling.scheme_place = coupling.place_of("scheme");
    }
    coupling.finish();
  }
  if (top.has("ranks")) {
    MapReader ranks = top.map("ranks");
    c.ranks.partition =
        ranks.optional_choice("partition", c.ranks.partition, "partition", {"slabs", "rcb"});
    c.ranks.partition_place = ranks.place_of("partition");
    c.ranks.bodies = ranks.optional_choice("bodies", c.ranks.bodies, "division of the bodies",
                                           {"islands", "every_rank"});
    ranks.finish();
  }
  // A case of bodies alone needs no fluid and no model.
  if (top.has("fluid") || c.bodies.empty()) c.fluid = read_fluid(top.map("fluid"), c);

  index = 0;
  for (auto& wall : top.list_of_maps("walls")) c.walls.push_back(read_wall(wall, c, index++));
  index = 0;
  for (auto& entry : top.list_of_maps("boundaries")) {
    if (entry.optional<std::string>("type", "") == "periodic") {
      if (c.periodic) {
        entry.fail("type", fmt::format("a case has one periodic axis, and {} is one already",
                                       c.periodic->key));
      }
      c.periodic = read_periodic(entry, index++, c.dimension);
      continue;
    }
    c.boundaries.push_back(read_boundary(entry, index++, c.domain, c.dimension, file_name));
    for (std::size_t k = 0; k + 1 < c.boundaries.size(); ++k) {
      const BoundaryConfig& earlier = c.boundaries[k];
      if (earlier.axis == c.boundaries.back().axis && earlier.upper == c.boundaries.back().upper) {
        entry.fail("side",
                   fmt::format("side {} is already {}'s", earlier.side_name(), earlier.key));
      }
    }
  }
  if (c.periodic) check_periodic(c);
  if ((!c.boundaries.empty() || c.periodic) && !c.has_fluid()) {
    top.fail("boundaries", "a case of bodies alone (no 'fluid') has no open boundaries");
  }
  index = 0;
  for (auto& entry : top.list_of_maps("damping")) {
    c.damping.push_back(read_damping_zone(entry, index++, c.domain, c.dimension));
  }
  if (!c.damping.empty() && !c.has_fluid()) {
    top.fail("damping", "a case of bodies alone (no 'fluid') has no water to damp");
  }
  index = 0;
  for (auto& probe : top.list_of_maps("probes")) c.probes.push_back(read_probe(probe, index++, c));

  if (top.has("compare")) c.compare = read_compare(top);

  if (!c.has_fluid() && top.has("model")) {
    top.fail("model", "a case of bodies alone (no 'fluid') has no fluid model");
  }
  if (c.has_fluid()) {
    MapReader model = top.map("model");
    c.model_name = model.required<std::string>("name");
    c.model = top.node("model");
    c.model_line = model.line();
  }
  top.finish();
  return c;
}

}  // namespace

CaseConfig parse_case(const std::string& text, const std::string& file_name,
                      const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(file_name, e.mark.line + 1, "", "YAML syntax error: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull())
    throw InputError(file_name, 1, "", "the case file is empty");
  try {
    return read_root(root, file_name, overrides);
  } catch (const YAML::Exception& e) {
    // The readers check every node's kind before converting it; this is the net under them,
    // so that no input ends in an uncaught exception (tests/fuzz).
    throw InputError(file_name, e.mark.is_null() ? 0 : e.mark.line + 1, "",
                     "cannot read this YAML: " + e.msg);
  }
}

CaseConfig read_case(const std::string& path, const std::vector<std::string>& overrides) {
  if (std::filesystem::is_directory(path)) {
    throw InputError(path, 0, "", "is a directory, not a case file");
  }
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open the case file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_case(text.str(), path, overrides);
}

}  // namespace sluice::io
