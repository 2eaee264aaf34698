#include "margin/polynomial.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_poly.h>
#include <flint/nmod_poly.h>
#include <flint/ulong_extras.h>

#include <initializer_list>
#include <stdexcept>

#include "algebra/flint_poly.hpp"
#include "algebra/flint_thread.hpp"
#include "algebra/pencil.hpp"

namespace relpos::detail {
namespace {

/// c[0..n) as a FLINT polynomial divided by its content, which is returned (> 0).
Integer primitive_part(const Integer* c, int n, fmpz_poly_t out) {
  fmpz_poly_zero(out);
  fmpz_t z;
  fmpz_init(z);
  for (int i = 0; i < n; ++i) {
    fmpz_set_mpz(z, c[i].mpz());
    fmpz_poly_set_coeff_fmpz(out, i, z);
  }
  fmpz_poly_content(z, out);
  fmpz_poly_scalar_divexact_fmpz(out, out, z);
  Integer content;  // fresh object: written through its mpz_t
  fmpz_get_mpz(content.mpz(), z);
  fmpz_clear(z);
  return content;
}

/// out = sum_i c_i l^i u^j (variables l = 0, u = 1) added to out.
void add_terms(fmpz_mpoly_t out, const fmpz_poly_t c, const fmpz_t factor, ulong j, const fmpz_mpoly_ctx_t ctx) {
  fmpz_t x;
  fmpz_init(x);
  for (slong i = 0; i <= fmpz_poly_degree(c); ++i) {
    fmpz_poly_get_coeff_fmpz(x, c, i);
    fmpz_mul(x, x, factor);
    const ulong exps[2] = {static_cast<ulong>(i), j};
    fmpz_t old;
    fmpz_init(old);
    fmpz_mpoly_get_coeff_fmpz_ui(old, out, exps, ctx);
    fmpz_add(x, x, old);
    fmpz_mpoly_set_coeff_fmpz_ui(out, x, exps, ctx);
    fmpz_clear(old);
  }
  fmpz_clear(x);
}

/// Whether F and S are proven coprime by a prime p dividing neither leading coefficient with
/// gcd(F mod p, S mod p) = 1 (a common factor over Z would divide both modulo p, keeping its degree).
bool coprime_modulo_a_prime(const fmpz_poly_t F, const fmpz_poly_t S) {
  ulong p = ulong(1) << 20;
  for (int tried = 0; tried < 3; ++tried) {
    p = n_nextprime(p, 1);
    if (fmpz_fdiv_ui(fmpz_poly_lead(F), p) == 0 || fmpz_fdiv_ui(fmpz_poly_lead(S), p) == 0) continue;
    nmod_poly_t f, s, g;
    nmod_poly_init(f, p);
    nmod_poly_init(s, p);
    nmod_poly_init(g, p);
    fmpz_poly_get_nmod_poly(f, F);
    fmpz_poly_get_nmod_poly(s, S);
    nmod_poly_gcd(g, f, s);
    const bool one = nmod_poly_degree(g) == 0;
    nmod_poly_clear(f);
    nmod_poly_clear(s);
    nmod_poly_clear(g);
    if (one) return true;
  }
  return false;
}

/// 27 Disc = 4 I^3 - J^2 for the quartic h(l) = a l^4 + b l^3 + c l^2 + d l + e, I = 12ae - 3bd + c^2,
/// J = 72ace + 9bcd - 27ad^2 - 27eb^2 - 2c^3, here with h_i = den F_i - num u S_i polynomials in u:
/// out = 4 I^3 - J^2 (a positive multiple of Disc_l h), in u.
void quartic_discriminant(fmpz_poly_t out, const fmpz_poly_t F, const fmpz_poly_t S, const fmpz_t den,
                          const fmpz_t num) {
  fmpz_poly_t h[5], i3, j, t, u;
  for (auto& x : h) fmpz_poly_init(x);
  fmpz_poly_init(i3);
  fmpz_poly_init(j);
  fmpz_poly_init(t);
  fmpz_poly_init(u);
  fmpz_t x;
  fmpz_init(x);
  for (slong k = 0; k < 5; ++k) {  // h_k = den F_k + (-num) S_k u (num holds -num)
    fmpz_poly_get_coeff_fmpz(x, F, k);
    fmpz_mul(x, x, den);
    fmpz_poly_set_coeff_fmpz(h[k], 0, x);
    fmpz_poly_get_coeff_fmpz(x, S, k);
    fmpz_mul(x, x, num);
    fmpz_poly_set_coeff_fmpz(h[k], 1, x);
  }
  const fmpz_poly_struct *a = h[4], *b = h[3], *c = h[2], *d = h[1], *e = h[0];
  auto add_term = [&](fmpz_poly_t acc, long coefficient, std::initializer_list<const fmpz_poly_struct*> factors) {
    fmpz_poly_one(t);
    for (const fmpz_poly_struct* f : factors) fmpz_poly_mul(t, t, f);
    fmpz_poly_scalar_mul_si(t, t, coefficient);
    fmpz_poly_add(acc, acc, t);
  };
  fmpz_poly_zero(u);  // I
  add_term(u, 12, {a, e});
  add_term(u, -3, {b, d});
  add_term(u, 1, {c, c});
  fmpz_poly_zero(j);  // J
  add_term(j, 72, {a, c, e});
  add_term(j, 9, {b, c, d});
  add_term(j, -27, {a, d, d});
  add_term(j, -27, {e, b, b});
  add_term(j, -2, {c, c, c});
  fmpz_poly_pow(i3, u, 3);
  fmpz_poly_scalar_mul_si(i3, i3, 4);
  fmpz_poly_sqr(t, j);
  fmpz_poly_sub(out, i3, t);
  fmpz_clear(x);
  for (auto& y : h) fmpz_poly_clear(y);
  fmpz_poly_clear(i3);
  fmpz_poly_clear(j);
  fmpz_poly_clear(t);
  fmpz_poly_clear(u);
}

}  // namespace

namespace {

/// A matrix of integers read as m(i, j) (the pencil templates' accessor).
struct IntegerMatrix {
  std::array<Integer, 16> a;
  const Integer& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// q times the lcm of its denominators (written to `out`), and that lcm.
Integer integer_multiple(const Matrix4& q, IntegerMatrix& out) {
  Integer l(1);
  for (const Rational& x : q.a) mpz_lcm(l.mpz(), l.mpz(), mpq_denref(x.mpq()));
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = q.a[i].numerator() * (l / q.a[i].denominator());
  return l;
}

}  // namespace

PointPencil point_pencil(const ScaledFamily& family, const Matrix4& p) {
  IntegerMatrix ez, pz;
  PointPencil out;
  out.alpha = integer_multiple(family.point, ez);
  out.beta = integer_multiple(p, pz);
  out.f = characteristic_polynomial<Integer>(pz, ez);
  out.s = special_polynomial<Integer>(pz, ez);
  out.k = family.k;
  return out;
}

Quartic<Rational> PointPencil::scaled(const Rational& v) const {
  const Rational c = v * Rational(alpha) * k;
  Quartic<Rational> out;
  for (std::size_t i = 0; i < 5; ++i) out[i] = i < 3 ? Rational(f[i]) - c * Rational(s[i]) : Rational(f[i]);
  return out;
}

namespace {

/// D times the hard case's factor: the resultant in l of the square-free part of g and H (sigma at
/// the roots of g, math.md §19). False when FLINT cannot form it.
bool times_hard_case(fmpz_mpoly_t D, const fmpz_mpoly_t H, const fmpz_poly_t g, const fmpz_mpoly_ctx_t ctx) {
  fmpz_poly_t gs, dg;
  fmpz_poly_init(gs);
  fmpz_poly_init(dg);
  fmpz_mpoly_t G, R;
  fmpz_mpoly_init(G, ctx);
  fmpz_mpoly_init(R, ctx);
  fmpz_t one;
  fmpz_init(one);
  fmpz_poly_derivative(dg, g);
  fmpz_poly_gcd(gs, g, dg);
  bool ok = fmpz_poly_divides(gs, g, gs) != 0;
  fmpz_one(one);
  add_terms(G, gs, one, 0, ctx);
  ok = ok && fmpz_mpoly_resultant(R, G, H, 0, ctx) != 0;
  if (ok) fmpz_mpoly_mul(D, D, R, ctx);
  fmpz_clear(one);
  fmpz_mpoly_clear(G, ctx);
  fmpz_mpoly_clear(R, ctx);
  fmpz_poly_clear(gs);
  fmpz_poly_clear(dg);
  return ok;
}

}  // namespace

std::vector<Integer> margin_polynomial(const PointPencil& pencil) {
  flint_thread_cleanup_at_exit();
  fmpz_poly_t F, S, g;
  fmpz_poly_init(F);
  fmpz_poly_init(S);
  fmpz_poly_init(g);
  // f = a F, s = b S with F, S primitive; g = gcd(F, S); f - u c s = a g (F/g - u (c b / a) S/g)
  // for c = alpha k.
  const Integer a = primitive_part(pencil.f.data(), 5, F);
  const Integer b = primitive_part(pencil.s.data(), 3, S);
  if (coprime_modulo_a_prime(F, S))
    fmpz_poly_one(g);  // the common case, without a gcd over Z
  else
    fmpz_poly_gcd(g, F, S);
  // Exact divisions (g divides both; it is primitive, so the quotients are integral).
  bool ok = fmpz_poly_divides(F, F, g) != 0 && fmpz_poly_divides(S, S, g) != 0;
  const Rational kappa = Rational(pencil.alpha) * pencil.k * Rational(b, a);

  fmpz_mpoly_ctx_t ctx;
  fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
  fmpz_mpoly_t H, D;
  fmpz_mpoly_init(H, ctx);
  fmpz_mpoly_init(D, ctx);
  fmpz_t num, den;
  fmpz_init(num);
  fmpz_init(den);
  fmpz_set_mpz(den, mpq_denref(kappa.mpq()));
  fmpz_set_mpz(num, mpq_numref(kappa.mpq()));
  fmpz_neg(num, num);
  fmpz_poly_t pu;
  fmpz_poly_init(pu);
  if (ok && fmpz_poly_degree(F) == 4) {  // g = 1: the discriminant of a quartic from its invariants
    quartic_discriminant(pu, F, S, den, num);
  } else if (ok) {
    add_terms(H, F, den, 0, ctx);  // den F(l) - num u S(l): a positive multiple of F/g - u kappa S/g
    add_terms(H, S, num, 1, ctx);
    ok = fmpz_mpoly_discriminant(D, H, 0, ctx) != 0;
  }
  if (ok && fmpz_poly_degree(g) >= 1) ok = times_hard_case(D, H, g, ctx);
  if (ok && fmpz_poly_degree(F) != 4) ok = fmpz_mpoly_get_fmpz_poly(pu, D, 1, ctx) != 0;
  std::vector<Integer> out;
  if (ok && !fmpz_poly_is_zero(pu)) {
    fmpz_poly_primitive_part(pu, pu);  // positive leading coefficient
    out = from_flint(pu);
  }
  fmpz_poly_clear(pu);
  fmpz_clear(num);
  fmpz_clear(den);
  fmpz_mpoly_clear(H, ctx);
  fmpz_mpoly_clear(D, ctx);
  fmpz_mpoly_ctx_clear(ctx);
  fmpz_poly_clear(F);
  fmpz_poly_clear(S);
  fmpz_poly_clear(g);
  // Never zero (math.md §19: F and S are coprime and F / S is not constant).
  if (out.empty()) throw std::logic_error("internal error: margin_polynomial: no polynomial (a zero discriminant)");
  return out;
}

std::vector<Integer> in_square(const std::vector<Integer>& p) {
  std::vector<Integer> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i > 0) out.emplace_back(0);  // the odd powers of t
    out.push_back(p[i]);
  }
  return out;
}

}  // namespace relpos::detail
