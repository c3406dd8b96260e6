#include "sphmol/scene/ghost_planes.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <sstream>
#include <string>

#include "sphmol/boundary/facing_mirrors.hpp"
#include "sphmol/scene/scene_messages.hpp"

namespace sphmol {

namespace {

using scene_messages::fail;
using scene_messages::kAxisName;
using scene_messages::num;

// A half-space a.x <= b.
template <int D>
struct HalfSpace {
  Eigen::Matrix<double, D, 1> a;
  double b;
};

// Whether the intersection of the half-spaces (which include the box's) holds a point, to `tol`: a
// bounded polytope that is not empty has a vertex, where D of its faces meet.
template <int D>
bool feasible(const std::vector<HalfSpace<D>>& hs, double tol) {
  const int n = static_cast<int>(hs.size());
  std::vector<int> pick(D);
  const auto check = [&](const Eigen::Matrix<double, D, 1>& x) {
    for (const auto& h : hs)
      if (h.a.dot(x) > h.b + tol) return false;
    return true;
  };
  // Every D-subset of the faces, in lexicographic order.
  for (int k = 0; k < D; ++k) pick[k] = k;
  while (true) {
    Eigen::Matrix<double, D, D> A;
    Eigen::Matrix<double, D, 1> b;
    for (int k = 0; k < D; ++k) {
      A.row(k) = hs[pick[k]].a.transpose();
      b[k] = hs[pick[k]].b;
    }
    const Eigen::FullPivLU<Eigen::Matrix<double, D, D>> lu(A);
    if (lu.isInvertible() && check(lu.solve(b))) return true;
    int k = D - 1;
    while (k >= 0 && pick[k] == n - D + k) --k;
    if (k < 0) return false;
    ++pick[k];
    for (int j = k + 1; j < D; ++j) pick[j] = pick[j - 1] + 1;
  }
}

}  // namespace

void check_ghost_body(const WallBodySpec& b) {
  // Under boundary: ghost a plane body is a mirror without saying so: the message says why.
  const std::string what = b.treatment == "ghost" ? "a ghost mirror" : "a plane body under discretization.boundary: ghost (a mirror)";
  if (b.layers > 0) fail(b.where_layers, what + " has no wall particles: remove layers");
  if (b.motion) fail(b.where_motion, what + " stays in place; a moving surface is velocity: [...] along the plane");
  double n2 = 0.0, vn = 0.0, v2 = 0.0;
  for (std::size_t d = 0; d < b.shape.normal.size(); ++d) {
    n2 += b.shape.normal[d] * b.shape.normal[d];
    if (d < b.velocity.size()) vn += b.shape.normal[d] * b.velocity[d];
  }
  for (double c : b.velocity) v2 += c * c;
  if (std::abs(vn) > 1e-12 * std::sqrt(n2 * v2))
    fail(b.where_velocity, what + " stays in place, so its velocity must lie along the plane (normal component " +
                               num(vn / std::sqrt(n2)) + " m/s)");
}

bool is_ghost_body(const WallBodySpec& body, const Config& config) {
  return body.treatment == "ghost" ||
         (body.treatment.empty() && body.shape.type == "plane" && config.discretization.boundary == "ghost");
}

void check_ghost_bodies(const SceneSpec& spec, const Config& config, const std::string& boundary_where) {
  const bool ghost = config.discretization.boundary == "ghost";
  for (const auto& w : spec.walls) {
    if (ghost && !is_ghost_body(w, config)) {
      if (w.shape.type == "plane")
        fail(w.where_treatment, "'" + w.treatment + "' makes wall particles, and discretization.boundary: ghost makes every "
                                "wall a mirror (wall particles would get no images); use treatment: ghost or "
                                "boundary: wall_particles");
      if (boundary_where.empty())
        fail(w.where, "discretization.boundary: ghost mirrors only planes (the domain's faces and plane wall bodies); a " +
                          w.shape.type + " body needs discretization.boundary: wall_particles");
      fail(boundary_where, "ghost mirrors only planes (the domain's faces and plane wall bodies); the scene's wall body " +
                               w.name + " (" + w.where + ") is a " + w.shape.type + " and needs wall_particles");
    }
    if (ghost) check_ghost_body(w);
    if (!ghost && w.treatment == "ghost")
      fail(w.where_treatment, "a ghost mirror needs discretization.boundary: ghost, which makes every wall a mirror (mirrors "
                              "reflect fluid only, so wall particles beside them would get no images)");
  }
}

template <int D>
std::vector<GhostPlane<D>> ghost_planes(const SceneSpec& spec, const Config& config, BoxWalls<D>& faces, double dx,
                                        double support) {
  std::vector<GhostPlane<D>> planes;
  std::vector<std::string> where;
  const auto& dom = spec.domain;
  for (const auto& w : spec.walls) {
    if (!is_ghost_body(w, config)) continue;
    GhostPlane<D> p;
    double len = 0.0;
    for (int d = 0; d < D; ++d) len += w.shape.normal[d] * w.shape.normal[d];
    len = std::sqrt(len);
    for (int d = 0; d < D; ++d) {
      p.normal[d] = w.shape.normal[d] / len;
      p.offset += p.normal[d] * w.shape.point[d];
    }
    p.no_slip = !w.free_slip;
    for (std::size_t d = 0; d < w.velocity.size() && d < static_cast<std::size_t>(D); ++d) p.velocity[d] = w.velocity[d];
    int axis = -1, nonzero = 0;
    for (int d = 0; d < D; ++d) {
      if (p.normal[d] != 0.0) ++nonzero, axis = d;
      if (dom.boundary[d] == AxisBoundary::periodic && p.normal[d] != 0.0)
        fail(w.where, std::string("a ghost mirror across the periodic axis ") + kAxisName[d] +
                          " would not be periodic; its normal must have no " + kAxisName[d] + " component");
    }
    if (nonzero == 1) {
      const double k = (w.shape.point[axis] - dom.lo[axis]) / dx;
      if (std::abs(k - std::round(k)) > 1e-6)
        fail(w.where, std::string("a ghost mirror along the ") + kAxisName[axis] + " axis must lie a whole number of spacings (" +
                          num(dx) + " m) from the domain's lower face, as the faces do; it lies " + num(k) + " spacings from it");
    }
    // On a closed face of the domain: it replaces that face's mirror (a moving or free-slip face).
    if (nonzero == 1) {
      const int side = p.normal[axis] > 0.0 ? 0 : 1;
      auto& f = faces[axis][side];
      if (f.present && std::abs(f.position - w.shape.point[axis]) <= 1e-9 * dx) f.present = false;
    }
    planes.push_back(p);
    where.push_back(w.where);
  }
  // Every pair of mirrors (the box's present faces and the planes) that meet at an angle other than
  // 0 or 90 degrees must stay apart by more than the support throughout the domain.
  std::vector<GhostPlane<D>> all;
  std::vector<std::string> names;
  for (int d = 0; d < D; ++d)
    for (int s = 0; s < 2; ++s) {
      if (!faces[d][s].present) continue;
      all.push_back(face_plane(d, s, faces[d][s]));
      names.push_back(std::string("the domain's ") + (s == 0 ? "lower " : "upper ") + kAxisName[d] + " face");
    }
  const std::size_t n_faces = all.size();
  all.insert(all.end(), planes.begin(), planes.end());
  double size = 0.0;
  for (int d = 0; d < D; ++d) size = std::max(size, dom.hi[d] - dom.lo[d]);
  // Mirrors facing each other across the fluid (normals opposed, fluid sides overlapping) must be far
  // enough apart that the images of images, which are not made, stay out of the support.
  for (std::size_t a = 0; a < all.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      double c = 0.0;
      for (int d = 0; d < D; ++d) c += all[a].normal[d] * all[b].normal[d];
      if (std::abs(c + 1.0) > kMirrorRightAngle) continue;
      const double gap = -(all[a].offset + all[b].offset);
      if (facing_mirrors_too_close(gap, dx, support))
        fail(a < n_faces ? dom.where_hi : where[a - n_faces],
             (a < n_faces ? "the domain's faces: " : "this ghost mirror and " + (b < n_faces ? names[b] : "the ghost mirror at " + where[b - n_faces]) + ": ") +
                 facing_mirrors_message(gap, dx, support));
    }
  for (std::size_t a = n_faces; a < all.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      double c = 0.0;
      for (int d = 0; d < D; ++d) c += all[a].normal[d] * all[b].normal[d];
      if (std::abs(c - 1.0) <= kMirrorRightAngle) {
        // Facing the same way, a gap g apart: the fluid keeps dx/2 in front of the front one, so the
        // images the one behind makes lie at least 2 g + dx from any fluid particle, and they must
        // stay out of the support (they would mirror that fluid a second time).
        const double gap = std::abs(all[a].offset - all[b].offset);
        if (2.0 * gap + dx < support * (1.0 - 1e-9))
          fail(where[a - n_faces], "this ghost mirror and " + (b < n_faces ? names[b] : "the ghost mirror at " + where[b - n_faces]) +
                                       " face the same way " + num(gap) + " m apart: the images of the one behind would reach the "
                                       "fluid of the other (2 gap + dx = " + num(2.0 * gap + dx) + " m within the kernel support, " +
                                       num(support) + " m); open that face or move the plane");
        continue;
      }
      if (std::abs(c) <= kMirrorRightAngle || std::abs(c + 1.0) <= kMirrorRightAngle) continue;
      std::vector<HalfSpace<D>> hs;
      for (int d = 0; d < D; ++d) {
        HalfSpace<D> up, down;
        up.a.setZero();
        down.a.setZero();
        up.a[d] = 1.0;
        up.b = dom.hi[d];
        down.a[d] = -1.0;
        down.b = -dom.lo[d];
        hs.push_back(up);
        hs.push_back(down);
      }
      for (const std::size_t m : {a, b}) {
        HalfSpace<D> inside, near;  // 0 <= n.x - c <= support
        for (int d = 0; d < D; ++d) inside.a[d] = -all[m].normal[d], near.a[d] = all[m].normal[d];
        inside.b = -all[m].offset;
        near.b = all[m].offset + support;
        hs.push_back(inside);
        hs.push_back(near);
      }
      if (feasible<D>(hs, 1e-9 * size)) {
        const double angle = std::acos(std::max(-1.0, std::min(1.0, -c))) * 180.0 / M_PI;
        fail(where[a - n_faces], "this ghost mirror and " + (b < n_faces ? names[b] : "the ghost mirror at " + where[b - n_faces]) +
                                     " meet at " + num(angle) + " degrees within the kernel support (" + num(support) +
                                     " m) of the domain; mirrors need right angles where the fluid reaches both (use "
                                     "discretization.boundary: wall_particles)");
      }
    }
  return planes;
}

template std::vector<GhostPlane<2>> ghost_planes<2>(const SceneSpec&, const Config&, BoxWalls<2>&, double, double);
template std::vector<GhostPlane<3>> ghost_planes<3>(const SceneSpec&, const Config&, BoxWalls<3>&, double, double);

}  // namespace sphmol
