#include "sphmol/parallel/vector_family.hpp"

#include <nvector/nvector_parallel.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <stdexcept>
#include <unordered_map>

namespace sphmol::parallel {

// Every tracked vector's family. SUNDIALS' operations are plain C function pointers with no room for
// a context, and an nvector_parallel's content has no spare field, so the family is found by the
// vector's address.
struct FamilyRegistry {
  std::mutex lock;
  std::unordered_map<N_Vector, std::shared_ptr<VectorFamily>> of;

  static FamilyRegistry& get() {
    static FamilyRegistry registry;
    return registry;
  }
  void add(N_Vector v, std::shared_ptr<VectorFamily> family, bool root = false) {
    const std::lock_guard<std::mutex> hold(lock);
    family->members_.push_back(v);
    if (root) family->root_ = v;
    of.emplace(v, std::move(family));
  }
  std::shared_ptr<VectorFamily> find(N_Vector v) {
    const std::lock_guard<std::mutex> hold(lock);
    const auto it = of.find(v);
    return it == of.end() ? nullptr : it->second;
  }
  void remove(N_Vector v) {
    std::shared_ptr<VectorFamily> family;  // released after the lock
    const std::lock_guard<std::mutex> hold(lock);
    const auto it = of.find(v);
    if (it == of.end()) return;
    family = std::move(it->second);
    of.erase(it);
    auto& m = family->members_;
    m.erase(std::remove(m.begin(), m.end(), v), m.end());
    if (family->root_ == v) family->root_ = nullptr;
  }
  std::vector<N_Vector> members(const VectorFamily& f) {
    const std::lock_guard<std::mutex> hold(lock);
    return f.members_;
  }
  N_Vector root(const VectorFamily& f) {
    const std::lock_guard<std::mutex> hold(lock);
    return f.root_;
  }
};

namespace {

// The clone operations of a member: nvector_parallel's own, then the clone joins its template's
// family. They are C callbacks: no exception may leave them (SUNDIALS reads a null clone as a failed
// allocation).
// nvector_parallel's clone `make` of w, joined to w's family.
N_Vector join_family(N_Vector w, N_Vector (*make)(N_Vector)) {
  N_Vector v = make(w);
  if (!v) return nullptr;
  try {
    if (auto family = FamilyRegistry::get().find(w)) FamilyRegistry::get().add(v, std::move(family));
  } catch (...) {
    N_VDestroy_Parallel(v);
    return nullptr;
  }
  return v;
}

N_Vector tracked_clone(N_Vector w) { return join_family(w, N_VClone_Parallel); }
N_Vector tracked_clone_empty(N_Vector w) { return join_family(w, N_VCloneEmpty_Parallel); }

void tracked_destroy(N_Vector v) {
  if (!v) return;
  FamilyRegistry::get().remove(v);
  N_VDestroy_Parallel(v);
}

}  // namespace

std::vector<N_Vector> VectorFamily::members() const { return FamilyRegistry::get().members(*this); }
N_Vector VectorFamily::root() const { return FamilyRegistry::get().root(*this); }

std::shared_ptr<VectorFamily> track_clones(N_Vector root) {
  if (!root || N_VGetVectorID(root) != SUNDIALS_NVEC_PARALLEL) throw std::invalid_argument("track_clones: not an nvector_parallel");
  if (family_of(root)) throw std::logic_error("track_clones: the vector is a member of a family already");
  auto family = std::make_shared<VectorFamily>();
  FamilyRegistry::get().add(root, family, true);
  root->ops->nvclone = &tracked_clone;
  root->ops->nvcloneempty = &tracked_clone_empty;
  root->ops->nvdestroy = &tracked_destroy;
  return family;
}

std::shared_ptr<VectorFamily> family_of(N_Vector v) { return FamilyRegistry::get().find(v); }

FamilyMove::FamilyMove(const std::vector<std::shared_ptr<VectorFamily>>& families, const double* state, std::size_t length)
    : families_(families) {
  for (const auto& family : families_) {
    if (!family) continue;
    for (N_Vector v : family->members()) {
      const double* data = NV_DATA_P(v);
      const auto n = static_cast<std::size_t>(NV_LOCLENGTH_P(v));
      if (n != length) throw std::logic_error("FamilyMove: a member is not of the state's local length");
      if (v == family->root()) {
        if (n > 0 && data != state) throw std::logic_error("FamilyMove: a family's root does not wrap the state");
        roots_.push_back(v);
      } else if (NV_OWN_DATA_P(v) == SUNTRUE) {
        owning_.push_back(v);
        values_.emplace_back(data, data + n);
      } else if (data == nullptr) {
        empty_.push_back(v);
      } else {
        throw std::logic_error("FamilyMove: a clone wraps storage it does not own, which cannot move");
      }
    }
  }
}

std::vector<std::vector<double>*> FamilyMove::arrays() {
  std::vector<std::vector<double>*> a;
  for (auto& v : values_) a.push_back(&v);
  return a;
}

void FamilyMove::finish(double* state, std::size_t length) {
  for (std::size_t k = 0; k < owning_.size(); ++k) {
    N_Vector v = owning_[k];
    const std::vector<double>& values = values_[k];
    if (values.size() != length) throw std::logic_error("FamilyMove::finish: a moved member is not of the state's new length");
    // N_VDestroy_Parallel frees owned data with free(): it is allocated as N_VNew_Parallel does
    // (nothing for no entries).
    double* data = nullptr;
    if (length > 0) {
      data = static_cast<double*>(std::malloc(length * sizeof(double)));
      if (!data) throw std::bad_alloc();
      std::memcpy(data, values.data(), length * sizeof(double));
    }
    std::free(NV_DATA_P(v));
    NV_DATA_P(v) = data;
    NV_LOCLENGTH_P(v) = static_cast<sunindextype>(length);
  }
  for (N_Vector v : roots_) {
    NV_DATA_P(v) = state;
    NV_LOCLENGTH_P(v) = static_cast<sunindextype>(length);
  }
  for (N_Vector v : empty_) NV_LOCLENGTH_P(v) = static_cast<sunindextype>(length);
  owning_.clear();
  roots_.clear();
  empty_.clear();
  values_.clear();
}

}  // namespace sphmol::parallel
