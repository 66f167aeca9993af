#include "parallel/ZoltanPartitioner.hpp"

#include <fmt/format.h>
#include <mpi.h>
#include <zoltan.h>

#include <algorithm>
#include <numeric>

#include "core/Error.hpp"

namespace isph {

namespace {

// What Zoltan's query functions read: this rank's points of the partition being made.
struct Points {
  const std::vector<Vec3>* x;
  const std::vector<double>* weights;
  const std::vector<label>* ids;
  int dimension;
};

void check(int status, const char* what) {
  if (status != ZOLTAN_OK && status != ZOLTAN_WARN) fatalError(fmt::format("Zoltan: {} failed (error {})", what, status));
}

int numObjects(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<int>(static_cast<const Points*>(data)->x->size());
}

void objectList(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int wdim, float* weights, int* ierr) {
  const auto& p = *static_cast<const Points*>(data);
  for (std::size_t i = 0; i < p.x->size(); ++i) {
    gids[i] = static_cast<ZOLTAN_ID_TYPE>((*p.ids)[i]);
    lids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    if (wdim > 0) weights[i] = static_cast<float>((*p.weights)[i]);
  }
  *ierr = ZOLTAN_OK;
}

int numGeometry(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<const Points*>(data)->dimension;
}

void geometry(void* data, int, int, int n, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int dim, double* out, int* ierr) {
  const auto& p = *static_cast<const Points*>(data);
  for (int k = 0; k < n; ++k) {
    const Vec3& x = (*p.x)[lids[k]];
    for (int d = 0; d < dim; ++d) out[k * dim + d] = x[d];
  }
  *ierr = ZOLTAN_OK;
}

void initialiseZoltanOnce() {
  static bool done = false;
  if (done) return;
  float version = 0;
  check(Zoltan_Initialize(0, nullptr, &version), "Zoltan_Initialize");
  done = true;
}

}  // namespace

ZoltanPartitioner::ZoltanPartitioner(const std::string& algorithm, int dimension, int nParts)
    : algorithm_(algorithm), dimension_(dimension), nParts_(nParts) {
  if (algorithm != "RCB" && algorithm != "HSFC") {
    fatalError(fmt::format("Zoltan: unknown algorithm '{}' (expected RCB or HSFC)", algorithm));
  }
  if (dimension < 1 || dimension > 3) fatalError(fmt::format("Zoltan: dimension {} is not 1, 2 or 3", dimension));
  if (nParts < 1) fatalError(fmt::format("Zoltan: {} parts", nParts));
  initialiseZoltanOnce();
  zz_ = Zoltan_Create(MPI_COMM_WORLD);
  if (!zz_) fatalError("Zoltan_Create failed");
  const std::pair<const char*, std::string> parameters[] = {
      {"DEBUG_LEVEL", "0"},
      {"LB_METHOD", algorithm},
      {"NUM_GID_ENTRIES", "1"},
      {"NUM_LID_ENTRIES", "1"},
      {"OBJ_WEIGHT_DIM", "1"},
      {"NUM_GLOBAL_PARTS", std::to_string(nParts)},
      {"RETURN_LISTS", "PARTS"},  // the part of every local object
      {"KEEP_CUTS", "1"},         // for partOf()
      {"REMAP", "1"},             // a new partition moves as little as it can
      {"IMBALANCE_TOL", "1.02"},
  };
  for (const auto& [name, value] : parameters) check(Zoltan_Set_Param(zz_, name, value.c_str()), name);
  if (algorithm == "RCB") {
    check(Zoltan_Set_Param(zz_, "RCB_REUSE", "1"), "RCB_REUSE");
    // Cuts halfway between the points on either side: a cut through a point would leave
    // partOf() to decide a tie its own way.
    check(Zoltan_Set_Param(zz_, "AVERAGE_CUTS", "1"), "AVERAGE_CUTS");
  }
}

ZoltanPartitioner::~ZoltanPartitioner() {
  if (zz_) Zoltan_Destroy(&zz_);
}

std::vector<int> ZoltanPartitioner::partition(const std::vector<Vec3>& points, const std::vector<double>& weights,
                                              const std::vector<label>& ids) {
  if (weights.size() != points.size() || ids.size() != points.size()) {
    fatalError("ZoltanPartitioner::partition: points, weights and ids differ in length");
  }
  Points data{&points, &weights, &ids, dimension_};
  check(Zoltan_Set_Num_Obj_Fn(zz_, numObjects, &data), "Zoltan_Set_Num_Obj_Fn");
  check(Zoltan_Set_Obj_List_Fn(zz_, objectList, &data), "Zoltan_Set_Obj_List_Fn");
  check(Zoltan_Set_Num_Geom_Fn(zz_, numGeometry, &data), "Zoltan_Set_Num_Geom_Fn");
  check(Zoltan_Set_Geom_Multi_Fn(zz_, geometry, &data), "Zoltan_Set_Geom_Multi_Fn");

  int changes = 0, nGid = 0, nLid = 0, nImport = 0, nExport = 0;
  ZOLTAN_ID_PTR importGids = nullptr, importLids = nullptr, exportGids = nullptr, exportLids = nullptr;
  int *importProcs = nullptr, *importParts = nullptr, *exportProcs = nullptr, *exportParts = nullptr;
  const int status = Zoltan_LB_Partition(zz_, &changes, &nGid, &nLid, &nImport, &importGids, &importLids, &importProcs,
                                         &importParts, &nExport, &exportGids, &exportLids, &exportProcs, &exportParts);
  Zoltan_LB_Free_Part(&importGids, &importLids, &importProcs, &importParts);
  Zoltan_LB_Free_Part(&exportGids, &exportLids, &exportProcs, &exportParts);
  check(status, "Zoltan_LB_Partition");
  // Each point in the part of the region that holds it, by the kept cuts: where the partition
  // itself splits points of equal coordinates (RCB balancing a row of a lattice, or a dummy
  // particle placed at its wall particle) between two parts, the cuts put them all on one side,
  // so equal points share a part, now and at every later partOf().
  partitioned_ = true;
  std::vector<int> part(points.size(), -1);
  for (std::size_t i = 0; i < points.size(); ++i) part[i] = partOf(points[i]);
  return part;
}

int ZoltanPartitioner::partOf(const Vec3& x) const {
  if (!partitioned_) fatalError("ZoltanPartitioner::partOf called before partition");
  double coords[3] = {x[0], x[1], x[2]};
  int proc = -1, part = -1;
  check(Zoltan_LB_Point_PP_Assign(zz_, coords, &proc, &part), "Zoltan_LB_Point_PP_Assign");
  return part;
}

double imbalance(const std::vector<double>& loads) {
  if (loads.empty()) return 1.0;
  const double total = std::accumulate(loads.begin(), loads.end(), 0.0);
  if (total <= 0) return 1.0;
  return *std::max_element(loads.begin(), loads.end()) / (total / static_cast<double>(loads.size()));
}

}  // namespace isph
