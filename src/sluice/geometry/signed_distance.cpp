#include "sluice/geometry/signed_distance.hpp"

#include <cmath>
#include <limits>

namespace sluice {

SurfacePoint box_surface(const Vec3& half, const Vec3& x) {
  SurfacePoint out;
  const Vec3 q = x.cwiseAbs() - half;
  if ((q.array() > 0).any()) {
    out.closest = x.cwiseMax(-half).cwiseMin(half);
    const Vec3 away = x - out.closest;
    out.distance = away.norm();
    out.normal = away / out.distance;
    return out;
  }
  // Inside: the nearest face is the one whose plane is closest.
  int axis = 0;
  q.maxCoeff(&axis);
  out.distance = q[axis];
  out.normal = Vec3::Zero();
  out.normal[axis] = x[axis] < 0 ? -1 : 1;
  out.closest = x;
  out.closest[axis] = out.normal[axis] * half[axis];
  return out;
}

SurfacePoint sphere_surface(double r, const Vec3& x) {
  SurfacePoint out;
  const double rho = x.norm();
  out.normal = rho > 0 ? Vec3(x / rho) : Vec3::UnitZ();
  out.distance = rho - r;
  out.closest = r * out.normal;
  return out;
}

SurfacePoint cylinder_surface(double r, double half_length, const Vec3& x) {
  SurfacePoint out;
  const double rho = x.head<2>().norm();
  const Vec3 radial = rho > 0 ? Vec3(x[0] / rho, x[1] / rho, 0) : Vec3::UnitX();
  const Vec3 axial(0, 0, x[2] < 0 ? -1 : 1);
  const double dr = rho - r, dz = std::abs(x[2]) - half_length;
  if (dr > 0 || dz > 0) {
    // Outside: the nearest point of the side, the cap, or the rim between them.
    out.closest = std::min(rho, r) * radial + std::min(std::abs(x[2]), half_length) * axial;
    const Vec3 away = x - out.closest;
    out.distance = away.norm();
    out.normal = away / out.distance;
    return out;
  }
  if (dr > dz) {
    out.distance = dr;
    out.normal = radial;
    out.closest = r * radial + Vec3(0, 0, x[2]);
  } else {
    out.distance = dz;
    out.normal = axial;
    out.closest = Vec3(x[0], x[1], axial[2] * half_length);
  }
  return out;
}

SurfacePoint plane_surface(const Vec3& point, const Vec3& normal, const Vec3& x) {
  SurfacePoint out;
  out.distance = (x - point).dot(normal);
  out.normal = normal;
  out.closest = x - out.distance * normal;
  return out;
}

SurfacePoint sampled_surface(const std::vector<Vec3>& position, const std::vector<Vec3>& normal,
                             const Vec3& x) {
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < position.size(); ++k) {
    const double d2 = (x - position[k]).squaredNorm();
    if (d2 < best) {
      best = d2;
      nearest = k;
    }
  }
  if (position.empty()) return {std::numeric_limits<double>::infinity(), x, Vec3::UnitZ()};
  return plane_surface(position[nearest], normal[nearest], x);
}

}  // namespace sluice
