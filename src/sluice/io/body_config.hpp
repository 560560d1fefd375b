// Rigid bodies as read from a case file (docs/case-format.md, "Bodies"): plain data in SI units,
// angles in radians, 3D vectors (2D cases: the x-z plane, rotation about y).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "sluice/contact/contact_material.hpp"
#include "sluice/core/types.hpp"
#include "sluice/geometry/triangle_mesh.hpp"
#include "sluice/waves/paddle_signal.hpp"

namespace sluice::io {

enum class BodyShape { kBox, kSphere, kCylinder, kMesh };
enum class BodyMotion { kFree, kFixed, kPrescribed };
enum class PrescribedKind { kConstantVelocity, kSinusoid, kTable, kWavemaker };
enum class PaddleKind { kPiston, kFlap };

// One row of a prescribed-motion table: the pose at `time` (rotation as angles about x, y, z).
struct PoseSample {
  double time = 0;
  Vec3 position = Vec3::Zero();
  Vec3 rotation = Vec3::Zero();
};

// A wave paddle at the x- end of a flume, making waves that travel towards +x: a piston moves
// along x; a flap turns about y, about a hinge on the vertical line through the body's
// position, `hinge_depth` below the still water line. Its displacement at the still water line
// follows `signal` (waves/paddle_signal.hpp), found from the waves asked for as the case is read.
struct WavemakerConfig {
  PaddleKind paddle = PaddleKind::kPiston;
  double water_depth = 0;         // [m], in front of the paddle
  double still_water = 0;         // the still water line's height z [m]: the floor + water_depth
  double hinge_depth = 0;         // flap [m]
  bool irregular = false;         // a JONSWAP sea, else one regular wave train
  double height = 0;              // regular: H [m]
  double period = 0;              // regular: T [s]; irregular: the peak period
  double significant_height = 0;  // irregular: H_m0 [m]
  int order = 1;                  // regular: 2 adds Madsen's (piston) or Schäffer's (flap)
  waves::PaddleSignal signal;
  // Active absorption (sim/paddle_absorber.hpp): the paddle adds absorption_gain [1/s] times
  // (`signal`'s elevation at its face less the water's there) to its velocity.
  bool active_absorption = false;
  double absorption_gain = 0;
};

struct PrescribedConfig {
  PrescribedKind kind = PrescribedKind::kConstantVelocity;
  // constant velocity: the body's initial velocity and angular velocity, held forever, reached
  // from rest over ramp_time (0: at once) along (1 - cos(pi t / ramp_time)) / 2.
  double ramp_time = 0;  // s
  // sinusoid: displacement amplitude * (sin(2 pi f t + phase) - sin(phase)), so that the body
  // starts at its position whatever the phase; rotation likewise.
  Vec3 amplitude = Vec3::Zero();
  Vec3 rotation_amplitude = Vec3::Zero();  // radians
  double frequency = 0;                    // Hz
  double phase = 0;                        // radians
  // table: poses from a CSV file, sorted in time, interpolated linearly, held at the ends.
  std::string table_file;
  std::vector<PoseSample> table;
  WavemakerConfig wavemaker;
};

struct BodyConfig {
  std::string name;
  BodyShape shape = BodyShape::kBox;
  Vec3 size = Vec3::Zero();  // box edge lengths (2D: x and z)
  double radius = 0;         // sphere, cylinder
  double length = 0;         // cylinder (3D: along its own z axis)
  std::string mesh_file;     // mesh: resolved against the case file's folder
  TriangleMesh mesh;         // mesh: as read (closed, outward), scaled
  double mesh_scale = 1;
  double density = 0;  // one of density or mass is > 0
  double mass = 0;
  Vec3 position = Vec3::Zero();  // where the shape's own origin goes (box/sphere/cylinder: centre)
  Vec3 rotation = Vec3::Zero();  // initial orientation, angles about x, then y, then z (radians)
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  BodyMotion motion = BodyMotion::kFree;
  PrescribedConfig prescribed;
  std::array<bool, 3> locked_translation{};
  std::array<bool, 3> locked_rotation{};
  ContactMaterial material;
  // A grain that a model added to the case (penalty-sph's free solid layers): a fluid sees it as
  // one solid particle at its centre of mass, as large as the body, not as particles under its
  // surface. Not a case-file key.
  bool seen_as_one_particle = false;
  // Where messages about it point when it is not an entry of `bodies` (a grain: its layer's
  // key path, "model.solids[0]"); empty: "bodies[N]".
  std::string key;
  int line = 0;  // of the list entry
  // Where messages about its starting position point (MapReader::place_of).
  std::string position_file;
  int position_line = 0;
};

}  // namespace sluice::io
