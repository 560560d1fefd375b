#include "sluice/parallel/rcb_partition.hpp"

#include <stdexcept>

#ifdef SLUICE_WITH_ZOLTAN
#include <zoltan.h>

#include <cfloat>
#include <cstdint>
#include <limits>
#endif

namespace sluice {

#ifndef SLUICE_WITH_ZOLTAN
bool rcb_offered() {
  return false;
}

Decomposition rcb_boxes(const Communicator&, int, std::span<const double>,
                        std::span<const double>) {
  throw std::logic_error("rcb_boxes: this build has no Zoltan (SLUICE_WITH_ZOLTAN=OFF)");
}
#else
bool rcb_offered() {
  return true;
}

namespace {

// What Zoltan's query functions read: this rank's points.
struct Points {
  int dimension;
  std::span<const double> coordinates, work;
  ZOLTAN_ID_TYPE first_id;  // this rank's first global number
  std::size_t count() const { return work.size(); }
};

int count_of(void* data, int* error) {
  *error = ZOLTAN_OK;
  return static_cast<int>(static_cast<Points*>(data)->count());
}

void list_of(void* data, int, int, ZOLTAN_ID_PTR global, ZOLTAN_ID_PTR local, int, float* weights,
             int* error) {
  const auto& p = *static_cast<Points*>(data);
  for (std::size_t i = 0; i < p.count(); ++i) {
    global[i] = p.first_id + static_cast<ZOLTAN_ID_TYPE>(i);
    local[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    weights[i] = static_cast<float>(p.work[i]);
  }
  *error = ZOLTAN_OK;
}

int dimension_of(void* data, int* error) {
  *error = ZOLTAN_OK;
  return static_cast<Points*>(data)->dimension;
}

void coordinates_of(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR local,
                    int dimension, double* out, int* error) {
  const auto& p = *static_cast<Points*>(data);
  for (int k = 0; k < count; ++k) {
    for (int a = 0; a < dimension; ++a)
      out[k * dimension + a] = p.coordinates[local[k] * static_cast<std::size_t>(dimension) + a];
  }
  *error = ZOLTAN_OK;
}

void check(int code, const char* what) {
  if (code != ZOLTAN_OK && code != ZOLTAN_WARN)
    throw std::runtime_error(std::string("Zoltan: ") + what + " failed");
}

// Zoltan gives an open side as +-DBL_MAX; the boxes hold infinity there.
double open_ended(double bound) {
  if (bound <= -DBL_MAX) return -std::numeric_limits<double>::infinity();
  if (bound >= DBL_MAX) return std::numeric_limits<double>::infinity();
  return bound;
}

}  // namespace

Decomposition rcb_boxes(const Communicator& ranks, int dimension, std::span<const double> points,
                        std::span<const double> work) {
  if (points.size() != work.size() * static_cast<std::size_t>(dimension))
    throw std::logic_error("rcb_boxes: `dimension` coordinates and one weight a point");
  if (!ranks.split()) {
    RankBox all;
    all.lo.fill(-std::numeric_limits<double>::infinity());
    all.hi.fill(std::numeric_limits<double>::infinity());
    return Decomposition(dimension, {all});
  }
  static const bool initialized = [] {
    float version = 0;
    return Zoltan_Initialize(0, nullptr, &version) == ZOLTAN_OK;
  }();
  if (!initialized) throw std::runtime_error("Zoltan: Zoltan_Initialize failed");

  // Each rank's points are numbered after those of the ranks before it.
  const std::vector<double> counts = ranks.gather_all(std::vector<double>{double(work.size())});
  double before = 0;
  for (int r = 0; r < ranks.rank(); ++r) before += counts[static_cast<std::size_t>(r)];
  Points p{dimension, points, work, static_cast<ZOLTAN_ID_TYPE>(before)};

  Zoltan_Struct* zz = Zoltan_Create(MPI_COMM_WORLD);
  if (zz == nullptr) throw std::runtime_error("Zoltan: Zoltan_Create failed");
  struct Destroy {
    Zoltan_Struct*& zz;
    ~Destroy() { Zoltan_Destroy(&zz); }
  } destroy{zz};
  for (const auto& [name, value] : {std::pair{"DEBUG_LEVEL", "0"},
                                    {"LB_METHOD", "RCB"},
                                    {"KEEP_CUTS", "1"},
                                    {"RETURN_LISTS", "NONE"},
                                    {"OBJ_WEIGHT_DIM", "1"},
                                    {"NUM_GID_ENTRIES", "1"},
                                    {"NUM_LID_ENTRIES", "1"},
                                    {"IMBALANCE_TOL", "1.02"}}) {
    check(Zoltan_Set_Param(zz, name, value), name);
  }
  Zoltan_Set_Num_Obj_Fn(zz, count_of, &p);
  Zoltan_Set_Obj_List_Fn(zz, list_of, &p);
  Zoltan_Set_Num_Geom_Fn(zz, dimension_of, &p);
  Zoltan_Set_Geom_Multi_Fn(zz, coordinates_of, &p);

  int changes = 0, global_entries = 0, local_entries = 0, imports = 0, exports = 0;
  ZOLTAN_ID_PTR import_global = nullptr, import_local = nullptr;
  ZOLTAN_ID_PTR export_global = nullptr, export_local = nullptr;
  int *import_ranks = nullptr, *import_parts = nullptr, *export_ranks = nullptr,
      *export_parts = nullptr;
  check(Zoltan_LB_Partition(zz, &changes, &global_entries, &local_entries, &imports, &import_global,
                            &import_local, &import_ranks, &import_parts, &exports, &export_global,
                            &export_local, &export_ranks, &export_parts),
        "Zoltan_LB_Partition");
  Zoltan_LB_Free_Part(&import_global, &import_local, &import_ranks, &import_parts);
  Zoltan_LB_Free_Part(&export_global, &export_local, &export_ranks, &export_parts);

  std::vector<RankBox> boxes(static_cast<std::size_t>(ranks.size()));
  for (int r = 0; r < ranks.size(); ++r) {
    int axes = 0;
    RankBox& b = boxes[static_cast<std::size_t>(r)];
    check(Zoltan_RCB_Box(zz, r, &axes, &b.lo[0], &b.lo[1], &b.lo[2], &b.hi[0], &b.hi[1], &b.hi[2]),
          "Zoltan_RCB_Box");
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = open_ended(b.lo[a]);
      b.hi[a] = open_ended(b.hi[a]);
    }
  }
  return Decomposition(dimension, std::move(boxes));
}
#endif

}  // namespace sluice
