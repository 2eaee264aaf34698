// The fast path of the root structure (roots.hpp, simple_root_structure): f square-free and,
// once its rational common roots with s are divided out, coprime to s and without rational root;
// the real roots approximated in doubles and each certified by exact opposite signs.
#include <gmp.h>

#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "algebra/approximate_roots.hpp"
#include "algebra/double_sign.hpp"
#include "algebra/flint_poly.hpp"
#include "algebra/flint_thread.hpp"
#include "algebra/forms.hpp"
#include "algebra/modular.hpp"
#include "algebra/roots.hpp"

namespace relpos {
namespace {

/// The real roots of h (integer coefficients h[0..n], n <= 4, square-free, no rational root, h(0) != 0),
/// `expected` of them: approximated in doubles, each certified by exact opposite signs of h at the
/// (dyadic) ends of disjoint intervals, as many as there are real roots, so each isolates exactly
/// one (simple, irrational) root. False when the doubles do not separate them.
bool certified_real_roots(const Integer* h, int n, std::size_t expected, std::vector<RealRoot>& out) {
  detail::DoubleSign sign_at(h, n);
  const double* c = sign_at.coefficients();
  const double bound = sign_at.root_bound();
  if (bound == 0) return false;  // roots beyond the double range: no fast path
  double roots[4];
  const std::size_t count = static_cast<std::size_t>(detail::approximate_real_roots(c, n, bound, roots));
  if (count != expected) return false;
  double prev_hi = -HUGE_VAL;
  out.reserve(out.size() + count);
  for (std::size_t k = 0; k < count; ++k) {
    const double r = roots[k];
    if (r == 0 || !std::isfinite(r)) return false;
    bool ok = false;
    for (int widen = 0; widen < 4 && !ok; ++widen) {
      static constexpr double relative[4] = {0x1p-44, 0x1p-34, 0x1p-24, 0x1p-14};  // 2^(-44 + 10 widen)
      const double delta = std::fabs(r) * relative[widen];
      const double lo = r - delta, hi = r + delta;
      if (!(lo > prev_hi) || (lo < 0) != (r < 0) || (hi < 0) != (r < 0)) break;
      if (k + 1 < count && !(hi < roots[k + 1])) break;
      const int sl = sign_at(lo), sh = sign_at(hi);
      if (sl != 0 && sh != 0 && sl != sh) {
        RealRoot& root = out.emplace_back();  // fresh bounds: written in place
        root.sign = r < 0 ? -1 : 1;
        detail::forms::set_double(root.lower.mpq(), lo);
        detail::forms::set_double(root.upper.mpq(), hi);
        prev_hi = hi;
        ok = true;
      }
    }
    if (!ok) return false;
  }
  return true;
}

/// The real roots of h as certified_real_roots(), when two of them are closer than doubles resolve
/// (near a tangency, two roots of f~ about sqrt(delta) apart): h is moved exactly to a critical point
/// c = M 2^e (a double approximation of a root of h', M an integer, 2^e its last place), as
///   Q(z) = 2^(-e n) h((M + z) 2^e)   (integer coefficients; a FLINT Taylor shift),
/// whose roots z = (x - c) / 2^e put the cluster at O(1) with a separation doubles resolve; Q's roots
/// are certified as h's were (Q has h's signs at corresponding points, a positive factor) and mapped
/// back exactly. Each critical point is tried in turn.
bool zoomed_real_roots(const Integer* h, int n, std::size_t expected, std::vector<RealRoot>& out) {
  if (n < 2) return false;
  double c[5], d[4], critical[4];
  const double bound = detail::scaled_doubles(h, n, c);
  if (bound == 0) return false;
  for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
  const int m = detail::approximate_real_roots(d, n - 1, bound, critical);
  fmpz_poly_t p, q;
  fmpz_poly_init(p);
  fmpz_poly_init(q);
  fmpz_t shift, coeff;
  fmpz_init(shift);
  fmpz_init(coeff);
  bool ok = false;
  for (int k = 0; k < m && !ok; ++k) {
    const double x = critical[k];
    if (x == 0 || !std::isfinite(x)) continue;
    const int e = std::ilogb(x) - 52;  // x = M 2^e with |M| < 2^53
    if (e >= 0) continue;
    fmpz_set_si(shift, static_cast<slong>(std::ldexp(x, -e)));
    for (int i = 0; i <= n; ++i) {  // P(y) = sum h_i 2^(-e (n - i)) y^i, then Q(z) = P(M + z)
      fmpz_set_mpz(coeff, h[i].mpz());
      fmpz_mul_2exp(coeff, coeff, static_cast<ulong>(-e) * static_cast<ulong>(n - i));
      fmpz_poly_set_coeff_fmpz(p, i, coeff);
    }
    fmpz_poly_taylor_shift(q, p, shift);
    std::array<Integer, 5> qc;
    detail::integer_coefficients(q, qc);
    std::vector<RealRoot> zs;
    if (qc[0] == 0 || !certified_real_roots(qc.data(), n, expected, zs)) continue;
    const Rational centre(x), unit(std::ldexp(1.0, e));
    ok = true;
    for (RealRoot& r : zs) {
      r.lower = centre + r.lower * unit;
      r.upper = centre + r.upper * unit;
      const int sl = CGAL::sign(r.lower), su = CGAL::sign(r.upper);
      if (sl == 0 || sl != su) ok = false;
      r.sign = sl;
    }
    if (ok) out.insert(out.end(), zs.begin(), zs.end());
  }
  fmpz_clear(shift);
  fmpz_clear(coeff);
  fmpz_poly_clear(p);
  fmpz_poly_clear(q);
  return ok;
}

/// The sign of Disc(p) (FLINT).
int discriminant_sign(const fmpz_poly_t p) {
  fmpz_t z;
  fmpz_init(z);
  fmpz_poly_discriminant(z, p);
  const int sign = fmpz_sgn(z);
  fmpz_clear(z);
  return sign;
}

/// The square-free polynomial h whose real roots are isolated: f itself, or f / g for g = gcd(f, s)
/// of degree 1 or 2 with rational roots (the special roots every sphere has), those kept apart.
struct Cofactor {
  std::vector<RealRoot> common;                   // g's roots, increasing: each a simple root of f
  std::optional<std::array<Integer, 5>> divided;  // h's coefficients when g was divided out
  const Integer* h = nullptr;                     // h's coefficients: f's own or *divided
  int degree = 4, sign_disc = 0;
};

/// x as a root of f shared with s.
RealRoot common_root(const Rational& x, const Quadratic<Integer>& sc) {
  RealRoot r;
  r.exact = x;
  r.lower = r.upper = x;
  r.sign = CGAL::sign(x) < 0 ? -1 : 1;
  r.multiplicity_s = (2 * sc[2] * x + sc[1] == 0) ? 2 : 1;  // 2 when s is a square
  return r;
}

/// The roots of g (coefficients gc[0..dg], dg = 1 or 2) into out, increasing; false when they are
/// not rational (a quadratic g whose discriminant is not a positive square).
bool rational_roots_of_gcd(const std::array<Integer, 5>& gc, slong dg, const Quadratic<Integer>& sc,
                           std::vector<RealRoot>& out) {
  if (dg == 1) {
    out.push_back(common_root(Rational(-gc[0], gc[1]), sc));
    return true;
  }
  Integer d = gc[1] * gc[1] - 4 * gc[2] * gc[0], root;  // root: fresh, written through mpz()
  if (!(d > 0 && mpz_perfect_square_p(d.mpz()))) return false;
  mpz_sqrt(root.mpz(), d.mpz());
  const Integer den = 2 * gc[2];
  out.push_back(common_root(Rational(-gc[1] - root, den), sc));
  out.push_back(common_root(Rational(-gc[1] + root, den), sc));
  if (out[1].exact < out[0].exact) std::swap(out[0], out[1]);
  return true;
}

/// f and s not shown coprime modulo small primes: g = gcd(f, s) over Z. For g = 1, f must have no
/// rational root (the modular tests); otherwise g's roots must be rational and h = f / g of degree
/// >= 2, square-free and without rational root (f(0) != 0: no root of g is 0). False when any of
/// this fails.
bool divide_out_gcd(const fmpz_poly_t f, const Quartic<Integer>& fc, const Quadratic<Integer>& sc,
                    const unsigned long* f_residues, Cofactor& out) {
  const detail::FlintPoly s(sc);
  fmpz_poly_t g, h;
  fmpz_poly_init(g);
  fmpz_poly_init(h);
  fmpz_poly_gcd(g, f, s.p);
  const slong dg = fmpz_poly_degree(g);
  bool ok = dg <= 2 && fmpz_poly_divides(h, f, g) && fmpz_poly_degree(h) >= 2;
  if (ok && dg >= 1) {
    std::array<Integer, 5> gc;
    detail::integer_coefficients(g, gc);
    ok = rational_roots_of_gcd(gc, dg, sc, out.common);
    if (ok) {
      out.sign_disc = discriminant_sign(h);
      ok = out.sign_disc != 0 && detail::certainly_no_rational_root(h);
    }
    if (ok) {
      out.degree = detail::integer_coefficients(h, out.divided.emplace());
      out.h = out.divided->data();
    }
  } else if (ok) {  // gcd 1 after all
    ok = detail::no_root_modulo_small_primes(fc, f_residues) || detail::no_root_modulo_word_primes(f);
  }
  fmpz_poly_clear(g);
  fmpz_poly_clear(h);
  return ok;
}

/// h's real roots certified (zoomed in when doubles do not separate them), then g's rational roots
/// placed between the intervals; false when either fails (a rational root inside an interval:
/// never seen).
bool isolate(Cofactor& h, std::vector<RealRoot>& roots) {
  // Square-free h of degree n: n real roots when Disc(h) > 0 (for n = 4 also none: then the doubles
  // find none, and the general path decides), else 1 for a cubic, n - 2 otherwise.
  const int n = h.degree;
  const std::size_t expected = static_cast<std::size_t>(h.sign_disc > 0 ? n : (n == 3 ? 1 : n - 2));
  if (!certified_real_roots(h.h, n, expected, roots)) {
    roots.clear();
    if (!zoomed_real_roots(h.h, n, expected, roots)) return false;
  }
  for (RealRoot& r : h.common) {
    auto at = roots.begin();
    while (at != roots.end() && at->upper < *r.exact) ++at;
    if (at != roots.end() && at->lower <= *r.exact) return false;
    roots.insert(at, std::move(r));
  }
  return true;
}

}  // namespace

std::optional<RootStructure> simple_root_structure(const Quartic<Integer>& fc, const Quadratic<Integer>& sc,
                                                   int sign_disc_f) {
  detail::flint_thread_cleanup_at_exit();
  if (fc[4] == 0 || fc[0] == 0 || sc[2] == 0) return std::nullopt;
  // FLINT's polynomial of f only when a test on words does not settle it (the usual pair needs none).
  std::optional<detail::FlintPoly> f_flint;
  auto f = [&]() -> const fmpz_poly_struct* {
    if (!f_flint) f_flint.emplace(fc);
    return f_flint->p;
  };
  const int disc = sign_disc_f != 0 ? sign_disc_f : discriminant_sign(f());
  if (disc == 0) return std::nullopt;
  // f is square-free. Its common roots with s (special roots: every sphere has one) are divided
  // out when they are rational; each is a simple root of f, and the cofactor is coprime to s.
  Cofactor h;
  h.h = fc.data();
  h.sign_disc = disc;
  unsigned long f_residues[5];  // f modulo first_primes_product: for both modular tests
  for (std::size_t i = 0; i < 5; ++i) f_residues[i] = detail::residue<detail::first_primes_product>(fc[i].mpz());
  const bool ok = detail::certainly_coprime(f_residues, sc)
                      ? detail::no_root_modulo_small_primes(fc, f_residues) || detail::no_root_modulo_word_primes(f())
                      : divide_out_gcd(f(), fc, sc, f_residues, h);
  RootStructure rs;
  if (!ok || !isolate(h, rs.real_roots)) return std::nullopt;
  rs.degree_ftilde = h.degree;
  rs.sign_disc_f = disc;
  rs.sign_disc_ftilde = h.sign_disc;
  rs.nonreal = 4 - static_cast<int>(rs.real_roots.size());
  return rs;
}

}  // namespace relpos
