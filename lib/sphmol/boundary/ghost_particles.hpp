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
//   through the wall), in the viscous terms only (Workspace::v_viscous, read by the Morris and the
//   strain-rate viscosity). Every other pair sum (continuity, pressure, energy, artificial viscosity)
//   sees the free-slip image, which holds the flow through the wall to v_w.n and nothing else: as
//   with Adami et al. (2012)'s wall velocity for wall particles, the no-slip velocity in the
//   continuity sum would compress or expand the fluid beside the wall wherever it slips along it (an
//   inviscid dam break in a ghost-walled scene gained kinetic energy beyond what gravity put in and
//   blew up at t = 0.086 s; a 2D shock tube with no-slip mirrors at t = 0.026 s);
//   corner image: free slip = both mirrors in turn; no slip (viscous) = per direction: the component along each
//   mirror's normal n_k mirrored about that wall's own normal velocity (2 v_wk.n_k - v.n_k, so no
//   wall lets fluid through), and the component tangent to every mirror of the corner (the edge
//   direction in 3D; none in 2D) as 2 <v_w> - v, <v_w> the mean of the walls' tangential velocities
//   projected on that direction. A wall's tangential velocity is normal to the other wall of the
//   corner: at the lid's corners of a driven cavity the lid speed is the side wall's normal
//   direction, and taking it into the corner image (as -v + v_wA + v_wB does) makes the mean of
//   source and image U/2 through the side wall: the fluid next to the lid was pumped out of the box
//   (a 40^2 cavity at Re 100 lost particles through the side walls and blew up at t = 0.44 s).
// Besides the box's faces, any plane (GhostPlane: a unit normal into the fluid, not necessarily along
// an axis) mirrors the same way: x_g = x - 2 (n.x - c) n, and free slip mirrors the normal component
// of v - v_w. Corner images are made for every set of nearby mirrors that are pairwise at right
// angles (the images of mirrors at other angles do not close; the scene builder refuses such mirrors
// where the fluid could reach both, scene/ghost_planes.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
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

// |n_a . n_b| below this: two mirrors at right angles (corner images); |n_a . n_b| within it of 1:
// parallel. Loose enough for normals typed to 7 digits.
inline constexpr double kMirrorRightAngle = 1e-6;

// A mirror plane n.x = offset, n the unit normal pointing into the fluid; velocity tangential.
template <int D>
struct GhostPlane {
  std::array<double, D> normal{};
  double offset = 0.0;
  bool no_slip = true;
  std::array<double, D> velocity{};
  double speed() const {
    double v2 = 0.0;
    for (double c : velocity) v2 += c * c;
    return std::sqrt(v2);
  }
};

// Box face (d, s) (s = 0 the lower one) as a mirror plane: its normal points into the box.
template <int D>
GhostPlane<D> face_plane(int d, int s, const PlanarWall<D>& wall) {
  GhostPlane<D> p;
  p.normal[d] = s == 0 ? 1.0 : -1.0;
  p.offset = s == 0 ? wall.position : -wall.position;
  p.no_slip = wall.no_slip;
  p.velocity = wall.velocity;
  return p;
}

template <int D>
class GhostGenerator final : public ParticleGenerator<D> {
 public:
  // support: the kernel support in units of h (images are made within support * max h of a wall).
  // The box's faces come first, in the order (x lower, x upper, y lower, ...), then `planes`.
  GhostGenerator(BoxWalls<D> walls, double support, const std::vector<GhostPlane<D>>& planes = {})
      : walls_(walls), planes_(planes), support_(support) {
    for (int d = 0; d < D; ++d)
      for (int s = 0; s < 2; ++s)
        if (walls[d][s].present) mirrors_.push_back({face_plane(d, s, walls[d][s]), d, walls[d][s].position});
    for (const auto& p : planes) mirrors_.push_back({p, -1, 0.0});
    for (const auto& m : mirrors_) any_no_slip_ = any_no_slip_ || m.plane.no_slip;
    if (mirrors_.size() > 32) throw std::invalid_argument("ghost walls: at most 32 mirror planes");
    for (std::size_t a = 0; a < mirrors_.size(); ++a) {
      std::uint32_t bits = 0;
      for (std::size_t b = 0; b < mirrors_.size(); ++b) {
        double c = 0.0;
        for (int d = 0; d < D; ++d) c += mirrors_[a].plane.normal[d] * mirrors_[b].plane.normal[d];
        if (b != a && std::abs(c) <= kMirrorRightAngle) bits |= 1u << b;
      }
      perpendicular_.push_back(bits);
    }
  }

  // A lower bound for the largest h of the fluid: images are made within support * max(reach_h, the
  // workspace's largest h) of a wall. A rank's local system holds only part of the fluid; given the
  // largest h over all ranks it makes the images the whole system makes (distributed_system.cpp).
  void set_reach_h(double reach_h) { reach_h_ = reach_h; }

  bool generate(std::size_t n_base, Particles<D>& pt, Workspace<D>& w) override {
    n_base_ = n_base;
    double hmax = std::max(w.h, reach_h_);
    for (std::size_t i = 0; i < w.n_fluid && i < w.hs.size(); ++i) hmax = std::max(hmax, w.hs[i]);
    const double width = support_ * hmax;
    new_source_.clear();
    new_mask_.clear();
    std::vector<std::uint32_t>& near = near_;
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      if (pt.kind[i] == Kind::Out) continue;  // taken out (outflow): no image
      near.clear();
      for (std::size_t m = 0; m < mirrors_.size(); ++m)
        if (distance(mirrors_[m], w, i) < width) near.push_back(static_cast<std::uint32_t>(m));
      // Every non-empty set of the nearby mirrors that are pairwise at right angles (never both walls
      // of one direction). At most D mirrors are pairwise perpendicular, so the sets stay few.
      const auto nn = static_cast<unsigned>(near.size());
      if (nn > 16) throw std::invalid_argument("ghost walls: a particle lies near more than 16 mirror planes");
      for (std::uint32_t sub = 1; sub < (1u << nn); ++sub) {
        std::uint32_t mask = 0;
        bool ok = true;
        for (unsigned b = 0; b < nn && ok; ++b) {
          if (!(sub & (1u << b))) continue;
          const std::uint32_t bit = 1u << near[b];
          ok = (mask & ~perpendicular_[near[b]]) == 0;
          mask |= bit;
        }
        if (!ok) continue;
        new_source_.push_back(static_cast<std::uint32_t>(i));
        new_mask_.push_back(mask);
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
    // With a no-slip mirror the viscous terms read their own velocities: the fluid's (and the scene's
    // wall particles') own, and the images' no-slip ones.
    const bool viscous = any_no_slip_;
    if (viscous)
      for (int d = 0; d < D; ++d) {
        w.v_viscous[d].resize(n);
        std::copy(w.v[d].begin(), w.v[d].begin() + static_cast<std::ptrdiff_t>(n_base), w.v_viscous[d].begin());
      }
    for (std::size_t g = 0; g < source_.size(); ++g) {
      const std::size_t i = source_[g];
      image(w, i, mask_[g], n_base + g, viscous);
      w.rho[n_base + g] = w.rho[i];
      w.e[n_base + g] = w.e[i];
      w.hs[n_base + g] = w.hs[i];
    }
    return changed;
  }
  // No viscous term reads the images' no-slip velocities (an inviscid fluid): they are not made.
  void without_viscous_terms() { any_no_slip_ = false; }
  std::size_t count() const override { return source_.size(); }
  double max_wall_speed() const override {
    double s = 0.0;
    for (const auto& m : mirrors_) s = std::max(s, m.plane.speed());
    return s;
  }
  std::size_t base() const { return n_base_; }
  // The mirrors as given: a rank's local system (parallel/distributed_system.hpp) is assembled with the same.
  const BoxWalls<D>& walls() const { return walls_; }
  const std::vector<GhostPlane<D>>& planes() const { return planes_; }
  const std::vector<std::uint32_t>& sources() const { return source_; }
  const std::vector<std::uint32_t>& masks() const { return mask_; }
  // R (row-major D x D) of the image made with `mask` (masks()): the product of the mirrors'
  // reflections I - 2 n n^T, which commute (the mirrors of an image are pairwise at right angles). A
  // tensor of the source maps to R T R^T at the image (boundary/ghost_integral_approach_matrix.hpp).
  void reflection(std::uint32_t mask, double (&R)[D * D]) const {
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) R[a * D + b] = a == b ? 1.0 : 0.0;
    for (std::size_t k = 0; k < mirrors_.size(); ++k) {
      if (!(mask & (1u << k))) continue;
      const auto& n = mirrors_[k].plane.normal;
      double next[D * D];
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) {
          double s = 0.0;  // (I - 2 n n^T) R
          for (int c = 0; c < D; ++c) s += ((a == c ? 1.0 : 0.0) - 2.0 * n[a] * n[c]) * R[c * D + b];
          next[a * D + b] = s;
        }
      for (int q = 0; q < D * D; ++q) R[q] = next[q];
    }
  }

 private:
  struct Mirror {
    GhostPlane<D> plane;
    int axis = -1;          // a box face: its axis (the exact arithmetic of the box walls); -1 a plane
    double position = 0.0;  // a box face: x_axis = position
  };
  // The signed distance of particle i from the mirror, positive on the fluid side.
  static double distance(const Mirror& m, const Workspace<D>& w, std::size_t i) {
    if (m.axis >= 0) return m.plane.normal[m.axis] > 0.0 ? w.x[m.axis][i] - m.position : m.position - w.x[m.axis][i];
    double s = -m.plane.offset;
    for (int d = 0; d < D; ++d) s += m.plane.normal[d] * w.x[d][i];
    return s;
  }

  // Writes image g of particle i through the mirrors in `mask`: its position, its free-slip velocity
  // into w.v and, with `viscous` (a no-slip mirror in the scene), its viscous velocity into
  // w.v_viscous (no slip through the no-slip mirrors, the free-slip rule through the others).
  void image(Workspace<D>& w, std::size_t i, std::uint32_t mask, std::size_t g, bool viscous) const {
    double v[D], vs[D];  // viscous (no slip where the mirror says so) and free slip
    int walls = 0;
    bool all_no_slip = true;
    for (int d = 0; d < D; ++d) {
      w.x[d][g] = w.x[d][i];
      v[d] = vs[d] = w.v[d][i];
    }
    for (std::size_t k = 0; k < mirrors_.size(); ++k) {
      if (!(mask & (1u << k))) continue;
      const Mirror& mirror = mirrors_[k];
      const GhostPlane<D>& m = mirror.plane;
      ++walls;
      all_no_slip = all_no_slip && m.no_slip;
      // The image so far (for a corner: already mirrored through the other mirrors) mirrored again.
      if (mirror.axis >= 0) {
        w.x[mirror.axis][g] = 2.0 * mirror.position - w.x[mirror.axis][g];
      } else {
        double dist = -m.offset;
        for (int d = 0; d < D; ++d) dist += m.normal[d] * w.x[d][g];
        for (int d = 0; d < D; ++d) w.x[d][g] -= 2.0 * dist * m.normal[d];
      }
      free_slip(mirror, vs);
      if (m.no_slip) {
        for (int c = 0; c < D; ++c) v[c] = 2.0 * m.velocity[c] - v[c];
      } else {
        free_slip(mirror, v);
      }
    }
    if (walls > 1 && all_no_slip) corner_no_slip(w, i, mask, walls, v);
    for (int c = 0; c < D; ++c) w.v[c][g] = vs[c];
    if (viscous)
      for (int c = 0; c < D; ++c) w.v_viscous[c][g] = v[c];
  }

  // The normal component of v mirrored about the mirror's normal velocity (Niedoba 2012, eqs 2.77-2.78).
  static void free_slip(const Mirror& mirror, double (&v)[D]) {
    const GhostPlane<D>& m = mirror.plane;
    if (mirror.axis >= 0) {
      v[mirror.axis] = 2.0 * m.velocity[mirror.axis] - v[mirror.axis];
      return;
    }
    double vn = 0.0;
    for (int d = 0; d < D; ++d) vn += m.normal[d] * (v[d] - m.velocity[d]);
    for (int c = 0; c < D; ++c) v[c] -= 2.0 * vn * m.normal[c];
  }

  // The no-slip corner image's velocity (the header's rule). The mirrors of a corner are pairwise at
  // right angles, so their normals and the common tangent space split v orthogonally.
  void corner_no_slip(const Workspace<D>& w, std::size_t i, std::uint32_t mask, int walls, double (&v)[D]) const {
    double tangent[D], wall_tangent[D] = {};
    for (int c = 0; c < D; ++c) {
      tangent[c] = w.v[c][i];
      v[c] = 0.0;
    }
    for (std::size_t k = 0; k < mirrors_.size(); ++k) {
      if (!(mask & (1u << k))) continue;
      const GhostPlane<D>& m = mirrors_[k].plane;
      double vn = 0.0, wn = 0.0;
      for (int d = 0; d < D; ++d) {
        vn += m.normal[d] * w.v[d][i];
        wn += m.normal[d] * m.velocity[d];
      }
      for (int d = 0; d < D; ++d) {
        tangent[d] -= vn * m.normal[d];
        v[d] += (2.0 * wn - vn) * m.normal[d];
      }
      // This wall's velocity with its components along every mirror normal of the corner removed.
      double vw[D];
      for (int d = 0; d < D; ++d) vw[d] = m.velocity[d];
      for (std::size_t l = 0; l < mirrors_.size(); ++l) {
        if (!(mask & (1u << l))) continue;
        const auto& nl = mirrors_[l].plane.normal;
        double a = 0.0;
        for (int d = 0; d < D; ++d) a += nl[d] * m.velocity[d];
        for (int d = 0; d < D; ++d) vw[d] -= a * nl[d];
      }
      for (int d = 0; d < D; ++d) wall_tangent[d] += vw[d] / walls;
    }
    for (int d = 0; d < D; ++d) v[d] += 2.0 * wall_tangent[d] - tangent[d];
  }

  BoxWalls<D> walls_;
  std::vector<GhostPlane<D>> planes_;
  std::vector<Mirror> mirrors_;
  std::vector<std::uint32_t> perpendicular_;  // per mirror: the mirrors at right angles to it
  double support_;
  bool any_no_slip_ = false;  // a no-slip mirror: images carry viscous velocities (Workspace::v_viscous)
  double reach_h_ = 0.0;
  std::size_t n_base_ = 0;
  std::vector<std::uint32_t> source_, new_source_;
  std::vector<std::uint32_t> mask_, new_mask_;
  std::vector<std::uint32_t> near_;  // generate's scratch: the mirrors near one particle
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
