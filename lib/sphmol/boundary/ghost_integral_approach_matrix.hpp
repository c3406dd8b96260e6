#pragma once
// The integral approach's matrix C (physics/integral_approach_matrix.hpp) at ghost (mirror) images:
// the source's C mirrored, C_g = R C_s R^T, with R the image's reflection. An image's neighbourhood is
// its source's mirrored, images of images included, which the image's own row lacks (no image is
// mirrored again): its own sum would see half a support near the wall. Runs after the fluid rows'
// matrices and before any IA term reads C_j.
#include <memory>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/physics/integral_approach_matrix.hpp"

namespace sphmol {

template <int D>
class GhostIntegralApproachMatrix final : public Term<D> {
 public:
  GhostIntegralApproachMatrix(const GhostGenerator<D>* gen, std::shared_ptr<IntegralApproachField<D>> C)
      : gen_(gen), C_(std::move(C)) {}
  std::string_view name() const override { return "ghost_integral_approach_matrix"; }
  void apply(Workspace<D>& w) const override {
    const auto& src = gen_->sources();
    const auto& masks = gen_->masks();
    const std::size_t b = gen_->base();
    C_->C.resize(w.n * D * D);
    for (std::size_t g = 0; g < src.size(); ++g) {
      double R[D * D];
      gen_->reflection(masks[g], R);
      const double* Cs = C_->of(src[g]);
      double* Cg = C_->C.data() + (b + g) * D * D;
      for (int a = 0; a < D; ++a)
        for (int c = 0; c < D; ++c) {
          double s = 0.0;
          for (int k = 0; k < D; ++k)
            for (int l = 0; l < D; ++l) s += R[a * D + k] * Cs[k * D + l] * R[c * D + l];
          Cg[a * D + c] = s;
        }
    }
  }

 private:
  const GhostGenerator<D>* gen_;
  std::shared_ptr<IntegralApproachField<D>> C_;
};

}  // namespace sphmol
