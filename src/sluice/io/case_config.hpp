// A case file after reading and validation: plain data in SI units, 3D vectors throughout
// (2D cases: the x-z plane, y = 0). The model's own parameters stay a YAML mapping that the
// model reads and validates itself, so a new model adds keys without touching this struct.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/geometry/axis_box.hpp"
#include "sluice/io/body_config.hpp"
#include "sluice/io/boundary_config.hpp"
#include "sluice/io/yaml_reader.hpp"
#include "sluice/rigid/rigid_system.hpp"

namespace sluice::io {

struct FluidBlockConfig {
  std::string name;
  AxisBox box;
  Vec3 velocity = Vec3::Zero();
  int line = 0;
};

struct FluidConfig {
  double density = 1000.0;            // rest density rho0 [kg/m^3]
  double kinematic_viscosity = 1e-6;  // nu [m^2/s]
  std::vector<FluidBlockConfig> blocks;
};

enum class WallShape { kTank, kBox, kPlane };

struct WallConfig {
  std::string name;
  WallShape shape = WallShape::kTank;
  AxisBox box;  // tank: the inside of the tank; box: the solid box
  // tank: sides left without a wall, among "x-", "x+", "y-", "y+", "z-", "z+"
  std::vector<std::string> open_sides;
  Vec3 point = Vec3::Zero();   // plane: a point on it
  Vec3 normal = Vec3::Zero();  // plane: unit normal pointing into the fluid
  // As a contact body: stiff, and leaving restitution and friction to the body it meets (the
  // pair takes the smaller of the two).
  ContactMaterial material{200e9, 0.3, 1.0, 1.0};
  // The velocity of the wall's surface, the wall itself staying in place (a belt, or the lid
  // of a driven cavity); the grid model (mac) alone honours it.
  Vec3 surface_velocity = Vec3::Zero();
  int line = 0;

  // Whether a tank's side along `axis` (0 x, 1 y, 2 z), at its max (`upper`) or min, is open.
  bool side_open(int axis, bool upper) const {
    const std::string side = std::string(1, "xyz"[axis]) + (upper ? "+" : "-");  // no allocation
    return std::find(open_sides.begin(), open_sides.end(), side) != open_sides.end();
  }
};

enum class ProbeKind { kPressure, kWaterHeight, kSurgeFront, kBoundaryFlux };

struct ProbeConfig {
  std::string name;
  ProbeKind kind = ProbeKind::kPressure;
  Vec3 point = Vec3::Zero();  // pressure: the point; water height: the gauge's (x, y)
  int axis = 0;               // surge front: 0 = x, 1 = y
  std::size_t boundary = 0;   // boundary flux: the index in `boundaries`
  std::string unit = "Pa";    // of its readings, for probes.csv's header
  int line = 0;
};

// Rigid-body contact (seed 000): particle pairs closer than `distance` are examined; a solid
// sub-step is `substep_fraction` of the shortest contact period. Without sub-cycling the fluid
// itself steps at the solid step whenever a contact is in reach (for comparisons, C6).
struct ContactConfig {
  // The contact solver by name (shipped_contact_solvers()): penalty, forces over solid
  // sub-steps; complementarity, friction cones of the velocity-level step
  // (rigid/rigid_system.hpp). Unset: the model's choice (penalty, but for the granular and
  // constraint models).
  std::optional<std::string> method;
  double distance = 0;  // default: the particle spacing
  double substep_fraction = 1.0 / 30;
  bool subcycling = true;
  VelocityStepSettings velocity_step;  // contact.complementarity: the solver, recovery, joints
  int line = 0;
};

// How the fluid and the bodies take a step together (coupling/coupling_scheme.hpp).
struct CouplingConfig {
  std::string scheme;  // empty: the model's own (the first its registry entry names)
  std::pair<std::string, int> scheme_place;  // file (or --set) and line of `coupling.scheme`
};

// A joint between two bodies named in `bodies` ("world" for the world), at a world anchor,
// with a world axis (revolute, prismatic), as at the start.
struct JointConfig {
  std::string name;
  JointType type = JointType::kSpherical;
  std::string body_a, body_b;
  Vec3 anchor = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();                                      // unit
  std::optional<double> motor_speed;                              // revolute [rad/s]
  double motor_torque = std::numeric_limits<double>::infinity();  // [N m]
  std::string key;                                                // "joints[N]", for messages
  int line = 0;
};

// One entry of `compare:`: the settings a model's run of `sluice compare` takes, as --set
// assignments "KEY.PATH=VALUE" in the order given.
struct CompareEntry {
  std::string model;
  std::vector<std::string> settings;
  bool sets_model = false;  // a `model` key replaces the whole model mapping
  int line = 0;
};

// How a run on several ranks (mpirun) splits the domain: `slabs` along the longest horizontal
// axis, moved by shift balancing, or `rcb`, Zoltan's recursive coordinate bisection into one box
// a rank (a build with Zoltan). One rank ignores it.
struct RanksConfig {
  std::string partition = "slabs";
  std::pair<std::string, int> partition_place;  // file (or --set) and line of the key
  // `islands`: each island of bodies that can touch over a step (or are joined) is advanced
  // by one rank, and every rank gathers the states after the step; `every_rank`: every rank
  // advances every body alike.
  std::string bodies = "islands";
};

struct CaseConfig {
  std::shared_ptr<const YamlSource> source;  // file name and --set overrides
  std::string name;
  int dimension = 3;
  double spacing = 0;                         // initial particle spacing dx [m]
  std::pair<std::string, int> spacing_place;  // file (or --set) and line of `spacing`
  AxisBox domain;                             // particles leaving it stop the run
  Vec3 gravity = Vec3(0, 0, -9.81);
  Vec3 travel_direction = Vec3::UnitX();  // unit, across gravity: the drag of OUT/loads.csv
  double end_time = 0;
  double output_interval = 0;
  double probe_interval = 0;
  FluidConfig fluid;  // no blocks: a case of bodies alone (no model either)
  std::vector<WallConfig> walls;
  std::vector<BoundaryConfig> boundaries;  // open sides of the domain: inlets, outlets
  std::optional<PeriodicAxis> periodic;    // the sides along one axis joined
  std::vector<DampingZone> damping;        // where the water's motion is relaxed to rest
  std::vector<BodyConfig> bodies;
  ContactConfig contact;
  CouplingConfig coupling;
  std::vector<JointConfig> joints;
  RanksConfig ranks;
  double body_interval = 0;        // time between rows of OUT/bodies/NAME.csv
  double checkpoint_interval = 0;  // simulated time between checkpoints; 0: none
  // The case as read, with its --set overrides, less the keys a resumed run may change
  // (end_time, checkpoint_interval, compare, ranks.bodies): a checkpoint of another case
  // differs in it.
  std::string identity;
  std::vector<ProbeConfig> probes;
  std::vector<CompareEntry> compare;  // read by `sluice compare` only
  std::string model_name;
  YAML::Node model;  // the whole `model:` mapping, read by the model
  int model_line = 0;

  const std::string& file() const { return source->file; }
  bool has_fluid() const { return !fluid.blocks.empty(); }
};

// A `{min, max}` box whose max exceeds its min on every axis of the case's dimension.
AxisBox read_box(MapReader& map, int dimension);

// Reads and validates a case file. `overrides` are "key.path=value" strings from --set.
// Throws InputError naming the file, line and key of the first problem found.
CaseConfig read_case(const std::string& path, const std::vector<std::string>& overrides = {});

// The same from YAML text (file name used in messages only).
CaseConfig parse_case(const std::string& text, const std::string& file_name,
                      const std::vector<std::string>& overrides = {});

}  // namespace sluice::io
