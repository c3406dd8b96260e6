#pragma once
// Groups a scene's terms into fused pair passes (rhs/fused_pair_pass.hpp). Consecutive pair terms
// share one pass; a per-particle term (an EOS, a body force) or a term whose output later terms read
// at neighbours (summation density) ends it. The term order is the assembly's: terms whose inputs do
// not depend on each other are placed next to each other there (rhs/assemble.cpp).
#include <algorithm>
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

// The fused pass of each term, in order: consecutive pair terms share a pass, which ends after a term
// that feeds neighbours and at any other term; -1 for a term that is not a pair term.
template <int D>
std::vector<int> fused_pass_of(const std::vector<std::unique_ptr<Term<D>>>& terms) {
  std::vector<int> pass(terms.size(), -1);
  int passes = 0;
  bool open = false;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    if (const auto* p = dynamic_cast<const PairTerm<D>*>(terms[k].get())) {
      passes += open ? 0 : 1;
      pass[k] = passes - 1;
      open = !p->feeds_neighbours();
    } else {
      open = false;
    }
  }
  return pass;
}

// The number of fused passes fuse_pair_terms would make (each evaluates the kernel once per pair).
template <int D>
std::size_t fused_pass_count(const std::vector<std::unique_ptr<Term<D>>>& terms) {
  const auto pass = fused_pass_of(terms);
  return pass.empty() ? 0 : static_cast<std::size_t>(*std::max_element(pass.begin(), pass.end()) + 1);
}

template <int D>
std::vector<std::unique_ptr<Term<D>>> fuse_pair_terms(std::vector<std::unique_ptr<Term<D>>> terms, KernelPass<D>* kernel) {
  if (!fusable(terms)) throw std::logic_error("fuse_pair_terms: a term needs the stored pair list");
  const auto pass = fused_pass_of(terms);
  std::vector<std::unique_ptr<Term<D>>> out;
  std::vector<std::unique_ptr<PairTerm<D>>> group;
  auto close = [&] {
    if (!group.empty()) out.push_back(std::make_unique<FusedPairPass<D>>(kernel, std::move(group)));
    group.clear();
  };
  for (std::size_t k = 0; k < terms.size(); ++k) {
    if (k > 0 && pass[k] != pass[k - 1]) close();
    if (pass[k] < 0) {
      out.push_back(std::move(terms[k]));
    } else {
      group.emplace_back(static_cast<PairTerm<D>*>(terms[k].release()));
    }
  }
  close();
  return out;
}

}  // namespace sphmol
