// margin(): s* and its proof (math.md §19). The positive roots of the margin polynomial in u = t^2
// are the candidates for s*^2; the nested family's positions at rational separators pick s*^2 among
// them (no contact below s*, contact above); s* itself is then isolated by its minimal polynomial,
// and the enclosure's ends get the certificates of the positions the nested family has there.
#include "relpos/margin.hpp"

#include <mpfr.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "algebra/between.hpp"
#include "algebra/irreducible.hpp"
#include "algebra/pair_size.hpp"
#include "algebra/polynomial_sign.hpp"
#include "algebra/power_of_two.hpp"
#include "certificate/build.hpp"
#include "decide/unchecked.hpp"
#include "margin/approximate.hpp"
#include "margin/descartes.hpp"
#include "margin/family.hpp"
#include "margin/multiplier.hpp"
#include "margin/polynomial.hpp"
#include "margin/refine.hpp"
#include "relpos/classify.hpp"
#include "relpos/error.hpp"

namespace relpos {
namespace {

using detail::RootInterval;

/// The double nearest q (ties to even), through MPFR at 53 bits; below the normal range from its
/// decimal text (strtod rounds correctly there).
double nearest_double(const Rational& q) {
  MPFR_DECL_INIT(x, 53);
  mpfr_set_q(x, q.mpq(), MPFR_RNDN);
  const double d = mpfr_get_d(x, MPFR_RNDN);
  if (d == 0 || std::fabs(d) < DBL_MIN || !std::isfinite(d)) return std::strtod(to_decimal(q, 40).c_str(), nullptr);
  return d;
}

/// A rational below (above == false) or above sqrt(x), x >= 0, within 2^-64 sqrt(x) of it:
/// sqrt(n / d) = sqrt(n d 2^128) / (d 2^64), the integer square root rounded down or up.
Rational sqrt_bound(const Rational& x, bool above) {
  Integer r = x.numerator() * x.denominator(), den = x.denominator();
  mpz_mul_2exp(r.mpz(), r.mpz(), 128);
  mpz_sqrt(r.mpz(), r.mpz());
  if (above) r += 1;
  mpz_mul_2exp(den.mpz(), den.mpz(), 64);
  return Rational(r, den);
}

/// The distinct irreducible factors of p (primitive, positive leading coefficients): p itself when
/// its degrees modulo a few primes prove it irreducible (the common case, and far cheaper), else
/// FLINT's factorisation.
std::vector<std::vector<Integer>> factors_of(const std::vector<Integer>& p) {
  if (detail::proven_irreducible(p)) return {p};
  return detail::irreducible_factors(p);
}

/// A positive real root of one irreducible factor of the margin polynomial in u.
struct Candidate {
  const std::vector<Integer>* factor;
  RootInterval root;
};

/// The candidates in increasing order, their intervals pairwise disjoint (distinct irreducible
/// factors share no root, so halving the overlapping ones ends).
std::vector<Candidate> candidates(const std::vector<std::vector<Integer>>& factors) {
  std::vector<Candidate> out;
  for (const auto& f : factors) {
    if (f.size() == 2) {  // a rational root -f0 / f1
      const Rational r(-f[0], f[1]);
      if (r > 0) out.push_back({&f, {r, r}});
      continue;
    }
    for (auto& r : detail::positive_roots(f)) out.push_back({&f, std::move(r)});
  }
  auto before = [](const Candidate& x, const Candidate& y) { return x.root.lo < y.root.lo; };
  for (bool overlapping = true; overlapping;) {
    std::sort(out.begin(), out.end(), before);
    overlapping = false;
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
      if (out[i].root.hi < out[i + 1].root.lo) continue;
      overlapping = true;
      detail::bisect(*out[i].factor, out[i].root);
      detail::bisect(*out[i + 1].factor, out[i + 1].root);
    }
  }
  return out;
}

/// The ellipsoid scaled about its centre by the square root of v > 0 (no validation: a real
/// ellipsoid; no size limit: its matrix is derived from a checked one).
Ellipsoid scaled_square(const detail::ScaledFamily& family, const Rational& v) {
  return detail::make_ellipsoid(detail::QuadricMatrix(family.at_square(v)));
}

/// The certificate of `position` for the pair scaled by sqrt(v), which is that pair's position
/// (certificate::build fails, as an internal error, rather than certify anything else).
Certificate certificate_of(const detail::ScaledFamily& family, const Paraboloid& p, const Rational& v,
                           Position position) {
  return detail::certificate::build(scaled_square(family, v), p, position);
}

/// s*^2 among the candidates: the nested family has no contact below s* and crosses above it, so
/// with a rational v_i between candidates i and i + 1, s*^2 is the first candidate whose v_i shows
/// contact (binary search: a few decisions).
std::size_t find_s_star(const std::vector<Candidate>& c, const detail::ScaledFamily& family, const Paraboloid& p) {
  std::size_t lo = 0, hi = c.size() - 1;
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    const Rational v =
        detail::rational_inside(c[mid].root.hi, c[mid + 1].root.lo, detail::Shortest::Bits);  // not a root
    const Position at = detail::classify_unchecked(scaled_square(family, v), p, Evidence::Minimal).verdict.position;
    if (at == Position::TI || at == Position::TE)
      throw std::logic_error("internal error: margin: a tangency between two roots of the margin polynomial");
    if (at == Position::C)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

/// s* from s*^2 in the open interval u of the irreducible polynomial q: its minimal polynomial (the
/// irreducible factor of q(t^2) that vanishes at s*) and an interval of it isolating s*.
std::pair<std::vector<Integer>, RootInterval> square_root_of(const std::vector<Integer>& q, RootInterval u) {
  // q is irreducible; q(t^2) is then irreducible too unless q(t^2) = +-m(t) m(-t) (Capelli), which
  // needs |lc q| = lc(m)^2 and |q(0)| = m(0)^2 to be squares (math.md §19): usually they are not.
  const std::vector<Integer> h = detail::in_square(q);
  const bool squares = mpz_perfect_square_p(q.back().mpz()) && mpz_perfect_square_p(Integer(CGAL::abs(q[0])).mpz());
  const std::vector<std::vector<Integer>> factors = squares ? factors_of(h) : std::vector<std::vector<Integer>>{h};
  for (int attempt = 0; attempt < 64; ++attempt) {
    // (sqrt(u.lo), sqrt(u.hi)) holds s* and no other positive root of q(t^2); its rational bounds
    // widen it by 2^-64, which keeps that unless roots are closer: then u is halved and tried again.
    const RootInterval t{sqrt_bound(u.lo, false), sqrt_bound(u.hi, true)};
    for (const auto& m : factors)
      if (detail::descartes_bound(m, t.lo, t.hi) == 1 &&
          detail::sign_of_value(m, t.lo) * detail::sign_of_value(m, t.hi) < 0)
        return {m, t};
    for (int i = 0; i < 8; ++i) detail::bisect(q, u);
  }
  throw std::logic_error("internal error: margin: s* not isolated from s*^2");
}

/// The margin of an irrational s* in r (an isolating interval of its minimal polynomial f): the
/// nearest double, an enclosure [lo, hi] of short dyadics, lo < s* < hi, hi - lo <= 2^-bits lo, in
/// which s* is the margin polynomial's only root (detail::isolates), and the certificates of the
/// pair scaled by lo (I for a centre inside the cup, else E) and by hi (C).
Margin irrational_margin(const std::vector<Integer>& f, RootInterval r, const std::optional<long double>& start,
                         const std::vector<Integer>& pi_t, const detail::ScaledFamily& family,
                         const detail::PointPencil& pencil, const Paraboloid& p, int bits, bool inside) {
  Margin out;
  out.polynomial = f;
  long fine = std::max(bits, 60) + 4;
  detail::refine_root(f, r, fine, start ? &*start : nullptr);
  // Rounding to nearest is monotone, so when both ends round alike so does s*; an irrational s* is
  // no tie between two doubles, so the halving ends.
  while (nearest_double(r.lo) != nearest_double(r.hi)) detail::bisect(f, r);
  out.approx = nearest_double(r.lo);
  for (long extra = 2;; extra += 4) {
    // w = 2^-(bits + extra) r.lo: the ends lie within w of r, so hi - lo < 3w <= 2^-bits lo.
    if (bits + extra > fine) detail::refine_root(f, r, fine = bits + extra);
    const Rational w = r.lo * detail::power_of_two(-static_cast<long>(bits + extra));
    out.lo = detail::rational_inside(r.lo - w, r.lo, detail::Shortest::Bits);
    out.hi = detail::rational_inside(r.hi, r.hi + w, detail::Shortest::Bits);
    if (detail::isolates(pi_t, f, out.lo, out.hi)) break;
    if (extra > 4096) throw std::logic_error("internal error: margin: no enclosure isolating s*");
  }
  // The positions are known (nested family).
  if (std::optional<Rational> l = detail::below_multiplier(pencil, out.lo, inside, bits)) {
    out.below.kind = Certificate::Kind::Definite;
    out.below.lambda = std::move(*l);
  } else {
    out.below = certificate_of(family, p, out.lo * out.lo, inside ? Position::I : Position::E);
  }
  out.above = certificate_of(family, p, out.hi * out.hi, Position::C);
  return out;
}

}  // namespace

AlgebraicReal Margin::value() const {
  if (lo == hi) return AlgebraicReal::rational(lo);
  return AlgebraicReal::root(polynomial, lo, hi, /*irreducible=*/true);
}

Margin margin(const Ellipsoid& e, const Paraboloid& p, int bits) {
  if (bits < 1 || bits > detail::kMaxMarginBits)
    throw InputError("margin: bits must be from 1 to " + std::to_string(detail::kMaxMarginBits) + ", got " +
                     std::to_string(bits));
  detail::check_normalized_pair_size(e, p);
  const detail::ScaledFamily family = detail::scaled_family(e.matrix());
  const Rational centre_value = detail::form_at(p.matrix(), family.centre);  // < 0: inside the cup
  Margin out;
  if (centre_value == 0) {  // the centre on the surface: s* = 0
    out.polynomial = {Integer(0), Integer(1)};
    return out;
  }
  const bool inside = centre_value < 0;
  const detail::PointPencil pencil = detail::point_pencil(family, p.matrix());
  const std::vector<Integer> pi = detail::margin_polynomial(pencil);
  const std::vector<std::vector<Integer>> factors = factors_of(pi);
  const std::vector<Candidate> c = candidates(factors);
  if (c.empty()) throw std::logic_error("internal error: margin: the margin polynomial has no positive root");
  const Candidate& star = c[find_s_star(c, family, p)];
  const Rational& v = star.root.lo;
  if (v == star.root.hi && mpz_perfect_square_p(mpq_numref(v.mpq())) && mpz_perfect_square_p(mpq_denref(v.mpq()))) {
    // s* rational: the tangency at s* itself (TI inside, TE outside).
    Integer num, den;
    mpz_sqrt(num.mpz(), mpq_numref(v.mpq()));
    mpz_sqrt(den.mpz(), mpq_denref(v.mpq()));
    out.lo = out.hi = Rational(num, den);
    out.polynomial = {-num, den};
    out.approx = nearest_double(out.lo);
    out.at = certificate_of(family, p, v, inside ? Position::TI : Position::TE);
    return out;
  }
  RootInterval u = star.root;
  if (u.lo == u.hi) {  // s*^2 rational, not a square: s* is a root of den t^2 - num, irreducible
    u.lo = v * (1 - detail::power_of_two(-8));
    u.hi = v * (1 + detail::power_of_two(-8));
  }
  auto [f, r] = square_root_of(*star.factor, u);
  // A start for Newton's method: the square root of s*^2's approximation in long double.
  std::optional<long double> start;
  const long double ulo = CGAL::to_double(u.lo), uhi = CGAL::to_double(u.hi);
  for (const long double x : detail::approximate_real_roots(*star.factor))
    if (x >= ulo && x <= uhi) start = std::sqrt(x);
  return irrational_margin(f, r, start, detail::in_square(pi), family, pencil, p, bits, inside);
}

}  // namespace relpos
