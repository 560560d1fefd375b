#include "sluice/contact/contact_body_builder.hpp"

#include <cmath>

namespace sluice {

ContactBody make_contact_body(const BodySample& sample, const MassProperties& mass,
                              const ContactMaterial& material, double contact_radius,
                              bool flat_faces) {
  ContactBody body;
  body.material = material;
  body.state.mass = mass.mass;
  body.state.principal_inertia = mass.inertia.diagonal();
  body.contact_radius = contact_radius;
  body.flat_faces = flat_faces;
  for (std::size_t k = 0; k < sample.surface_count(); ++k) {
    body.surface_position.push_back(sample.position[k] - mass.center_of_mass);
    body.surface_normal.push_back(sample.normal[k]);
    body.surface_area.push_back(sample.area[k]);
  }
  return body;
}

ContactBody make_floor_patch(double half_width, double dx, const ContactMaterial& material) {
  ContactBody floor;
  floor.fixed = true;
  floor.material = material;
  const int n = static_cast<int>(std::lround(2 * half_width / dx));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      floor.surface_position.push_back(
          Vec3(-half_width + (i + 0.5) * dx, -half_width + (j + 0.5) * dx, 0));
      floor.surface_normal.push_back(Vec3::UnitZ());
      floor.surface_area.push_back(dx * dx);
    }
  }
  return floor;
}

}  // namespace sluice
