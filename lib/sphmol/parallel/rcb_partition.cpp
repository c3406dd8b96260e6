#include "sphmol/parallel/rcb_partition.hpp"

#include <zoltan.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sphmol::parallel {

namespace {

// What Zoltan's query functions read: the caller's arrays, for the length of one partition call.
template <int D>
struct Objects {
  std::array<const double*, D> x{};
  const double* weight = nullptr;
  const std::uint64_t* gid = nullptr;
  std::size_t n = 0;
};

template <int D>
int count_objects(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<int>(static_cast<Objects<D>*>(data)->n);
}

template <int D>
void list_objects(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int wdim, float* w, int* ierr) {
  const auto& o = *static_cast<Objects<D>*>(data);
  for (std::size_t i = 0; i < o.n; ++i) {
    gids[i] = static_cast<ZOLTAN_ID_TYPE>(o.gid[i]);
    lids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    if (wdim == 1) w[i] = static_cast<float>(o.weight[i]);
  }
  *ierr = ZOLTAN_OK;
}

template <int D>
int dimensions(void*, int* ierr) {
  *ierr = ZOLTAN_OK;
  return D;
}

template <int D>
void coordinates(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int dims, double* out, int* ierr) {
  const auto& o = *static_cast<Objects<D>*>(data);
  for (int k = 0; k < count; ++k)
    for (int d = 0; d < dims; ++d) out[k * dims + d] = o.x[d][lids[k]];
  *ierr = ZOLTAN_OK;
}

void set(Zoltan_Struct* zz, const char* name, const std::string& value) {
  if (Zoltan_Set_Param(zz, name, value.c_str()) != ZOLTAN_OK)
    throw std::runtime_error(std::string("Zoltan refused parameter ") + name + " = " + value);
}

// Zoltan marks an open side with +-DBL_MAX.
double side(double v) {
  if (v >= DBL_MAX) return std::numeric_limits<double>::infinity();
  if (v <= -DBL_MAX) return -std::numeric_limits<double>::infinity();
  return v;
}

}  // namespace

template <int D>
RcbPartitioner<D>::RcbPartitioner(const Communicator& comm, double imbalance_tolerance)
    : comm_(comm), tolerance_(imbalance_tolerance) {
  if (!(imbalance_tolerance > 1.0) || !std::isfinite(imbalance_tolerance))
    throw std::invalid_argument("RCB partition: the imbalance tolerance must be a number above 1 (got " +
                                std::to_string(imbalance_tolerance) + ")");
  float version = 0.0f;
  if (Zoltan_Initialize(0, nullptr, &version) != ZOLTAN_OK) throw std::runtime_error("Zoltan_Initialize failed");
  zz_ = Zoltan_Create(comm_.handle());
  if (zz_ == nullptr) throw std::runtime_error("Zoltan_Create failed");
  set(zz_, "DEBUG_LEVEL", "0");
  set(zz_, "LB_METHOD", "RCB");
  set(zz_, "NUM_GID_ENTRIES", "1");
  set(zz_, "NUM_LID_ENTRIES", "1");
  set(zz_, "OBJ_WEIGHT_DIM", "1");
  set(zz_, "RETURN_LISTS", "EXPORT");
  set(zz_, "IMBALANCE_TOL", std::to_string(imbalance_tolerance));
  set(zz_, "KEEP_CUTS", "1");     // the cut boxes (Zoltan_RCB_Box)
  set(zz_, "AVERAGE_CUTS", "1");  // a cut midway between the particles on its two sides
  set(zz_, "RCB_OUTPUT_LEVEL", "0");
}

template <int D>
RcbPartitioner<D>::~RcbPartitioner() {
  Zoltan_Destroy(&zz_);
}

template <int D>
RcbResult<D> RcbPartitioner<D>::partition(const std::array<const double*, D>& x, const double* weight,
                                          const std::uint64_t* gid, std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("RCB partition: " + std::to_string(n) + " particles on one rank exceed Zoltan's int count");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(weight[i] >= 0.0) || !std::isfinite(weight[i]))
      throw std::invalid_argument("RCB partition: particle " + std::to_string(gid[i]) + " has weight " +
                                  std::to_string(weight[i]) + " (a weight is finite and >= 0)");
    if (gid[i] > std::numeric_limits<ZOLTAN_ID_TYPE>::max())
      throw std::invalid_argument("RCB partition: global id " + std::to_string(gid[i]) + " exceeds Zoltan's id type");
  }
  Objects<D> objects{x, weight, gid, n};
  Zoltan_Set_Num_Obj_Fn(zz_, count_objects<D>, &objects);
  Zoltan_Set_Obj_List_Fn(zz_, list_objects<D>, &objects);
  Zoltan_Set_Num_Geom_Fn(zz_, dimensions<D>, &objects);
  Zoltan_Set_Geom_Multi_Fn(zz_, coordinates<D>, &objects);

  int changes = 0, n_gid = 0, n_lid = 0, n_import = 0, n_export = 0;
  ZOLTAN_ID_PTR import_gid = nullptr, import_lid = nullptr, export_gid = nullptr, export_lid = nullptr;
  int *import_proc = nullptr, *import_part = nullptr, *export_proc = nullptr, *export_part = nullptr;
  const int rc = Zoltan_LB_Partition(zz_, &changes, &n_gid, &n_lid, &n_import, &import_gid, &import_lid, &import_proc,
                                     &import_part, &n_export, &export_gid, &export_lid, &export_proc, &export_part);
  // The query functions must not outlive `objects`.
  Zoltan_Set_Num_Obj_Fn(zz_, nullptr, nullptr);
  Zoltan_Set_Obj_List_Fn(zz_, nullptr, nullptr);
  Zoltan_Set_Num_Geom_Fn(zz_, nullptr, nullptr);
  Zoltan_Set_Geom_Multi_Fn(zz_, nullptr, nullptr);
  if (rc != ZOLTAN_OK && rc != ZOLTAN_WARN) {
    Zoltan_LB_Free_Part(&import_gid, &import_lid, &import_proc, &import_part);
    Zoltan_LB_Free_Part(&export_gid, &export_lid, &export_proc, &export_part);
    throw std::runtime_error("Zoltan RCB partition failed (error code " + std::to_string(rc) + ")");
  }

  RcbResult<D> out;
  out.destination.assign(n, comm_.rank());
  for (int k = 0; k < n_export; ++k) out.destination[export_lid[k]] = export_proc[k];
  out.changed = changes != 0;
  Zoltan_LB_Free_Part(&import_gid, &import_lid, &import_proc, &import_part);
  Zoltan_LB_Free_Part(&export_gid, &export_lid, &export_proc, &export_part);

  out.boxes.resize(static_cast<std::size_t>(comm_.size()));
  if (comm_.size() == 1) {
    // Zoltan makes no cut for one rank (and keeps no box): the one box is everything.
    out.boxes[0].lo.fill(-std::numeric_limits<double>::infinity());
    out.boxes[0].hi.fill(std::numeric_limits<double>::infinity());
    return out;
  }
  for (int r = 0; r < comm_.size(); ++r) {
    int dims = 0;
    double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
    if (Zoltan_RCB_Box(zz_, r, &dims, &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]) != ZOLTAN_OK || dims != D)
      throw std::runtime_error("Zoltan gave no cut box for rank " + std::to_string(r));
    for (int d = 0; d < D; ++d) {
      out.boxes[r].lo[d] = side(lo[d]);
      out.boxes[r].hi[d] = side(hi[d]);
    }
  }
  return out;
}

double load_imbalance(const Communicator& comm, double local_weight) {
  const double total = comm.sum(local_weight), largest = comm.max(local_weight);
  return total > 0.0 ? largest * comm.size() / total : 1.0;
}

template class RcbPartitioner<1>;
template class RcbPartitioner<2>;
template class RcbPartitioner<3>;

}  // namespace sphmol::parallel
