#include "sphmol/neighbors/kdtree_search.hpp"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits.h>

#include <algorithm>
#include <iterator>

namespace sphmol {
namespace {

template <int D>
struct KdPoint {
  std::array<double, D> c;
  std::uint32_t index;  // the original particle this point (or periodic image) stands for
};

template <int D>
struct CoordIterator {
  using result_type = const double*;
  const double* operator()(const KdPoint<D>& p) const { return p.c.data(); }
  const double* operator()(const KdPoint<D>& p, int) const { return p.c.data() + D; }
};

template <int D>
using Traits = CGAL::Search_traits<double, KdPoint<D>, const double*, CoordIterator<D>, CGAL::Dimension_tag<D>>;

// Every periodic image of point i that lies within `radius` of the box.
template <int D>
void add_images(const SearchInput<D>& in, std::size_t i, std::vector<KdPoint<D>>& pts) {
  int combos = 1;
  for (int d = 0; d < D; ++d) combos *= 3;
  for (int c = 0; c < combos; ++c) {
    KdPoint<D> p{{}, static_cast<std::uint32_t>(i)};
    bool any = false, ok = true;
    for (int d = 0, cc = c; d < D; ++d, cc /= 3) {
      const int s = cc % 3 - 1;  // shift by -L, 0, +L
      const double x = in.x[d][i];
      p.c[d] = x;
      if (s == 0) continue;
      any = true;
      const Domain<D>& dom = *in.domain;
      if (!dom.periodic[d]) { ok = false; break; }
      // +L images come from particles near the low face, -L from those near the high face.
      if (s > 0 && x - dom.lo[d] >= in.radius) { ok = false; break; }
      if (s < 0 && dom.hi[d] - x >= in.radius) { ok = false; break; }
      p.c[d] = x + s * dom.length(d);
    }
    if (any && ok) pts.push_back(p);
  }
}

}  // namespace

template <int D>
void KdTreeSearch<D>::build(const SearchInput<D>& in, PairList& out) {
  in.domain->require_pair_radius(in.radius);
  std::vector<KdPoint<D>> pts;
  pts.reserve(in.n + in.n / 4);
  for (std::size_t i = 0; i < in.n; ++i) {
    KdPoint<D> p{{}, static_cast<std::uint32_t>(i)};
    for (int d = 0; d < D; ++d) p.c[d] = in.x[d][i];
    pts.push_back(p);
  }
  for (std::size_t i = 0; i < in.n; ++i) add_images(in, i, pts);

  CGAL::Kd_tree<Traits<D>> tree(pts.begin(), pts.end());
  tree.build();
  out.clear(in.n);
  std::vector<KdPoint<D>> found;
  std::vector<std::uint32_t> row;
  // The tree query is slightly inflated; the shared predicate then decides, so that every search
  // gives exactly the same pair set.
  const double query_radius = in.radius * (1.0 + 1e-9);
  const detail::PairDistance<D> pd(in);
  for (std::size_t i = 0; i < in.n; ++i) {
    found.clear();
    row.clear();
    tree.search(std::back_inserter(found), CGAL::Fuzzy_sphere<Traits<D>>(pts[i], query_radius, 0.0));
    for (const auto& p : found)
      if (pd.is_pair(in, i, p.index)) row.push_back(p.index);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    out.j.insert(out.j.end(), row.begin(), row.end());
    out.offset[i + 1] = static_cast<std::uint32_t>(out.j.size());
  }
}

template class KdTreeSearch<1>;
template class KdTreeSearch<2>;
template class KdTreeSearch<3>;

}  // namespace sphmol
