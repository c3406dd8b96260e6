#include "sphmol/time/erk_table.hpp"

#include <arkode/arkode_butcher_erk.h>

#include <vector>

namespace sphmol {

bool erk_reuse_of_last_stage_is_valid(ARKodeButcherTable B) {
  const int s = B->stages;
  if (B->c[s - 1] != 1.0) return true;
  for (int j = 0; j < s; ++j)
    if (B->A[s - 1][j] != B->b[j]) return false;
  return true;
}

ARKodeButcherTable load_erk_table(const std::string& name) {
  ARKodeButcherTable B = ARKodeButcherTable_LoadERKByName(name.c_str());
  if (!B || erk_reuse_of_last_stage_is_valid(B)) return B;
  const int s = B->stages, n = s + 1;
  std::vector<double> c(n), A(static_cast<std::size_t>(n) * n, 0.0), b(n, 0.0), d(n, 0.0);
  for (int i = 0; i < s; ++i) {
    c[i] = B->c[i];
    b[i] = B->b[i];
    if (B->d) d[i] = B->d[i];
    for (int j = 0; j < s; ++j) A[static_cast<std::size_t>(i) * n + j] = B->A[i][j];
  }
  c[s] = 1.0;
  for (int j = 0; j < s; ++j) A[static_cast<std::size_t>(s) * n + j] = B->b[j];  // the FSAL stage: y_n+1
  ARKodeButcherTable E = ARKodeButcherTable_Create(n, B->q, B->p, c.data(), A.data(), b.data(), B->d ? d.data() : nullptr);
  ARKodeButcherTable_Free(B);
  return E;
}

}  // namespace sphmol
