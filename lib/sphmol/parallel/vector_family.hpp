#pragma once
// The vectors a SUNDIALS integrator keeps over a rank's part of the state, found again when the
// particles move between ranks (DistributedSystem::repartition).
//
// CVODE, ARKODE and their nonlinear and linear solvers and interpolation modules make every vector
// they keep through the state vector's clone operation (N_VClone, N_VCloneVectorArray): CVODE's
// Nordsieck array and error weights, ARKODE's step solution, stages and interpolation history, the
// Newton and fixed-point solvers' corrections. A family records its root (the vector over the state)
// and every clone made from it or from a clone of it, from N_VClone until N_VDestroy, by taking over
// the nvclone, nvcloneempty and nvdestroy operations of an nvector_parallel root (SUNDIALS
// copies a vector's operations into its clones). At a repartition every member's values move with
// their particles as the state's own do (FamilyMove), so that the integrator finds all of its history
// in the new share, each entry with the particle it belongs to: the weighted norms and dot products
// are exact order-independent sums (fixed_point_norm_mpi.hpp) and every other vector operation acts
// entry by entry, so the integrator continues exactly as in the serial run, without a resize and
// without losing its history (Adams order and step ratios, interpolation history, error controller).
#include <mpi.h>
#include <sundials/sundials_nvector.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace sphmol::parallel {

class VectorFamily {
 public:
  // The live members, in the order they were made (the same on every rank: the integrators clone
  // their vectors in the same order on every rank).
  std::vector<N_Vector> members() const;
  // The vector track_clones() was given (null once destroyed).
  N_Vector root() const;

 private:
  friend struct FamilyRegistry;
  std::vector<N_Vector> members_;
  N_Vector root_ = nullptr;
};

// Makes `root`, an nvector_parallel (N_VMake_Parallel or N_VNew_Parallel), the root of a new
// family: it and every vector cloned from it or from its clones are members until destroyed. The
// family lives while any member does.
std::shared_ptr<VectorFamily> track_clones(N_Vector root);
// The family of a member (null: not a member of any).
std::shared_ptr<VectorFamily> family_of(N_Vector v);

// Moving the members of some families with the particles of the state they are clones of. The
// constructor copies out the values of every member that owns its data (arrays(), each of the
// state's local length, to be moved with the particles exactly as the state is), and notes the
// roots, which wrap the state's storage (`state`). finish() gives every owning member its moved
// values (new storage of the new local length), points the roots at the state's new storage and
// gives empty clones (no data) the new length; the global length does not change. Which members
// own data does not depend on the rank, so every rank moves the same arrays. A root over other
// storage than the state's, or a clone that was given storage of its own (N_VCloneEmpty, then
// N_VSetArrayPointer), cannot be moved: the constructor throws std::logic_error.
class FamilyMove {
 public:
  FamilyMove(const std::vector<std::shared_ptr<VectorFamily>>& families, const double* state, std::size_t length);
  // The owning members' values, in the families' and members' order.
  std::vector<std::vector<double>*> arrays();
  void finish(double* state, std::size_t length);

 private:
  std::vector<std::shared_ptr<VectorFamily>> families_;  // kept alive while moving
  std::vector<N_Vector> owning_, roots_, empty_;
  std::vector<std::vector<double>> values_;
};

}  // namespace sphmol::parallel
