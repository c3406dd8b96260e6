#pragma once
// Ghost (mirror) particles for planar, axis-aligned walls, Niedoba 2012, §2.2.4 (eqs 2.77-2.78) and
// §3.3 (Fig 3.4). At every RHS evaluation, each fluid particle closer than the kernel support
// (kappa * the largest current h, so variable-h scenes get more images where the gas expands, as in
// Niedoba 2012, §3.4) to a wall gets a mirror
// image behind it; a particle near two walls (a corner) gets three images: one per wall and one
// mirrored through both (Fig 3.4); in 3D near three walls, all seven. Images carry the source's mass
// (Niedoba 2012, §3.3: "m_f = m"), smoothing length and internal energy (Niedoba 2012, §3.5: ghosts
// "take over" the properties of their source), and its density (GhostStateCopy, after the density
// pass). Under a body force the pressure is not simply copied
// (boundary/ghost_hydrostatic_pressure.hpp, after the EOS). Velocities, with v_w the wall velocity:
//   free slip (Niedoba 2012, eqs 2.77-2.78): tangential component kept, normal component mirrored about v_w;
//   no slip: v_g = 2 v_w - v, so the mean of a pair is v_w on the wall (a linear profile continues
//   through the wall);
//   corner image: free slip = both mirrors in turn; no slip = -v + v_wA + v_wB (the velocity that
//   makes the mean of source and image the mean of the two wall velocities; at a stationary corner
//   simply -v). At the moving lid's corners of a driven cavity this gives the average of lid and side
//   wall, i.e. half the lid speed: the corner singularity is smoothed over one image, nothing more.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sphmol/rhs/particle_generator.hpp"
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
struct PlanarWall {
  bool present = false;
  double position = 0.0;  // the wall plane x_d = position
  bool no_slip = true;
  std::array<double, D> velocity{};
};

// walls[d][0] is the lower wall in direction d, walls[d][1] the upper one.
template <int D>
using BoxWalls = std::array<std::array<PlanarWall<D>, 2>, D>;

template <int D>
class GhostGenerator final : public ParticleGenerator<D> {
 public:
  // support: the kernel support in units of h (images are made within support * max h of a wall).
  GhostGenerator(BoxWalls<D> walls, double support) : walls_(walls), support_(support) {}

  bool generate(std::size_t n_base, Particles<D>& pt, Workspace<D>& w) override {
    n_base_ = n_base;
    double hmax = w.h;
    for (std::size_t i = 0; i < w.n_fluid && i < w.hs.size(); ++i) hmax = std::max(hmax, w.hs[i]);
    const double width = support_ * hmax;
    new_source_.clear();
    new_mask_.clear();
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      unsigned near[2 * D];
      int nn = 0;
      for (int d = 0; d < D; ++d)
        for (int s = 0; s < 2; ++s) {
          const auto& wall = walls_[d][s];
          if (!wall.present) continue;
          const double dist = s == 0 ? w.x[d][i] - wall.position : wall.position - w.x[d][i];
          if (dist < width) near[nn++] = 1u << (2 * d + s);
        }
      // every non-empty combination of the nearby walls, never both walls of one direction
      for (unsigned sub = 1; sub < (1u << nn); ++sub) {
        unsigned mask = 0;
        for (int b = 0; b < nn; ++b)
          if (sub & (1u << b)) mask |= near[b];
        bool ok = true;
        for (int d = 0; d < D; ++d) ok = ok && ((mask >> (2 * d)) & 3u) != 3u;
        if (!ok) continue;
        new_source_.push_back(static_cast<std::uint32_t>(i));
        new_mask_.push_back(static_cast<std::uint8_t>(mask));
      }
    }
    const bool changed = new_source_ != source_ || new_mask_ != mask_;
    source_.swap(new_source_);
    mask_.swap(new_mask_);
    const std::size_t n = n_base + source_.size();
    if (changed) {
      pt.mass.resize(n_base);
      pt.rho.resize(n_base);
      pt.kind.resize(n_base);
      for (std::size_t g = 0; g < source_.size(); ++g) {
        pt.mass.push_back(pt.mass[source_[g]]);
        pt.rho.push_back(pt.rho[source_[g]]);
        pt.kind.push_back(Kind::Wall);
      }
    }
    w.n = n;
    for (int d = 0; d < D; ++d) {
      w.x[d].resize(n);
      w.v[d].resize(n);
    }
    w.rho.resize(n);
    w.p.resize(n);
    // Every per-particle array covers the images too: the EOS writes c (and reads e) for all w.n.
    w.c.resize(n);
    w.e.resize(n);
    w.hs.resize(n, w.h);
    for (auto& s : w.strain) s.resize(n);
    for (std::size_t g = 0; g < source_.size(); ++g) {
      const std::size_t i = source_[g];
      image(w, i, mask_[g], n_base + g);
      w.rho[n_base + g] = w.rho[i];
      w.e[n_base + g] = w.e[i];
      w.hs[n_base + g] = w.hs[i];
    }
    return changed;
  }
  std::size_t count() const override { return source_.size(); }
  double max_wall_speed() const override {
    double s = 0.0;
    for (const auto& side : walls_)
      for (const auto& wall : side) {
        if (!wall.present) continue;
        double v2 = 0.0;
        for (double c : wall.velocity) v2 += c * c;
        s = std::max(s, std::sqrt(v2));
      }
    return s;
  }
  std::size_t base() const { return n_base_; }
  const std::vector<std::uint32_t>& sources() const { return source_; }
  const std::vector<std::uint8_t>& masks() const { return mask_; }

 private:
  void image(Workspace<D>& w, std::size_t i, unsigned mask, std::size_t g) const {
    double v[D], vw_sum[D] = {};
    int walls = 0;
    bool all_no_slip = true;
    for (int d = 0; d < D; ++d) {
      w.x[d][g] = w.x[d][i];
      v[d] = w.v[d][i];
    }
    for (int d = 0; d < D; ++d)
      for (int s = 0; s < 2; ++s) {
        if (!(mask & (1u << (2 * d + s)))) continue;
        const auto& wall = walls_[d][s];
        w.x[d][g] = 2.0 * wall.position - w.x[d][g];
        ++walls;
        all_no_slip = all_no_slip && wall.no_slip;
        for (int c = 0; c < D; ++c) vw_sum[c] += wall.velocity[c];
        if (wall.no_slip) {
          for (int c = 0; c < D; ++c) v[c] = 2.0 * wall.velocity[c] - v[c];
        } else {
          v[d] = 2.0 * wall.velocity[d] - v[d];
        }
      }
    if (walls > 1 && all_no_slip)
      for (int c = 0; c < D; ++c) v[c] = -w.v[c][i] + 2.0 * vw_sum[c] / walls;
    for (int c = 0; c < D; ++c) w.v[c][g] = v[c];
  }

  BoxWalls<D> walls_;
  double support_;
  std::size_t n_base_ = 0;
  std::vector<std::uint32_t> source_, new_source_;
  std::vector<std::uint8_t> mask_, new_mask_;
};

// Copies density (and, through the EOS that runs next, pressure) from each ghost's source. Runs right
// after the fluid density pass.
template <int D>
class GhostStateCopy final : public Term<D> {
 public:
  explicit GhostStateCopy(const GhostGenerator<D>* gen) : gen_(gen) {}
  std::string_view name() const override { return "ghost_particles"; }
  void apply(Workspace<D>& w) const override {
    const auto& src = gen_->sources();
    const std::size_t b = gen_->base();
    for (std::size_t g = 0; g < src.size(); ++g) w.rho[b + g] = w.rho[src[g]];
  }

 private:
  const GhostGenerator<D>* gen_;
};

}  // namespace sphmol
