#include "sluice/contact/contact_body_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

std::vector<ContactBody> make_tank_walls(const Vec3& inside_min, const Vec3& inside_max,
                                         const std::vector<std::string>& open_sides, double dx,
                                         const ContactMaterial& material, int dimension) {
  // The tank's inner surface is the surface of its inner box, with the normals turned inward.
  const Vec3 size = inside_max - inside_min;
  const Vec3 centre = 0.5 * (inside_min + inside_max);
  const BodySample box = sample_box_body(size, dx, 0, dimension);
  std::vector<ContactBody> walls;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {-1, 1}) {
      const std::string side = std::string(1, "xyz"[axis]) + (sign > 0 ? "+" : "-");
      if (std::find(open_sides.begin(), open_sides.end(), side) != open_sides.end()) continue;
      ContactBody wall;
      wall.fixed = true;
      wall.material = material;
      for (std::size_t k = 0; k < box.surface_count(); ++k) {
        if (box.normal[k][axis] * sign < 0.5) continue;  // another side's particle
        wall.surface_position.push_back(centre + box.position[k]);
        wall.surface_normal.push_back(-box.normal[k]);
        wall.surface_area.push_back(box.area[k]);
      }
      if (!wall.surface_position.empty()) walls.push_back(std::move(wall));
    }
  }
  return walls;
}

ContactBody make_plane_wall(const Vec3& point, const Vec3& normal, const Vec3& lo, const Vec3& hi,
                            double dx, const ContactMaterial& material, int dimension) {
  ContactBody wall;
  wall.fixed = true;
  wall.material = material;
  wall.half_space = HalfSpace{point, normal};
  // Tangent axes of the plane (2D: the one in the x-z plane), and the lattice over the part of
  // the plane that the box's corners span, anchored at `point`.
  std::vector<Vec3> tangents;
  if (dimension == 2) {
    tangents = {Vec3(normal[2], 0, -normal[0])};
  } else {
    const Vec3 t = normal.unitOrthogonal();
    tangents = {t, normal.cross(t)};
  }
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1 ? hi : lo)[0], (corner & 2 ? hi : lo)[1], (corner & 4 ? hi : lo)[2]);
    for (std::size_t i = 0; i < tangents.size(); ++i) {
      low[i] = std::min(low[i], (c - point).dot(tangents[i]));
      high[i] = std::max(high[i], (c - point).dot(tangents[i]));
    }
  }
  auto first = [&](std::size_t i) { return static_cast<long>(std::floor(low[i] / dx)); };
  auto last = [&](std::size_t i) { return static_cast<long>(std::ceil(high[i] / dx)); };
  const bool plane_2d = tangents.size() == 1;
  auto inside = [&](const Vec3& x) {
    for (int a = 0; a < 3; ++a) {
      if (plane_2d && a == 1) continue;
      if (x[a] < lo[a] || x[a] > hi[a]) return false;
    }
    return true;
  };
  for (long i = first(0); i < last(0); ++i) {
    for (long j = plane_2d ? 0 : first(1); j < (plane_2d ? 1 : last(1)); ++j) {
      Vec3 x = point + (i + 0.5) * dx * tangents[0];
      if (!plane_2d) x += (j + 0.5) * dx * tangents[1];
      if (!inside(x)) continue;
      wall.surface_position.push_back(x);
      wall.surface_normal.push_back(normal);
      wall.surface_area.push_back(plane_2d ? dx : dx * dx);
    }
  }
  return wall;
}

ContactBody make_fixed_box(const Vec3& box_min, const Vec3& box_max, double dx,
                           const ContactMaterial& material, int dimension) {
  const BodySample box = sample_box_body(box_max - box_min, dx, 0, dimension);
  ContactBody body;
  body.fixed = true;
  body.material = material;
  const Vec3 centre = 0.5 * (box_min + box_max);
  for (std::size_t k = 0; k < box.surface_count(); ++k) {
    body.surface_position.push_back(centre + box.position[k]);
    body.surface_normal.push_back(box.normal[k]);
    body.surface_area.push_back(box.area[k]);
  }
  return body;
}

}  // namespace sluice
