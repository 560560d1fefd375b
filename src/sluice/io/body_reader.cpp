#include "sluice/io/body_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <tuple>

#include "sluice/geometry/mesh_io.hpp"
#include "sluice/waves/jonswap.hpp"
#include "sluice/waves/linear_waves.hpp"
#include "sluice/waves/paddle_transfer.hpp"

namespace sluice::io {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

// An angle or angular quantity: a vector about x, y, z in 3D, one number about y in 2D.
Vec3 read_rotation(MapReader& map, const std::string& key, double unit) {
  if (!map.has(key)) return Vec3::Zero();
  if (map.source().dimension == 2) return Vec3(0, map.required<double>(key) * unit, 0);
  return map.required<Vec3>(key) * unit;
}

// The waves a wavemaker makes and the paddle's signal for them (docs/case-format.md,
// "Wavemakers").
WavemakerConfig read_wavemaker(MapReader& map, const BodyContext& context) {
  WavemakerConfig w;
  if (!(context.gravity > 0)) map.fail("type", "a wavemaker needs gravity (the case has none)");
  w.paddle = map.optional_choice("paddle", "piston", "paddle", {"piston", "flap"}) == "piston"
                 ? PaddleKind::kPiston
                 : PaddleKind::kFlap;
  w.water_depth = map.required_positive("water_depth");
  w.still_water = context.floor + w.water_depth;
  if (w.paddle == PaddleKind::kFlap) {
    w.hinge_depth = map.optional_positive("hinge_depth", w.water_depth);
  } else if (map.has("hinge_depth")) {
    map.fail("hinge_depth", "only read for a flap (a piston does not turn)");
  }
  const double hinge = w.paddle == PaddleKind::kFlap ? w.hinge_depth : waves::kPistonHinge;
  const bool regular =
      map.optional_choice("wave", "regular", "wave", {"regular", "jonswap"}) == "regular";
  w.irregular = !regular;
  std::vector<waves::WaveComponent> sea;
  if (regular) {
    w.height = map.required_positive("height");
    w.period = map.required_positive("period");
    const double omega = 2 * std::numbers::pi / w.period;
    const double k = waves::wavenumber(omega, w.water_depth, context.gravity);
    const double limit = waves::breaking_height(k, w.water_depth);
    if (w.height >= limit) {
      map.fail("height", fmt::format("{} m breaks: the limit at this period and depth is {:.4g} m "
                                     "(Miche: H/L = 0.142 tanh kh, L = {:.4g} m)",
                                     w.height, limit, 2 * std::numbers::pi / k));
    }
    w.order = map.optional<int>("order", 1);
    if (w.order != 1 && w.order != 2) map.fail("order", "must be 1 or 2");
    sea.push_back({w.height / 2, omega, map.optional<double>("phase_deg", 0.0) * kDegree});
  } else {
    waves::JonswapSea js;
    js.significant_height = w.significant_height = map.required_positive("significant_height");
    js.peak_period = w.period = map.required_positive("peak_period");
    js.peak_enhancement = map.optional<double>("peak_enhancement", 3.3);
    if (!(js.peak_enhancement >= 1)) map.fail("peak_enhancement", "must be 1 or more");
    const int seed = map.optional<int>("seed", 1);
    if (seed < 0) map.fail("seed", "must be zero or more");
    js.seed = static_cast<std::uint64_t>(seed);
    js.components = map.optional<int>("components", 256);
    if (js.components < 1) map.fail("components", "must be 1 or more");
    js.min_frequency = map.optional_positive("min_frequency", 0.5 / js.peak_period);
    js.max_frequency = map.optional_positive("max_frequency", 3 / js.peak_period);
    if (!(js.max_frequency > js.min_frequency)) {
      map.fail("max_frequency", fmt::format("must exceed min_frequency ({} Hz)", js.min_frequency));
    }
    sea = waves::jonswap_components(js);
  }
  const double ramp = map.optional_non_negative("ramp_time", 2 * w.period);
  w.signal = waves::paddle_signal(sea, w.water_depth, hinge, context.gravity, w.order == 2, ramp);
  w.active_absorption = map.optional<bool>("active_absorption", false);
  if (w.active_absorption) {
    // The transfer function read backwards at the (peak) frequency: the paddle velocity that
    // makes a wave of unit elevation, omega / (H/S); sqrt(g/h) for a piston in shallow water.
    const double omega = 2 * std::numbers::pi / w.period;
    const double k = waves::wavenumber(omega, w.water_depth, context.gravity);
    w.absorption_gain = omega / waves::height_over_stroke(k, w.water_depth, hinge);
  }
  return w;
}

PrescribedConfig read_prescribed(MapReader& map, const BodyContext& context) {
  const std::string& case_file = context.case_file;
  PrescribedConfig p;
  const std::string type = map.required<std::string>("type");
  if (type == "constant_velocity") {
    p.kind = PrescribedKind::kConstantVelocity;
    p.ramp_time = map.optional_non_negative("ramp_time", 0.0);
  } else if (type == "sinusoid") {
    p.kind = PrescribedKind::kSinusoid;
    p.amplitude = map.optional<Vec3>("amplitude", Vec3::Zero());
    p.rotation_amplitude = read_rotation(map, "rotation_amplitude_deg", kDegree);
    p.frequency = map.required_positive("frequency");
    p.phase = map.optional<double>("phase_deg", 0.0) * kDegree;
  } else if (type == "table") {
    p.kind = PrescribedKind::kTable;
    const std::string file = map.required<std::string>("file");
    p.table_file = (std::filesystem::path(case_file).parent_path() / file).string();
    p.table = read_pose_table(p.table_file, map, "file");
  } else if (type == "wavemaker") {
    p.kind = PrescribedKind::kWavemaker;
    p.wavemaker = read_wavemaker(map, context);
  } else {
    map.fail_choice("type", "prescribed motion", type,
                    {"constant_velocity", "sinusoid", "table", "wavemaker"});
  }
  map.finish();
  return p;
}

void read_locks(MapReader& map, BodyConfig& b) {
  if (map.source().dimension == 2) {  // the x-z plane: no y, no rotation about x or z
    b.locked_translation[1] = true;
    b.locked_rotation[0] = b.locked_rotation[2] = true;
  }
  const std::vector<std::string> names = {"x", "y", "z", "rx", "ry", "rz"};
  for (const auto& dof : map.optional<std::vector<std::string>>("locked", {})) {
    const auto found = std::find(names.begin(), names.end(), dof);
    if (found == names.end()) map.fail_choice("locked", "degree of freedom", dof, names);
    const auto k = found - names.begin();
    (k < 3 ? b.locked_translation[k] : b.locked_rotation[k - 3]) = true;
  }
}

void read_shape(MapReader& map, BodyConfig& b, const std::string& case_file) {
  const std::string shape = map.required<std::string>("shape");
  if (shape == "box") {
    b.shape = BodyShape::kBox;
    b.size = map.required<Vec3>("size");
    for (int a = 0; a < 3; ++a) {
      if (map.source().dimension == 2 && a == 1) continue;
      if (!(b.size[a] > 0)) map.fail("size", "every edge length must be greater than zero");
    }
  } else if (shape == "sphere" || shape == "cylinder") {
    b.shape = shape == "sphere" ? BodyShape::kSphere : BodyShape::kCylinder;
    b.radius = map.required_positive("radius");
    if (b.shape == BodyShape::kCylinder && map.source().dimension == 3) {
      b.length = map.required_positive("length");
    }
  } else if (shape == "mesh") {
    b.shape = BodyShape::kMesh;
    if (map.source().dimension == 2) map.fail("shape", "mesh bodies need a 3D case");
    const std::string file = map.required<std::string>("file");
    b.mesh_scale = map.optional_positive("scale", 1.0);
    b.mesh_file = (std::filesystem::path(case_file).parent_path() / file).string();
    b.mesh = read_mesh(b.mesh_file, b.mesh_scale, map.source().file, map.line_of("file"),
                       map.path_of("file"));
  } else {
    map.fail_choice("shape", "body shape", shape, {"box", "sphere", "cylinder", "mesh"});
  }
}

}  // namespace

ContactMaterial read_material(MapReader& owner, const ContactMaterial& fallback) {
  ContactMaterial m = fallback;
  if (!owner.has("material")) return m;
  MapReader map = owner.map("material");
  m.young = map.optional<double>("young", m.young);
  if (!(m.young > 0)) map.fail("young", fmt::format("must be greater than zero, got {}", m.young));
  m.poisson = map.optional<double>("poisson", m.poisson);
  if (!(m.poisson > -1 && m.poisson < 0.5)) {
    map.fail("poisson", fmt::format("must lie in (-1, 0.5), got {}", m.poisson));
  }
  m.restitution = map.optional<double>("restitution", m.restitution);
  if (!(m.restitution > 0 && m.restitution <= 1)) {
    map.fail("restitution", fmt::format("must lie in (0, 1], got {}", m.restitution));
  }
  m.friction = map.optional<double>("friction", m.friction);
  if (!(m.friction >= 0)) {
    map.fail("friction", fmt::format("must be zero or more, got {}", m.friction));
  }
  map.finish();
  return m;
}

JointConfig read_joint(MapReader& map, std::size_t index) {
  JointConfig j;
  j.line = map.line();
  j.key = fmt::format("joints[{}]", index);
  j.name = map.optional<std::string>("name", fmt::format("joint{}", index));
  const std::string type = map.required<std::string>("type");
  const std::vector<std::string> types = {"fixed", "revolute", "prismatic", "spherical"};
  const auto found = std::find(types.begin(), types.end(), type);
  if (found == types.end()) map.fail_choice("type", "joint type", type, types);
  j.type = static_cast<JointType>(found - types.begin());
  if (!map.has("bodies")) map.fail("bodies", "missing required key");
  const YAML::Node bodies = map.node("bodies");
  if (!bodies.IsSequence() || bodies.size() != 2 || !bodies[0].IsScalar() ||
      !bodies[1].IsScalar()) {
    map.fail("bodies", "must name two bodies, [a, b] (\"world\" for the world)");
  }
  j.body_a = bodies[0].as<std::string>();
  j.body_b = bodies[1].as<std::string>();
  if (j.body_a == j.body_b) map.fail("bodies", "must name two different bodies");
  j.anchor = map.required<Vec3>("anchor");
  // In 2D (the x-z plane) a revolute joint turns about y, which an [x, z] vector cannot give.
  const bool planar = map.source().dimension == 2;
  if (planar && j.type == JointType::kRevolute) {
    if (map.has("axis")) map.fail("axis", "a 2D revolute joint turns about y: give no axis");
    j.axis = Vec3::UnitY();
  } else if (j.type == JointType::kRevolute || j.type == JointType::kPrismatic || map.has("axis")) {
    const Vec3 axis = map.required<Vec3>("axis");
    if (!(axis.norm() > 0)) map.fail("axis", "must not be zero");
    j.axis = axis.normalized();
  }
  if (map.has("motor")) {
    if (j.type != JointType::kRevolute) map.fail("motor", "only a revolute joint has a motor");
    MapReader motor = map.map("motor");
    j.motor_speed = motor.required<double>("speed");
    j.motor_torque = motor.optional_positive("torque", j.motor_torque);
    motor.finish();
  }
  map.finish();
  return j;
}

void read_velocity_step(MapReader& contact, ContactConfig& c) {
  if (!contact.has("complementarity")) return;
  MapReader map = contact.map("complementarity");
  VelocityStepSettings& s = c.velocity_step;
  s.solver.solver =
      map.optional_choice("solver", s.solver.solver, "complementarity solver", ccp_solver_names());
  s.solver.max_iterations =
      static_cast<int>(map.optional_positive("max_iterations", s.solver.max_iterations));
  s.solver.tolerance = map.optional_positive("tolerance", s.solver.tolerance);
  s.solver.jacobi_relaxation =
      map.optional_positive("jacobi_relaxation", s.solver.jacobi_relaxation);
  if (s.solver.jacobi_relaxation > 1) {
    map.fail("jacobi_relaxation",
             fmt::format("must not exceed 1, got {}", s.solver.jacobi_relaxation));
  }
  s.slip_iterations =
      static_cast<int>(map.optional_non_negative("slip_iterations", s.slip_iterations));
  s.recovery_speed = map.optional_positive("recovery_speed", s.recovery_speed);
  s.stabilisation = map.optional_positive("stabilisation", s.stabilisation);
  if (s.stabilisation > 1) {
    map.fail("stabilisation", fmt::format("must not exceed 1, got {}", s.stabilisation));
  }
  map.finish();
}

BodyConfig read_body(MapReader& map, std::size_t index, const BodyContext& context) {
  const std::string& case_file = context.case_file;
  BodyConfig b;
  b.line = map.line();
  b.name = map.optional<std::string>("name", fmt::format("body{}", index));
  if (b.name.empty() || b.name.find_first_of("/\\ ,") != std::string::npos) {
    map.fail("name", "must be a non-empty word without '/', '\\', ',' or spaces (it names a file)");
  }
  read_shape(map, b, case_file);

  if (map.has("density") == map.has("mass")) {
    map.fail_here("give exactly one of 'density' and 'mass'");
  }
  if (map.has("density")) {
    b.density = map.required<double>("density");
    if (!(b.density > 0))
      map.fail("density", fmt::format("must be greater than zero, got {}", b.density));
  } else {
    b.mass = map.required<double>("mass");
    if (!(b.mass > 0)) map.fail("mass", fmt::format("must be greater than zero, got {}", b.mass));
  }

  b.position = map.required<Vec3>("position");
  std::tie(b.position_file, b.position_line) = map.place_of("position");
  b.rotation = read_rotation(map, "rotation_deg", kDegree);
  b.velocity = map.optional<Vec3>("velocity", Vec3::Zero());
  b.angular_velocity = read_rotation(map, "angular_velocity", 1.0);

  const std::string motion = map.optional<std::string>("motion", "free");
  if (motion == "free") {
    b.motion = BodyMotion::kFree;
  } else if (motion == "fixed") {
    b.motion = BodyMotion::kFixed;
  } else if (motion == "prescribed") {
    b.motion = BodyMotion::kPrescribed;
    if (!map.has("prescribed"))
      map.fail("prescribed", "missing required key (motion is prescribed)");
    MapReader prescribed = map.map("prescribed");
    b.prescribed = read_prescribed(prescribed, context);
    if (b.prescribed.wavemaker.active_absorption && b.shape != BodyShape::kBox) {
      prescribed.fail("active_absorption",
                      "needs a box paddle: the water is measured a little before its face");
    }
  } else {
    map.fail_choice("motion", "motion", motion, {"free", "fixed", "prescribed"});
  }
  if (b.motion != BodyMotion::kPrescribed && map.has("prescribed")) {
    map.fail("prescribed", "only read when motion is prescribed");
  }
  read_locks(map, b);
  b.material = read_material(map, ContactMaterial{});
  map.finish();
  return b;
}

std::vector<PoseSample> read_pose_table(const std::string& path, const MapReader& owner,
                                        const std::string& key) {
  std::ifstream in(path);
  if (!in) owner.fail(key, fmt::format("cannot read the motion table '{}'", path));
  const std::vector<std::string> known = {"time", "x", "y", "z", "rx_deg", "ry_deg", "rz_deg"};
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ',')) {
      cell.erase(0, cell.find_first_not_of(" \t\r"));
      cell.erase(cell.find_last_not_of(" \t\r") + 1);
      cells.push_back(cell);
    }
    return cells;
  };
  std::string line;
  if (!std::getline(in, line)) owner.fail(key, fmt::format("motion table '{}' is empty", path));
  std::vector<int> column;  // which of `known` each column holds
  for (const auto& name : split(line)) {
    const auto found = std::find(known.begin(), known.end(), name);
    if (found == known.end()) {
      owner.fail(key,
                 fmt::format("motion table '{}' line 1: unknown column '{}', expected time, x, "
                             "y, z, rx_deg, ry_deg, rz_deg",
                             path, name));
    }
    column.push_back(static_cast<int>(found - known.begin()));
  }
  if (std::find(column.begin(), column.end(), 0) == column.end()) {
    owner.fail(key, fmt::format("motion table '{}' line 1: no 'time' column", path));
  }
  std::vector<PoseSample> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = split(line);
    if (cells.size() != column.size()) {
      owner.fail(key, fmt::format("motion table '{}' line {}: {} values for {} columns", path,
                                  number, cells.size(), column.size()));
    }
    PoseSample pose;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      double value = 0;
      std::size_t used = 0;
      try {
        value = std::stod(cells[c], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != cells[c].size() || cells[c].empty() || !std::isfinite(value)) {
        owner.fail(key, fmt::format("motion table '{}' line {}: '{}' is not a number", path, number,
                                    cells[c]));
      }
      const int k = column[c];
      if (k == 0)
        pose.time = value;
      else if (k <= 3)
        pose.position[k - 1] = value;
      else
        pose.rotation[k - 4] = value * kDegree;
    }
    if (owner.source().dimension == 2) {  // the x-z plane, turning about y
      pose.position[1] = 0;
      pose.rotation[0] = pose.rotation[2] = 0;
    }
    if (!rows.empty() && !(pose.time > rows.back().time)) {
      owner.fail(key, fmt::format("motion table '{}' line {}: time {} does not come after {} (the "
                                  "rows must be sorted in time)",
                                  path, number, pose.time, rows.back().time));
    }
    rows.push_back(pose);
  }
  if (rows.empty()) owner.fail(key, fmt::format("motion table '{}' has no rows", path));
  return rows;
}

}  // namespace sluice::io
