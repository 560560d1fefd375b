#include "sluice/sim/size_estimate.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "sluice/core/errors.hpp"
#include "sluice/core/types.hpp"
#include "sluice/geometry/sampling.hpp"

namespace sluice {

namespace {

const double kPi = std::acos(-1.0);

// A case of bodies alone keeps their surface particles in the particle base's fields, as
// `wcsph` keeps its own (docs/output.md).
constexpr double kBodyParticleBytes = 500;

// The case's model.device, or "cpu".
std::string device_of(const io::CaseConfig& config) {
  const YAML::Node device = config.model["device"];
  return device && device.IsScalar() ? device.Scalar() : "cpu";
}

// Product of the box's extents along the case's axes (2D: x and z).
double measure(const Vec3& extent, int dimension) {
  return dimension == 2 ? extent[0] * extent[2] : extent[0] * extent[1] * extent[2];
}

// A bound on the volume of a body: its shape's, or its mesh's bounding box's.
double body_volume(const io::BodyConfig& b, int dimension) {
  switch (b.shape) {
    case io::BodyShape::kBox:
      return measure(b.size, dimension);
    case io::BodyShape::kSphere:
      return dimension == 2 ? kPi * b.radius * b.radius : 4.0 / 3.0 * kPi * std::pow(b.radius, 3);
    case io::BodyShape::kCylinder:
      return dimension == 2 ? kPi * b.radius * b.radius : kPi * b.radius * b.radius * b.length;
    case io::BodyShape::kMesh: {
      if (b.mesh.vertices.empty()) return 0;
      Vec3 lo = b.mesh.vertices.front(), hi = lo;
      for (const Vec3& v : b.mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      return measure(hi - lo, dimension);
    }
  }
  return 0;
}

}  // namespace

SizeEstimate estimate_size(const io::CaseConfig& config) {
  return estimate_size(config, shipped_models(config.dimension));
}

SizeEstimate estimate_size(const io::CaseConfig& config, const ModelRegistry& models) {
  SizeEstimate out;
  const int dim = config.dimension;
  const double dx = config.spacing;
  const double cell_volume = std::pow(dx, dim);
  const ModelEntry* model = config.has_fluid() ? models.find(config.model_name) : nullptr;
  ModelSize size;  // an unknown model: the largest bytes per element
  if (model != nullptr) size = model->size;
  if (!config.has_fluid()) size.bytes_per_element = kBodyParticleBytes;
  out.element_name = size.element_name;
  if (size.elements) {
    out.elements = size.elements(config);
  } else {
    for (const auto& block : config.fluid.blocks)
      out.elements += lattice_points(block.box.max - block.box.min, dx, dim);
    // Walls: a shell of a few layers (the models' reach is at most three spacings) around a
    // tank's inside, a solid box's own volume, a plane's layers across the domain.
    const double shell = 3 * dx;
    const Vec3 domain = config.domain.max - config.domain.min;
    for (const auto& wall : config.walls) {
      const Vec3 inside = wall.box.max - wall.box.min;
      switch (wall.shape) {
        case io::WallShape::kTank:
          out.elements +=
              (measure(inside + Vec3::Constant(2 * shell), dim) - measure(inside, dim)) /
              cell_volume;
          break;
        case io::WallShape::kBox:
          out.elements += measure(inside, dim) / cell_volume;
          break;
        case io::WallShape::kPlane: {
          // A plane's cut through the domain is at most sqrt(D) times its largest face (the
          // cut's projection on the face it is most parallel to fits in that face).
          const double thinnest = dim == 2 ? std::min(domain[0], domain[2]) : domain.minCoeff();
          out.elements +=
              std::sqrt(double(dim)) * measure(domain, dim) / thinnest * shell / cell_volume;
          break;
        }
      }
    }
    for (const auto& body : config.bodies) out.elements += body_volume(body, dim) / cell_volume;
  }
  out.bytes = out.elements * size.bytes_per_element;
  // The emulated device's copy lives in the host's memory beside the host's own.
  if (size.device_bytes_per_element && device_of(config) == "emulated")
    out.bytes += out.elements * size.device_bytes_per_element(dim);
  return out;
}

double machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0;
}

bool runs_on_a_gpu(const io::CaseConfig& config, const ModelRegistry& models) {
  if (!config.has_fluid()) return false;
  const ModelEntry* model = models.find(config.model_name);
  if (model == nullptr || !model->size.device_bytes_per_element) return false;
  return device_of(config) == "gpu" &&
         std::find(model->devices.begin(), model->devices.end(), "gpu") != model->devices.end();
}

bool runs_on_a_gpu(const io::CaseConfig& config) {
  return runs_on_a_gpu(config, shipped_models(config.dimension));
}

void refuse_if_the_gpu_cannot_hold(const io::CaseConfig& config, const SizeEstimate& estimate,
                                   const exec::DeviceMemory& gpu) {
  refuse_if_the_gpu_cannot_hold(config, estimate, gpu, shipped_models(config.dimension));
}

void refuse_if_the_gpu_cannot_hold(const io::CaseConfig& config, const SizeEstimate& estimate,
                                   const exec::DeviceMemory& gpu, const ModelRegistry& models) {
  const ModelEntry* model = models.find(config.model_name);
  if (model == nullptr || !model->size.device_bytes_per_element) return;
  const double needed = estimate.elements * model->size.device_bytes_per_element(config.dimension);
  if (gpu.free_bytes <= 0 || needed <= gpu.free_bytes) return;
  throw InputError(config.spacing_place.first, config.spacing_place.second, "spacing",
                   fmt::format("at {} m the case needs about {:.3g} particles and {} of the "
                               "GPU's memory; the {} has {} free",
                               config.spacing, estimate.elements, readable_bytes(needed), gpu.name,
                               readable_bytes(gpu.free_bytes)));
}

void refuse_if_it_cannot_fit_here(const io::CaseConfig& config, const SizeEstimate& estimate) {
  refuse_if_it_cannot_fit(config, estimate, machine_memory_bytes());
  const ModelRegistry models = shipped_models(config.dimension);
  if (runs_on_a_gpu(config, models))
    refuse_if_the_gpu_cannot_hold(config, estimate, exec::gpu_memory(), models);
}

std::string readable_bytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int k = 0;
  while (k < 6 && bytes >= 1000) {
    bytes /= 1000;
    ++k;
  }
  return fmt::format("{:.3g} {}", bytes, units[k]);
}

void refuse_if_it_cannot_fit(const io::CaseConfig& config, const SizeEstimate& estimate,
                             double available) {
  if (available <= 0 || estimate.bytes <= available) return;
  throw InputError(
      config.spacing_place.first, config.spacing_place.second, "spacing",
      fmt::format("at {} m the case needs about {:.3g} {} and {} of memory; this machine has {}",
                  config.spacing, estimate.elements, estimate.element_name,
                  readable_bytes(estimate.bytes), readable_bytes(available)));
}

}  // namespace sluice
