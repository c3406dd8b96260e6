#pragma once
// Weighted RMS norms and dot products whose value does not depend on how the additions are ordered
// or split: the norm ARKODE and CVODE take of their error estimates and corrections, and the dot
// products of the Krylov solves of the implicit integrators (time/viscous_solve.hpp).
//
// Why: a floating-point sum rounds differently in another order, and adaptive step-size and order
// control amplifies last-bit differences of its error norms into another step sequence (on the dam
// break, changing rtol by one part in 1e15 changes ARKODE's steps within 0.01 s of simulated time).
// A run split over threads or MPI ranks adds its partial sums in another order than the serial run,
// so with ordinary sums it would take other steps and agree only to the tolerance.
//
// How: the terms (x_i w_i)^2 (x_i w_i rounded first, as SUNDIALS' serial vector does) are scaled
// by a power of two that puts the largest below 2^96 and truncated to integers; integers add
// exactly, in any order. The largest term is a max (exact in any order) taken first. Terms below
// 2^-96 of the largest are dropped, a relative error of at most N 2^-96 in the sum. The sum of a
// part is kept as three 48-bit chunks, so that parts can be added with ordinary 64-bit integer
// sums (an MPI_SUM over up to 2^16 ranks), and the whole length must stay below 2^31 entries.
// A NaN or infinite term makes the norm infinite, which fails the integrator's error test.
//
// Dot products the same way, for signed terms x_i y_i (rounded first, as SUNDIALS' serial vector
// does): truncated toward zero on the grid of the largest |x_i y_i|, summed modulo 2^128 (two's
// complement, exact in any order while |sum| < 2^127, which 2^31 terms below 2^96 keep), in the same
// three chunks. A NaN or infinite term makes the dot product NaN, which fails the Krylov solve.
//
// Plain signed sums of values v_i the same way (the measurements of a run, run/piece_reduction.hpp):
// on the grid of the largest |v_i|, so that a serial run and a run split over any number of ranks
// add the same integers and convert them to the same double.
#include <sundials/sundials_nvector.h>

#include <array>
#include <cstddef>
#include <cstdint>

namespace sphmol {

using FixedPointChunks = std::array<std::uint64_t, 3>;

// max_i (x_i w_i)^2 over n entries; +infinity if any term is NaN or infinite.
double largest_weighted_square(const double* x, const double* w, std::size_t n);
// The power of two the terms are scaled by, for the largest term of the whole vector (> 0, finite).
int fixed_point_shift(double largest);
// The terms' sum on the grid of `shift`, in chunks.
FixedPointChunks fixed_point_squares(const double* x, const double* w, std::size_t n, int shift);
// sqrt(sum / length) from the chunks summed over every part.
double fixed_point_wrms(const FixedPointChunks& chunks, int shift, double length);
// The whole norm of one part (a serial or OpenMP vector).
double fixed_point_wrms(const double* x, const double* w, std::size_t n);

// max_i |x_i y_i| over n entries; +infinity if any term is NaN or infinite.
double largest_product(const double* x, const double* y, std::size_t n);
// The signed terms' sum on the grid of `shift` (modulo 2^128), in chunks.
FixedPointChunks fixed_point_products(const double* x, const double* y, std::size_t n, int shift);
// The signed sum from the chunks summed over every part.
double fixed_point_sum(const FixedPointChunks& chunks, int shift);
// The whole dot product of one part.
double fixed_point_dot(const double* x, const double* y, std::size_t n);

// max_i |v_i| over n entries; +infinity if any value is NaN or infinite.
double largest_magnitude(const double* v, std::size_t n);
// The signed values' sum on the grid of `shift` (modulo 2^128), in chunks (fixed_point_sum converts).
FixedPointChunks fixed_point_values(const double* v, std::size_t n, int shift);
// The whole sum of one part (NaN if any value is not finite).
double fixed_point_total(const double* v, std::size_t n);

// Replaces the weighted RMS norm of a serial or OpenMP vector (and of every vector cloned from it)
// with fixed_point_wrms.
void use_fixed_point_norm(N_Vector v);
// Replaces the dot product of a serial or OpenMP vector (and of its clones) with fixed_point_dot, and
// removes the fused and local dot products, so that every dot product a solver takes is that one.
void use_fixed_point_dot(N_Vector v);

}  // namespace sphmol
