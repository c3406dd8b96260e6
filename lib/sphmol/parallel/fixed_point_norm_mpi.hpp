#pragma once
// SUNDIALS' MPI vector (nvector_parallel) over a rank's part of the state, with the weighted RMS
// norm of time/fixed_point_norm.hpp reduced over the ranks: the largest term by an MPI max, then the
// parts' fixed-point sums by an integer MPI sum. Integer sums do not depend on their order, so the
// norm, and with it ARKODE's and CVODE's steps and the final state, are those of the serial run
// (which takes the same norm) to the bit on any rank count, for two collectives of at most three
// numbers per norm. Dot products (the Krylov solves of the implicit integrators) likewise.
#include <mpi.h>
#include <sundials/sundials_nvector.h>

#include <cstddef>

namespace sphmol::parallel {

// Collective: an MPI vector over this rank's `local` doubles at `data` (no copy), `whole` doubles in
// all, on `comm` (which must outlive the vector and its clones), with the fixed-point norm and dot
// product; the root of a family that records its clones (vector_family.hpp: family_of).
N_Vector make_fixed_point_norm_vector(MPI_Comm comm, double* data, std::size_t local, std::size_t whole, SUNContext ctx);
// Collective: the same over `local` doubles of its own.
N_Vector new_fixed_point_vector(MPI_Comm comm, std::size_t local, std::size_t whole, SUNContext ctx);

}  // namespace sphmol::parallel
