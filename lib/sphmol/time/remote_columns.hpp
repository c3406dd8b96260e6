#pragma once
// Columns of a viscous operator (time/viscous_operator.hpp) whose velocities live on other
// processes. In a run over MPI ranks (parallel/velocity_halo.hpp) a rank records the viscous sums of
// the fluid particles it owns, over neighbours some of which are halo copies of other ranks'
// particles; applying the operator to a velocity block then needs the halo values of that block,
// fetched from their owners, and the Krylov solves on the block (time/viscous_solve.hpp) need vectors
// whose reductions span every rank, summed exactly so that they equal the serial run's.
#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

#include <cstddef>
#include <cstdint>

namespace sphmol {

class RemoteColumns {
 public:
  virtual ~RemoteColumns() = default;
  // Halo columns; they are numbered after the operator's own rows.
  virtual std::size_t size() const = 0;
  // Collective: the halo values of the velocity block v (`rows` particles, `components` blocks of
  // them) into ext, component d's at ext[d * stride + rows + h] for h < size().
  virtual void fetch(const double* v, std::size_t rows, int components, double* ext, std::size_t stride) const = 0;
  // Collective: a new vector of `length` entries on this process, its dot products and norms reduced
  // over every process in an order-independent way (time/fixed_point_norm.hpp).
  virtual N_Vector new_vector(std::size_t length, SUNContext ctx) const = 0;
  // The distribution of the rows over the processes: the same number on every process, and the same
  // for two operators only when every process owns the same rows in both (a vector made for one then
  // serves the other).
  virtual std::uint64_t distribution() const = 0;
};

}  // namespace sphmol
