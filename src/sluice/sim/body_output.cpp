#include "sluice/sim/body_output.hpp"

#include <filesystem>
#include <system_error>

#include "sluice/core/errors.hpp"

namespace sluice {

BodyOutput::BodyOutput(const std::string& out_dir, const RigidBodies& bodies) {
  energy_csv_ = std::make_unique<io::CsvWriter>(
      out_dir + "/energy.csv",
      std::vector<std::string>{"time", "body_kinetic", "body_potential", "contact_elastic",
                               "fluid_kinetic", "fluid_potential", "fluid_elastic", "total",
                               "fluid_mass", "solid_substeps"});
  if (bodies.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(out_dir + "/bodies", error);
  if (error) {
    throw InputError(out_dir, 0, "", "cannot create the bodies directory: " + error.message());
  }
  const std::vector<std::string> header = {
      "time",       "x",          "y",          "z",          "qw",        "qx",       "qy",
      "qz",         "vx",         "vy",         "vz",         "wx",        "wy",       "wz",
      "fluid_fx",   "fluid_fy",   "fluid_fz",   "fluid_mx",   "fluid_my",  "fluid_mz", "contact_fx",
      "contact_fy", "contact_fz", "contact_mx", "contact_my", "contact_mz"};
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    body_csv_.push_back(std::make_unique<io::CsvWriter>(
        out_dir + "/bodies/" + bodies.config(b).name + ".csv", header));
  }
}

void BodyOutput::record(double time, const RigidBodies& bodies, const Coupler& coupler,
                        const FluidEnergy& fluid) {
  const auto& system = bodies.system();
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    const RigidBody& s = bodies.state(b);
    const Eigen::Quaterniond q = bodies.shape_orientation(b);
    const Vec3 w = s.angular_velocity();
    const Vec3& ff = coupler.fluid_force()[b];
    const Vec3& fm = coupler.fluid_moment()[b];
    const Vec3& cf = system.contact_force()[b];
    const Vec3& cm = system.contact_torque()[b];
    body_csv_[b]->row({time,  s.position[0], s.position[1], s.position[2], q.w(), q.x(), q.y(),
                       q.z(), s.velocity[0], s.velocity[1], s.velocity[2], w[0],  w[1],  w[2],
                       ff[0], ff[1],         ff[2],         fm[0],         fm[1], fm[2], cf[0],
                       cf[1], cf[2],         cm[0],         cm[1],         cm[2]});
  }
  const RigidSystemEnergy e = system.energy();
  energy_csv_->row({time, e.kinetic, e.potential, e.elastic, fluid.kinetic, fluid.potential,
                    fluid.elastic, e.total() + fluid.kinetic + fluid.potential + fluid.elastic,
                    fluid.mass, static_cast<double>(bodies.substeps())});
}

}  // namespace sluice
