// FLINT reference pipeline for relpos_bench (see flint_reference.hpp).
#include "flint_reference.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <flint/fmpz_poly_mat.h>
#include <flint/nmod_poly.h>
#include <flint/ulong_extras.h>
#include <gmp.h>

#include "decide/decision.hpp"

namespace bench {

using relpos::Matrix4;
using relpos::RootFacts;

namespace {

/// Scratch space, one per thread, reused across calls (fmpz and fmpz_poly keep their limbs).
struct Work {
  fmpz P[16], E[16];        // the matrices with denominators cleared, row-major
  fmpz den, t, u;           // scratch
  fmpz top[3], bot[3];      // two quadratic minors
  fmpz F[5], S[4];          // coefficients of f and s (S[3] = lambda^3 term, must be 0)
  fmpz N, D, A, B;          // smallness
  fmpz_poly_t f, s, g, ft;  // f, s, gcd(f, s), f~
  nmod_poly_t fp;           // f mod a 62-bit prime (square-freeness filter)
  Work() {
    nmod_poly_init(fp, n_nextprime(UWORD(1) << 62, 1));
    for (auto* a : {P, E})
      for (int i = 0; i < 16; ++i) fmpz_init(a + i);
    for (auto* x : {&den, &t, &u, &N, &D, &A, &B}) fmpz_init(x);
    for (int i = 0; i < 3; ++i) fmpz_init(top + i), fmpz_init(bot + i);
    for (int i = 0; i < 5; ++i) fmpz_init(F + i);
    for (int i = 0; i < 4; ++i) fmpz_init(S + i);
    fmpz_poly_init(f), fmpz_poly_init(s), fmpz_poly_init(g), fmpz_poly_init(ft);
  }
  ~Work() {
    for (auto* a : {P, E})
      for (int i = 0; i < 16; ++i) fmpz_clear(a + i);
    for (auto* x : {&den, &t, &u, &N, &D, &A, &B}) fmpz_clear(x);
    for (int i = 0; i < 3; ++i) fmpz_clear(top + i), fmpz_clear(bot + i);
    for (int i = 0; i < 5; ++i) fmpz_clear(F + i);
    for (int i = 0; i < 4; ++i) fmpz_clear(S + i);
    fmpz_poly_clear(f), fmpz_poly_clear(s), fmpz_poly_clear(g), fmpz_poly_clear(ft);
    nmod_poly_clear(fp);
  }
  Work(const Work&) = delete;
  Work& operator=(const Work&) = delete;
};

Work& work() {
  thread_local Work w;
  return w;
}

/// out = m times the lcm of its denominators (a positive integer).
void clear_denominators(const Matrix4& m, fmpz* out, Work& w) {
  fmpz_one(&w.den);
  for (const auto& q : m.a) {
    fmpz_set_mpz(&w.t, mpq_denref(q.mpq()));
    if (!fmpz_equal(&w.t, &w.den) && !fmpz_is_one(&w.t)) fmpz_lcm(&w.den, &w.den, &w.t);
  }
  for (std::size_t i = 0; i < 16; ++i) {
    fmpz_set_mpz(out + i, mpq_numref(m.a[i].mpq()));
    fmpz_set_mpz(&w.t, mpq_denref(m.a[i].mpq()));
    if (fmpz_equal(&w.t, &w.den)) continue;
    fmpz_divexact(&w.t, &w.den, &w.t);
    fmpz_mul(out + i, out + i, &w.t);
  }
}

/// The 2x2 minor on rows (r0, r1), columns (c0, c1) of the pencil E + lambda P, as a quadratic.
void minor2(const Work& w, int r0, int r1, int c0, int c1, fmpz* m) {
  const fmpz *a0 = w.E + 4 * r0 + c0, *b0 = w.E + 4 * r0 + c1, *x0 = w.E + 4 * r1 + c0, *d0 = w.E + 4 * r1 + c1;
  const fmpz *a1 = w.P + 4 * r0 + c0, *b1 = w.P + 4 * r0 + c1, *x1 = w.P + 4 * r1 + c0, *d1 = w.P + 4 * r1 + c1;
  fmpz_fmms(m + 0, a0, d0, b0, x0);
  fmpz_mul(m + 1, a0, d1);
  fmpz_addmul(m + 1, a1, d0);
  fmpz_submul(m + 1, b0, x1);
  fmpz_submul(m + 1, b1, x0);
  fmpz_fmms(m + 2, a1, d1, b1, x1);
}

/// f and s of the cleared pencil into w.f, w.s (s with a positive leading coefficient). False if
/// the lambda^3 coefficient of s (det A) is not zero.
bool pencil(const Matrix4& e, const Matrix4& p, Work& w) {
  clear_denominators(e, w.E, w);
  clear_denominators(p, w.P, w);
  // f: Laplace expansion along rows 0 and 1; the sign of the column pair (j, k) is (-1)^(1 + j + k).
  for (int i = 0; i < 5; ++i) fmpz_zero(w.F + i);
  for (int j = 0; j < 4; ++j)
    for (int k = j + 1; k < 4; ++k) {
      int c[2], n = 0;
      for (int l = 0; l < 4; ++l)
        if (l != j && l != k) c[n++] = l;
      minor2(w, 0, 1, j, k, w.top);
      minor2(w, 2, 3, c[0], c[1], w.bot);
      const bool plus = (1 + j + k) % 2 == 0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) (plus ? fmpz_addmul : fmpz_submul)(w.F + a + b, w.top + a, w.bot + b);
    }
  // s: expansion of the 3x3 block along row 0; entry (0, j) is E(0, j) + lambda P(0, j).
  for (int i = 0; i < 4; ++i) fmpz_zero(w.S + i);
  for (int j = 0; j < 3; ++j) {
    const int c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
    minor2(w, 1, 2, c0, c1, w.bot);
    auto acc = j == 1 ? fmpz_submul : fmpz_addmul;
    for (int b = 0; b < 3; ++b) {
      acc(w.S + b, w.E + j, w.bot + b);
      acc(w.S + b + 1, w.P + j, w.bot + b);
    }
  }
  fmpz_poly_zero(w.f);
  for (int i = 0; i < 5; ++i) fmpz_poly_set_coeff_fmpz(w.f, i, w.F + i);
  fmpz_poly_zero(w.s);
  for (int i = 0; i < 3; ++i) fmpz_poly_set_coeff_fmpz(w.s, i, w.S + i);
  if (fmpz_sgn(fmpz_poly_lead(w.s)) < 0) fmpz_poly_neg(w.s, w.s);  // same roots
  return fmpz_is_zero(w.S + 3);
}

/// Distinct negative and positive real roots of a square-free h with h(0) != 0.
void count_real(const fmpz_poly_t h, int& neg, int& pos) {
  neg = pos = 0;
  const slong d = fmpz_poly_degree(h);
  if (d <= 0) return;
  if (d == 1) {  // root -h0 / h1
    (fmpz_sgn(h->coeffs) == fmpz_sgn(h->coeffs + 1) ? neg : pos) = 1;
    return;
  }
  slong n = 0, p = 0;
  _fmpz_poly_num_real_roots_sturm(&n, &p, h->coeffs, h->length);
  neg = static_cast<int>(n), pos = static_cast<int>(p);
}

int sign_of_disc(const fmpz_poly_t h, Work& w) {
  fmpz_poly_discriminant(&w.t, h);
  return fmpz_sgn(&w.t);
}

/// Sign of rho - 1 (see flint_reference.hpp), or 2 when s or K is not as a validated pair makes it.
int rho_vs_one(Work& w) {
  const fmpz *f0 = w.f->coeffs, *f4 = w.f->coeffs + 4;
  if (fmpz_poly_length(w.f) != 5 || fmpz_poly_length(w.s) != 3) return 2;
  const fmpz *s0 = w.s->coeffs, *s1 = w.s->coeffs + 1, *s2 = w.s->coeffs + 2;  // s2 > 0
  if (fmpz_sgn(s0) <= 0 || fmpz_sgn(s1) <= 0) return 2;                        // roots of s(-u) positive
  fmpz_mul(&w.N, f0, s2);                                                      // K = N / D
  fmpz_mul(&w.D, f4, s0);
  if (fmpz_sgn(&w.D) < 0) fmpz_neg(&w.N, &w.N), fmpz_neg(&w.D, &w.D);
  if (fmpz_sgn(&w.N) <= 0 || fmpz_sgn(&w.D) == 0) return 2;
  // A D^2 = (s2 N + s0 D)^2 - s1^2 N D: the sign of s(-sqrt K) (s2 K + s0 > 0, s1 sqrt K > 0).
  fmpz_fmma(&w.t, s2, &w.N, s0, &w.D);
  fmpz_mul(&w.A, &w.t, &w.t);
  fmpz_mul(&w.t, s1, s1);
  fmpz_mul(&w.u, &w.N, &w.D);
  fmpz_submul(&w.A, &w.t, &w.u);
  // B D = s1^2 D - 4 s2^2 N: the sign of s1 / (2 s2) - sqrt K (vertex of s(-u) right of sqrt K).
  fmpz_mul(&w.B, &w.t, &w.D);
  fmpz_mul(&w.u, s2, s2);
  fmpz_mul(&w.u, &w.u, &w.N);
  fmpz_mul_2exp(&w.u, &w.u, 2);
  fmpz_sub(&w.B, &w.B, &w.u);
  const int a = fmpz_sgn(&w.A), b = fmpz_sgn(&w.B);
  if (a == 0 && b >= 0) return 0;  // sqrt K = u1
  if (a > 0 && b > 0) return -1;   // sqrt K < u1
  return 1;                        // u1 < sqrt K
}

/// Root facts of every square-free factor of g (g(0) != 0), accumulated by multiplicity.
template <class Visit>
void for_squarefree_factors(const fmpz_poly_t g, Visit visit) {
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor_squarefree(fac, g);
  for (slong i = 0; i < fac->num; ++i) visit(fac->p + i, static_cast<int>(fac->exp[i]));
  fmpz_poly_factor_clear(fac);
}

}  // namespace

FlintAnswer flint_classify(const Matrix4& e, const Matrix4& p) {
  Work& w = work();
  FlintAnswer out;
  if (!pencil(e, p, w) || fmpz_poly_length(w.f) != 5 || fmpz_is_zero(w.f->coeffs)) return out;
  RootFacts& x = out.facts;
  // Disc(f) != 0 is certified modulo p when p does not divide f4 (then Disc(f mod p) = Disc(f) mod
  // p); only a zero there (Disc(f) = 0, or p | Disc(f)) pays for the exact discriminant.
  fmpz_poly_get_nmod_poly(w.fp, w.f);
  const bool squarefree = (nmod_poly_degree(w.fp) == 4 && nmod_poly_discriminant(w.fp) != 0) || sign_of_disc(w.f, w);
  if (squarefree) {  // one Sturm sequence
    count_real(w.f, x.negative, x.positive);
    x.real = x.negative + x.positive;
    x.nonreal = 4 - x.real;
    x.sign_disc_f = x.nonreal == 2 ? -1 : 1;  // (-1)^(number of non-real pairs) for square-free f
    x.sign_disc_ftilde = x.sign_disc_f;       // the table reads neither this nor degree_ftilde
  } else {
    fmpz_poly_gcd(w.g, w.f, w.s);
    if (!fmpz_poly_divides(w.ft, w.f, w.g)) return out;
    for_squarefree_factors(w.f, [&](const fmpz_poly_struct* h, int k) {
      int neg, pos;
      count_real(h, neg, pos);
      const int nonreal = static_cast<int>(fmpz_poly_degree(h)) - neg - pos;
      x.negative += neg, x.positive += pos, x.real += neg + pos;
      x.nonreal += k * nonreal;
      if (k >= 2) x.nonreal_multiple += nonreal;
    });
    for_squarefree_factors(w.ft, [&](const fmpz_poly_struct* h, int k) {
      if (k < 2) return;
      int neg, pos;
      count_real(h, neg, pos);
      x.tangent_negative += neg, x.tangent_positive += pos;
    });
    x.degree_ftilde = static_cast<int>(fmpz_poly_degree(w.ft));
    x.sign_disc_ftilde = sign_of_disc(w.ft, w);
  }
  out.rho_vs_one = rho_vs_one(w);
  if (out.rho_vs_one == 2) return out;
  const auto v = relpos::detail::decide_from_root_facts(x, out.rho_vs_one);
  if (!v) return out;  // not small, four negative roots: the gap test of math.md §8 (not in this reference)
  out.position = v->position;
  out.ok = true;
  return out;
}

std::string flint_self_check(const Matrix4& e, const Matrix4& p) {
  Work& w = work();
  std::string err;
  if (!pencil(e, p, w)) err += " lambda^3 coefficient of s is not zero;";
  fmpz_poly_mat_t m;
  fmpz_poly_t d, lin;
  fmpz_poly_init(d), fmpz_poly_init(lin);
  for (int n : {4, 3}) {
    fmpz_poly_mat_init(m, n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        fmpz_poly_zero(lin);
        fmpz_poly_set_coeff_fmpz(lin, 0, w.E + 4 * i + j);
        fmpz_poly_set_coeff_fmpz(lin, 1, w.P + 4 * i + j);
        fmpz_poly_set(fmpz_poly_mat_entry(m, i, j), lin);
      }
    fmpz_poly_mat_det(d, m);
    if (n == 4 && !fmpz_poly_equal(d, w.f)) err += " f differs from fmpz_poly_mat_det;";
    if (n == 3) {
      if (fmpz_sgn(fmpz_poly_lead(d)) < 0) fmpz_poly_neg(d, d);
      if (!fmpz_poly_equal(d, w.s)) err += " s differs from fmpz_poly_mat_det;";
    }
    fmpz_poly_mat_clear(m);
  }
  if (const int disc = sign_of_disc(w.f, w)) {
    int neg, pos;
    count_real(w.f, neg, pos);
    if (fmpz_poly_num_real_roots(w.f) != neg + pos) err += " Sturm count differs from fmpz_poly_num_real_roots;";
    if (disc != (neg + pos == 2 ? -1 : 1)) err += " sign of Disc(f) differs from the Sturm count's;";
  }
  fmpz_poly_clear(d), fmpz_poly_clear(lin);
  return err;
}

}  // namespace bench
