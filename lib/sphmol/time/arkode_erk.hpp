#pragma once
// SUNDIALS ARKODE ERKStep: any explicit Butcher table by name, adaptive (rtol/atol) with the CFL
// limit supplied through the stability callback, or fixed step. The N_Vector wraps the caller's
// state storage (no copy): serial or OpenMP, or the system's own when its state is split over
// processes (time/state_vector.hpp).
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <optional>
#include <utility>

#include "sphmol/time/integrator.hpp"

namespace sphmol {

class ArkodeErk final : public Integrator {
 public:
  struct Options {
    std::string table = "ARKODE_DORMAND_PRINCE_7_4_5";
    double rtol = 1e-6, atol = 1e-12;
    std::optional<double> fixed_step;
    long max_steps = 10'000'000;
  };
  explicit ArkodeErk(Options o);
  ~ArkodeErk() override;
  ArkodeErk(const ArkodeErk&) = delete;
  ArkodeErk& operator=(const ArkodeErk&) = delete;

  std::string name() const override { return "arkode_erk"; }
  nlohmann::json describe() const override;
  void initialize(OdeSystem& sys, double t0, double* y) override;
  void advance(double tout) override;
  IntegratorStats stats() const override;
  double step_toward(double tout) override;
  // Saves the current step size and the counters; a restart begins with that step as the initial step. The Runge-Kutta
  // history and error-controller memory are not saved, so a restart agrees within the tolerance,
  // not bit for bit.
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;
  // A repartition over ranks moves the state vector and every vector ERKStep cloned from it (the
  // step solution, stages, the last f, the interpolation history, error weights) with the particles
  // (StateVectorMaker, time/state_vector.hpp): ERKStep goes on as in the serial run, without an
  // evaluation. Nothing else here holds per-particle values.
  bool can_resize() const override { return true; }
  void resize(OdeSystem& sys, double t, double* y) override;
  // ERKStepResize at (t, y): the vectors and the first stage are computed anew (f changed: fluid
  // was taken out), the step size, the error controller's history and the counts are kept.
  void restart(OdeSystem& sys, double t, double* y) override;

 private:
  static int rhs_callback(double t, N_Vector y, N_Vector ydot, void* self);
  static int stability_callback(N_Vector y, double t, double* hstab, void* self);
  // Step attempts the CFL limit sized, and those the error controller sized, since the run's start.
  std::pair<long, long> limited_steps() const;

  Options opt_;
  OdeSystem* sys_ = nullptr;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  void* mem_ = nullptr;
  double t_ = 0.0;
  long steps_before_ = 0, rejected_before_ = 0;  // counted before a restart
  long stability_limited_before_ = 0, accuracy_limited_before_ = 0;  // the same, from the checkpoint
};

}  // namespace sphmol
