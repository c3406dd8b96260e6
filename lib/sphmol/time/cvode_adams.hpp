#pragma once
// SUNDIALS CVODE, Adams-Moulton (orders 1-12, variable step) for the non-stiff SPH system, with
// the fixed-point (functional) nonlinear iteration of SUNNonlinSol_FixedPoint: no Jacobian.
// Tolerances rtol/atol. CVODE has no stability callback, so the CFL limit is imposed through
// CVodeSetMaxStep, updated after every step from the stable step of the latest RHS evaluation.
// The N_Vector wraps the caller's state storage (no copy): serial, or the system's own when its
// state is split over processes (time/state_vector.hpp).
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_nonlinearsolver.h>

#include "sphmol/time/integrator.hpp"

namespace sphmol {

class CvodeAdams final : public Integrator {
 public:
  struct Options {
    double rtol = 1e-6, atol = 1e-12;
    long max_steps = 10'000'000;
  };
  explicit CvodeAdams(Options o) : opt_(o) {}
  ~CvodeAdams() override;
  CvodeAdams(const CvodeAdams&) = delete;
  CvodeAdams& operator=(const CvodeAdams&) = delete;

  std::string name() const override { return "cvode_adams"; }
  nlohmann::json describe() const override;
  void initialize(OdeSystem& sys, double t0, double* y) override;
  void advance(double tout) override;
  // One internal CVODE step (CV_ONE_STEP) with the stop time at tout, so the run loop sees a signal
  // after every step; advance() takes exactly these steps.
  double step_toward(double tout) override;
  IntegratorStats stats() const override;
  // CVODE's Adams history is of the old f: freed, and CVODE started again at (t, y), counts kept.
  void restart(OdeSystem& sys, double t, double* y) override;
  // A repartition over ranks moves the state vector and every vector CVODE and its fixed-point
  // solver cloned from it (the Nordsieck history, error weights, corrections) with the particles
  // (StateVectorMaker, time/state_vector.hpp): CVODE goes on with its order, step and history as in
  // the serial run. Nothing else here holds per-particle values; the step limit, from the latest
  // evaluation, is unchanged.
  bool can_resize() const override { return true; }
  void resize(OdeSystem& sys, double t, double* y) override;
  // Only the counters are saved (the summary's steps continue); the Nordsieck history is not, so a
  // restart is a fresh start from (t, y) that agrees within the tolerance.
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 private:
  void release();
  static int rhs_callback(double t, N_Vector y, N_Vector ydot, void* self);

  Options opt_;
  OdeSystem* sys_ = nullptr;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  SUNNonlinearSolver nls_ = nullptr;
  void* mem_ = nullptr;
  double t_ = 0.0;
  double tstop_ = 0.0;  // the stop time set in CVODE (set again only when it changes)
  bool tstop_set_ = false;
  long steps_before_ = 0, rejected_before_ = 0;  // counted before a restart
};

}  // namespace sphmol
