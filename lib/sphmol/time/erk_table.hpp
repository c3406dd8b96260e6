#pragma once
// The explicit Butcher table handed to ARKODE ERKStep. ERKStep takes the first stage of a step from
// the last stage of the previous one whenever c_s = 1, without checking that the last stage's state is
// the new solution (first same as last: row s of A equal to b). For tables with c_s = 1 that are not
// FSAL (Heun-Euler, Verner 8(5)6, the explicit halves of the ARK tables) every step then starts from
// f at a wrong state: y' = -y at h = 0.5 grows by 1.27 per step with Verner 8(5)6 instead of
// decaying by exp(-0.5). Such tables get one extra stage, c = 1 with row b (weight 0 in b and in the
// embedding): the method and its error estimate are unchanged, the reused derivative is f(t_n+1, y_n+1),
// and a step costs s evaluations, as the table without the reuse does.
#include <cstdio>  // arkode_butcher.h uses FILE without including it
#include <arkode/arkode_butcher.h>

#include <string>

namespace sphmol {

// The named ERK table, extended as above when needed; the caller frees it (ARKodeButcherTable_Free).
// Null for an unknown name.
ARKodeButcherTable load_erk_table(const std::string& name);

// True when ERKStep's reuse of the last stage is valid for B as it stands (c_s != 1, or row s of A is b).
bool erk_reuse_of_last_stage_is_valid(ARKodeButcherTable B);

}  // namespace sphmol
