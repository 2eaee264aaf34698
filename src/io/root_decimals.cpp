#include "io/root_decimals.hpp"

#include "algebra/denominators.hpp"
#include "algebra/roots.hpp"

namespace relpos::detail::io {
namespace {

/// f scaled by the positive lcm of its denominators: same roots, integer coefficients.
Quartic<Integer> integer_quartic(const Quartic<Rational>& f) {
  Integer l(1);
  forms::lcm_of_denominators(f.begin(), f.end(), l);
  Quartic<Integer> out;
  for (std::size_t i = 0; i < 5; ++i) out[i] = f[i].numerator() * (l / f[i].denominator());
  return out;
}

}  // namespace

std::vector<std::string> root_decimals(const Classification& c, int digits, bool only_multiple) {
  std::vector<std::string> out(c.roots.size());
  bool need_isolation = false;
  for (const auto& r : c.roots)
    if (!r.exact && (!only_multiple || r.multiplicity_f >= 2)) need_isolation = true;
  std::vector<std::string> iso;
  if (need_isolation) iso = real_root_decimals(integer_quartic(c.f), digits);
  for (std::size_t i = 0; i < c.roots.size(); ++i) {
    const auto& r = c.roots[i];
    if (only_multiple && r.multiplicity_f < 2) continue;  // not shown: left empty
    if (r.exact)
      out[i] = to_decimal(*r.exact, digits);
    else if (iso.size() == c.roots.size())
      out[i] = iso[i];
    else  // should not happen: fall back on the midpoint of the isolating interval
      out[i] = to_decimal((r.lower + r.upper) / 2, digits);
  }
  return out;
}

}  // namespace relpos::detail::io
