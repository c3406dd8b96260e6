#pragma once
// Twice-repeated integral of erfc: i^2 erfc(x) = int_x^inf int_t^inf erfc(s) ds dt
//   = ((1 + 2x^2) erfc(x) - 2x e^{-x^2}/sqrt(pi)) / 4   (Abramowitz & Stegun 7.2.6 with 7.2.5).
// The closed form cancels badly for large x (both terms ~ e^{-x^2}/sqrt(pi) x, difference ~ e^{-x^2}/(4 sqrt(pi) x^3)),
// so for x >= 1.5 we use the confluent hypergeometric form (DLMF 7.18.12)
//   i^n erfc(x) = e^{-x^2} / (2^n sqrt(pi)) U(n/2 + 1/2, 1/2, x^2),
// with GSL's U, which keeps ~1e-14 relative accuracy there (closed form 1e-11 at x = 20).

namespace sphmol {

double i2erfc(double x);

}  // namespace sphmol
