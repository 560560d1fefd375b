#include "sluice/sim/body_output.hpp"

#include <filesystem>
#include <system_error>

#include "sluice/core/errors.hpp"

namespace sluice {

BodyOutput::BodyOutput(const std::string& out_dir, const RigidBodies& bodies, const Vec3& travel,
                       const Vec3& gravity, int dimension, io::CsvStart start)
    : lift_axis_(gravity.norm() > 0 ? Vec3(-gravity.normalized()) : Vec3::UnitZ()),
      with_side_(dimension == 3) {
  drag_axis_ = -travel;
  side_axis_ = lift_axis_.cross(travel);
  energy_csv_ = std::make_unique<io::CsvWriter>(
      out_dir + "/energy.csv",
      std::vector<std::string>{"time", "body_kinetic", "body_potential", "contact_elastic",
                               "fluid_kinetic", "fluid_potential", "fluid_elastic", "total",
                               "fluid_mass", "solid_substeps"},
      start);
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
        out_dir + "/bodies/" + bodies.config(b).name + ".csv", header, start));
  }
  std::vector<std::string> loads_header{"time"};
  const auto add_columns = [&](const std::string& name) {
    loads_header.push_back(name + "_drag");
    loads_header.push_back(name + "_lift");
    if (with_side_) loads_header.push_back(name + "_side");
  };
  for (std::size_t b = 0; b < bodies.count(); ++b) add_columns(bodies.config(b).name);
  add_columns("all_bodies");
  loads_csv_ = std::make_unique<io::CsvWriter>(out_dir + "/loads.csv", loads_header, start);
}

void BodyOutput::archive_state(StateArchive& a) {
  a.section("body_output");
  for (auto& csv : body_csv_) csv->archive_state(a);
  if (loads_csv_) loads_csv_->archive_state(a);
  energy_csv_->archive_state(a);
  a(fluid_force_, fluid_moment_, contact_force_, contact_moment_, span_);
}

void BodyOutput::accumulate(double dt, const RigidBodies& bodies, const Coupler& coupler) {
  const std::size_t n = bodies.count();
  if (n == 0) return;
  if (fluid_force_.size() != n) {
    for (auto* sums : {&fluid_force_, &fluid_moment_, &contact_force_, &contact_moment_})
      sums->assign(n, Vec3::Zero());
  }
  const auto& system = bodies.system();
  for (std::size_t b = 0; b < n; ++b) {
    fluid_force_[b] += dt * coupler.fluid_force()[b];
    fluid_moment_[b] += dt * coupler.fluid_moment()[b];
    contact_force_[b] += dt * system.contact_force()[b];
    contact_moment_[b] += dt * system.contact_torque()[b];
  }
  span_ += dt;
}

void BodyOutput::record(double time, const RigidBodies& bodies, const Coupler& coupler,
                        const FluidEnergy& fluid) {
  const auto& system = bodies.system();
  // The interval's mean of a load, or the load as it stands where no step has been summed.
  const auto mean = [&](const std::vector<Vec3>& sums, const std::vector<Vec3>& now,
                        std::size_t b) -> Vec3 {
    return span_ > 0 && b < sums.size() ? Vec3(sums[b] / span_) : now[b];
  };
  std::vector<Vec3> force(bodies.count());
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    const RigidBody& s = bodies.state(b);
    const Eigen::Quaterniond q = bodies.shape_orientation(b);
    const Vec3 w = s.angular_velocity();
    const Vec3 ff = mean(fluid_force_, coupler.fluid_force(), b);
    const Vec3 fm = mean(fluid_moment_, coupler.fluid_moment(), b);
    const Vec3 cf = mean(contact_force_, system.contact_force(), b);
    const Vec3 cm = mean(contact_moment_, system.contact_torque(), b);
    force[b] = ff;
    body_csv_[b]->row({time,  s.position[0], s.position[1], s.position[2], q.w(), q.x(), q.y(),
                       q.z(), s.velocity[0], s.velocity[1], s.velocity[2], w[0],  w[1],  w[2],
                       ff[0], ff[1],         ff[2],         fm[0],         fm[1], fm[2], cf[0],
                       cf[1], cf[2],         cm[0],         cm[1],         cm[2]});
  }
  if (loads_csv_) {
    std::vector<double> row{time};
    Vec3 total = Vec3::Zero();
    const auto add_loads = [&](const Vec3& force) {
      row.push_back(force.dot(drag_axis_));
      row.push_back(force.dot(lift_axis_));
      if (with_side_) row.push_back(force.dot(side_axis_));
    };
    for (std::size_t b = 0; b < bodies.count(); ++b) {
      add_loads(force[b]);
      total += force[b];
    }
    add_loads(total);
    loads_csv_->row(row);
  }
  for (auto* sums : {&fluid_force_, &fluid_moment_, &contact_force_, &contact_moment_})
    std::fill(sums->begin(), sums->end(), Vec3::Zero());
  span_ = 0;
  const RigidSystemEnergy e = system.energy();
  energy_csv_->row({time, e.kinetic, e.potential, e.elastic, fluid.kinetic, fluid.potential,
                    fluid.elastic, e.total() + fluid.kinetic + fluid.potential + fluid.elastic,
                    fluid.mass, static_cast<double>(bodies.substeps())});
}

}  // namespace sluice
