#pragma once
// SUNDIALS ARKODE ARKStep with an additive Runge-Kutta ImEx pair (Kennedy & Carpenter 2003): the
// explicit part f_E of the split (time/imex_system.hpp) by the pair's ERK table, the viscous part by
// its DIRK table, adaptive (rtol/atol, explicit stability limit through the stability callback) or
// fixed step.
//
// The implicit part is f_I = L_n v + b_n with the operator frozen at the step's start y_n
// (time/viscous_operator.hpp), and the explicit part takes the rest, f_E = f - L_n v - b_n, so that
// f_E + f_I = f at every stage. f_I is then exactly linear in y (ARKStepSetLinear: one Newton
// iteration solves each stage) and its Jacobian is known, J v = L_n v on the velocity block: the
// stage systems (I - gamma J) z = r are the identity off that block, and on it are solved matrix-free
// by SUNDIALS' own Krylov solver (PCG or GMRES) with a Jacobi preconditioner 1 - gamma diag(L_n)
// (time/stage_linear_solver.hpp), starting from ARKStep's predictor. The error test and the stage
// solves' tolerance use weights with the state blocks' own scales (time/block_error_weights.hpp). The
// remainder (L(x) - L_n) v left in f_E changes over a step by O(dt v / h) relative to L: far from
// stiff at the acoustic step. The operator is rebuilt after every accepted step (the
// postprocess-step callback) from that evaluation, which the next step's first stage reuses.
#include <arkode/arkode_arkstep.h>
#include <sundials/sundials_context.h>

#include <memory>
#include <optional>
#include <vector>

#include "sphmol/config/ark_pairs.hpp"
#include "sphmol/time/imex_system.hpp"
#include "sphmol/time/integrator.hpp"
#include "sphmol/time/stage_linear_solver.hpp"
#include "sphmol/time/viscous_solve.hpp"

namespace sphmol {

class ArkodeImex final : public Integrator {
 public:
  struct Options {
    std::string table = "ARKODE_ARK324L2SA_ERK_4_2_3";  // either table of the pair
    double rtol = 1e-6, atol = 1e-12;
    std::optional<double> fixed_step;
    long max_steps = 10'000'000;
    KrylovOptions krylov;  // solver and max_iterations (the tolerance follows from rtol/atol)
  };
  explicit ArkodeImex(Options o);
  ~ArkodeImex() override;
  ArkodeImex(const ArkodeImex&) = delete;
  ArkodeImex& operator=(const ArkodeImex&) = delete;

  std::string name() const override { return "arkode_imex"; }
  nlohmann::json describe() const override;
  void initialize(OdeSystem& sys, double t0, double* y) override;
  void advance(double tout) override;
  IntegratorStats stats() const override;
  // ARKStep's stages are of the old f: freed, and ARKStep started again at (t, y), counts kept.
  void restart(OdeSystem& sys, double t, double* y) override;
  double step_toward(double tout) override;
  // A repartition over ranks moves the state vector and every vector ARKStep, its nonlinear and
  // linear solver interfaces and its interpolation module cloned from it (the step solution, stages,
  // error weights, the predictor's interpolation history) with the particles (StateVectorMaker,
  // time/state_vector.hpp). What this class holds per particle is made again on the new share: the
  // frozen operator L_n, b_n (and the cached evaluation) by one evaluation at (t, y), which is y_n,
  // where the serial run recorded them (step_done_callback); the stage solver's block bounds. The
  // steps, stage solves and Krylov iterations go on as in the serial run.
  bool can_resize() const override { return true; }
  void resize(OdeSystem& sys, double t, double* y) override;
  // As arkode_erk: the step size and the counters are saved, the Runge-Kutta history is not (a
  // restart agrees within the tolerance).
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;
  long krylov_iterations() const { return counts().krylov; }

 private:
  void release();  // frees what initialize() made (the destructor, restart())
  static int fe_callback(double t, N_Vector y, N_Vector ydot, void* self);
  static int fi_callback(double t, N_Vector y, N_Vector ydot, void* self);
  static int weights_callback(N_Vector y, N_Vector w, void* self);
  static int stability_callback(N_Vector y, double t, double* hstab, void* self);
  static int step_done_callback(double t, N_Vector y, void* self);
  // f_E(t, y) unfrozen and W = L(x) v + b(x) of the state, from the cache when (t, y) is the last
  // state evaluated.
  void evaluate(double t, const double* y);
  // Takes `sys` at (t, y): its velocity block, empty caches, and the frozen operator recorded at
  // (t, y). initialize() and resize() (the new share after a repartition) alike.
  void bind(OdeSystem& sys, double t, const double* y);

  Options opt_;
  OdeSystem* sys_ = nullptr;
  ImexSystem* imex_ = nullptr;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  std::unique_ptr<StageLinearSolver> ls_;
  void* mem_ = nullptr;
  double t_ = 0.0;
  std::size_t vb_ = 0, nv_ = 0;
  ViscousOperator frozen_, scratch_;  // L_n, b_n; the latest evaluation's operator
  std::vector<double> cache_y_, cache_fe_, cache_w_, wn_;
  double cache_t_ = 0.0;
  bool cached_ = false;
  bool cache_frozen_ = false;  // the cached evaluation's operator is the frozen one (a step's start)
  // What the solver counts, since the run's start: ARKStep's own counts plus those before a restart
  // (in the run, or from the checkpoint), which ARKStep started again from 0.
  struct Counts {
    long steps = 0, rejected = 0, stage_solves = 0, krylov = 0, stability_limited = 0, accuracy_limited = 0;
  };
  Counts counts() const;
  Counts before_;
};

}  // namespace sphmol
