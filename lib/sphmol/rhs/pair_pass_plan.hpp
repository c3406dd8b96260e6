#pragma once
// Groups a scene's terms into fused pair passes (rhs/fused_pair_pass.hpp). Consecutive pair terms
// share one pass; a per-particle term (an EOS, a body force) or a term whose output later terms read
// at neighbours (summation density) ends it. The term order is the assembly's: terms whose inputs do
// not depend on each other are placed next to each other there (rhs/assemble.cpp).
#include <memory>
#include <stdexcept>
#include <vector>

#include "sphmol/rhs/fused_pair_pass.hpp"

namespace sphmol {

// False for a term that sums over the stored active-pair list and has no row-by-row form.
template <int D>
bool can_run_fused(const Term<D>& t) {
  return !t.reads_stored_pairs() || dynamic_cast<const PairTerm<D>*>(&t) != nullptr;
}

template <int D>
bool fusable(const std::vector<std::unique_ptr<Term<D>>>& terms) {
  for (const auto& t : terms)
    if (!can_run_fused(*t)) return false;
  return true;
}

// The number of fused passes fuse_pair_terms would make (each evaluates the kernel once per pair).
template <int D>
std::size_t fused_pass_count(const std::vector<std::unique_ptr<Term<D>>>& terms) {
  std::size_t passes = 0;
  bool open = false;
  for (const auto& t : terms) {
    if (const auto* p = dynamic_cast<const PairTerm<D>*>(t.get())) {
      passes += open ? 0 : 1;
      open = !p->feeds_neighbours();
    } else {
      open = false;
    }
  }
  return passes;
}

template <int D>
std::vector<std::unique_ptr<Term<D>>> fuse_pair_terms(std::vector<std::unique_ptr<Term<D>>> terms, KernelPass<D>* kernel) {
  if (!fusable(terms)) throw std::logic_error("fuse_pair_terms: a term needs the stored pair list");
  std::vector<std::unique_ptr<Term<D>>> out;
  std::vector<std::unique_ptr<PairTerm<D>>> group;
  auto close = [&] {
    if (!group.empty()) out.push_back(std::make_unique<FusedPairPass<D>>(kernel, std::move(group)));
    group.clear();
  };
  for (auto& t : terms) {
    if (auto* p = dynamic_cast<PairTerm<D>*>(t.get())) {
      t.release();
      group.emplace_back(p);
      if (p->feeds_neighbours()) close();
    } else {
      close();
      out.push_back(std::move(t));
    }
  }
  close();
  return out;
}

}  // namespace sphmol
