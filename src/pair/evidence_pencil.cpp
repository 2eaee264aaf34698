#include "pair/evidence_pencil.hpp"

#include <gmp.h>

#include <algorithm>

#include "algebra/closed_evidence.hpp"
#include "algebra/decimal_recipe.hpp"
#include "algebra/exact_pencil.hpp"
#include "filters/fixed_pencil.hpp"

namespace relpos::detail {
namespace {

/// f = det(lambda P + E) and s = det(lambda A + M) from the two integer forms Pz = lp P and
/// Ez = le E (forms::integer_form): with g = det(mu Pz + Ez) and h = det(mu Az + Mz),
///   f_i = g_i / (lp^i le^(4-i)),  s_i = h_i / (lp^i le^(3-i))   (reported reduced),
/// and the common-lcm integer forms of the root isolation, S^4 f and S^3 s with S = lcm(lp, le):
///   S^4 f_i = g_i (S/lp)^i (S/le)^(4-i),  S^3 s_i = h_i (S/lp)^i (S/le)^(3-i).
void reported_polynomials(const Quartic<PooledInteger>& g, const Quadratic<PooledInteger>& h,
                          const forms::SplitScale& sp, const forms::SplitScale& se, const Integer& lp,
                          const Integer& le, Quartic<Rational>& f, Quadratic<Rational>& s, Quartic<Integer>& fi,
                          Quadratic<Integer>& si) {
  // Every Rational written here is a fresh default one and every Integer the scratch's (their values
  // not shared): written in place, without a temporary handle per coefficient.
  for (unsigned long i = 0; i < 5; ++i) forms::divided_by_powers(g[i].mpz(), {{sp, i}, {se, 4 - i}}, f[i].mpq());
  for (unsigned long i = 0; i < 3; ++i) forms::divided_by_powers(h[i].mpz(), {{sp, i}, {se, 3 - i}}, s[i].mpq());
  // S/lp and S/le from the splits, without a gcd: S = 2^max 5^max lcm(rest_p, rest_e), and the lcm
  // of the rests is one of them when the other is 1 or they are equal (doubles, decimal text, a
  // standard paraboloid with decimal a and b beside a decimal ellipsoid). Then
  // S/lp = 2^ta 5^fa rest_a with rest_a = rest_e / gcd = rest_e or 1, and the same for S/le.
  const bool p_rest_one = mpz_cmp_ui(sp.rest.mpz(), 1) == 0, e_rest_one = mpz_cmp_ui(se.rest.mpz(), 1) == 0;
  if (p_rest_one || e_rest_one || mpz_cmp(sp.rest.mpz(), se.rest.mpz()) == 0) {
    const unsigned long twos = std::max(sp.twos, se.twos), fives = std::max(sp.fives, se.fives);
    const unsigned long ta = twos - sp.twos, tb = twos - se.twos, fa = fives - sp.fives, fb = fives - se.fives;
    const forms::SplitScale* rest_a = p_rest_one && !e_rest_one ? &se : nullptr;  // its rest_power: rest_a^k
    const forms::SplitScale* rest_b = e_rest_one && !p_rest_one ? &sp : nullptr;
    auto times = [&](const PooledInteger& z, unsigned long i, unsigned long j, Integer& r) {  // z (S/lp)^i (S/le)^j
      const mpz_ptr to = r.mpz();  // the scratch's: written in place
      mpz_mul_2exp(to, z.mpz(), ta * i + tb * j);
      if (const unsigned long k = fa * i + fb * j; k > 0) forms::times_power_of_five(to, to, k);
      if (rest_a && i > 0) mpz_mul(to, to, rest_a->rest_power[i].mpz());
      if (rest_b && j > 0) mpz_mul(to, to, rest_b->rest_power[j].mpz());
    };
    for (unsigned long i = 0; i < 5; ++i) times(g[i], i, 4 - i, fi[i]);
    for (unsigned long i = 0; i < 3; ++i) times(h[i], i, 3 - i, si[i]);
    return;
  }
  PooledInteger common, a, b;
  mpz_lcm(common.mpz(), lp.mpz(), le.mpz());
  mpz_divexact(a.mpz(), common.mpz(), lp.mpz());
  mpz_divexact(b.mpz(), common.mpz(), le.mpz());
  PooledInteger pa[5], pb[5];  // powers of S/lp and S/le
  pa[0] = pb[0] = PooledInteger(1);
  for (std::size_t i = 1; i < 5; ++i) pa[i] = pa[i - 1] * a, pb[i] = pb[i - 1] * b;
  auto times = [](const PooledInteger& z, const PooledInteger& x, const PooledInteger& y, Integer& r) {
    mpz_mul(r.mpz(), z.mpz(), x.mpz());
    mpz_mul(r.mpz(), r.mpz(), y.mpz());
  };
  for (std::size_t i = 0; i < 5; ++i) times(g[i], pa[i], pb[4 - i], fi[i]);
  for (std::size_t i = 0; i < 3; ++i) times(h[i], pa[i], pb[3 - i], si[i]);
}

/// lambda_s, the root of s nearest 0, from h: with mu = lambda le / lp, s(lambda) = h(mu) / le^3, so
/// Disc(s) = Disc(h) / (lp le^2)^2 (reduced along the split scales), rational iff Disc(h) is a square
/// R^2, and then lambda_s = (lp / le) (R - h1) / (2 h2). `s` is the reduced s.
anysize::LambdaS lambda_s_of_pencil(const Quadratic<PooledInteger>& h, const forms::SplitScale& sp,
                                    const forms::SplitScale& se, const Quadratic<Rational>& s) {
  PooledInteger disc, t;
  mpz_mul(disc.mpz(), h[1].mpz(), h[1].mpz());
  mpz_mul(t.mpz(), h[2].mpz(), h[0].mpz());
  mpz_submul_ui(disc.mpz(), t.mpz(), 4);
  if (h[2].sign() > 0 && mpz_sgn(disc.mpz()) >= 0 && mpz_perfect_square_p(disc.mpz())) {
    // lambda_s = (R - h1) lp / (2 h2 le) = ((R - h1) / (lp le^2)) / (2 s2), as h2 = lp^2 le s2: the
    // first quotient reduced along the split scales, the second one a quotient of short fractions.
    PooledInteger root_minus_h1;
    mpz_sqrt(root_minus_h1.mpz(), disc.mpz());
    mpz_sub(root_minus_h1.mpz(), root_minus_h1.mpz(), h[1].mpz());
    Rational l;  // fresh: written in place
    forms::divided_by_powers(root_minus_h1.mpz(), {{sp, 1}, {se, 2}}, l.mpq());
    mpq_div(l.mpq(), l.mpq(), s[2].mpq());
    mpq_div_2exp(l.mpq(), l.mpq(), 1);
    return anysize::rational_lambda_s(l);
  }
  return anysize::lambda_s_of(anysize::to_poly(s.data(), 3), forms::divided_by_powers(disc.mpz(), {{sp, 2}, {se, 4}}));
}

}  // namespace

EvidencePencil::EvidencePencil(const Ellipsoid& e, const Paraboloid& p, bool certificate_reads_forms,
                               EvidenceScratch& scratch)
    : lambda_s(compute(e, p, certificate_reads_forms, scratch)) {}

anysize::LambdaS EvidencePencil::compute(const Ellipsoid& e, const Paraboloid& p, bool certificate_reads_forms,
                                         EvidenceScratch& ws) {
  const std::optional<DoubleMatrix4> pd = p.doubles(), ed = e.doubles();  // copies: read once
  ws.sp = ws.unit;
  ws.se = ws.unit;
  // A sphere and a standard paraboloid read from decimal text: f, s, lambda_s and rho from their
  // closed forms, on short integers (the splits then need no factors).
  const DecimalRecipe* es = ed ? nullptr : storage_of(e).recipe();
  const DecimalRecipe* ps = pd ? nullptr : storage_of(p).recipe();
  const bool closed = es && ps && forms::has_closed_evidence(*es, *ps);
  // The closed forms read only the scales' exponents: then, unless the certificate reads the forms,
  // only those exponents are written (no entries, lcm or rest).
  write_integer_forms(e, p, pd, ed, closed, closed && !certificate_reads_forms, ws);
  if (closed) {
    Rational lambda_s_value, rho_value;  // fresh: written in place
    // S = lcm(lp, le): a sphere's scale is 2^a 5^b, a standard paraboloid's 2^c 5^d lcm(R_a^2, R_b^2).
    forms::sphere_standard_evidence(*es, *ps,
                                    {f, s, lambda_s_value, rho_value, std::max(ws.sp.twos, ws.se.twos),
                                     std::max(ws.sp.fives, ws.se.fives), ws.f_multiple, ws.s_multiple});
    rho = rho_value;
    return anysize::rational_lambda_s(lambda_s_value);
  }
  // g and h in fixed-size integers when the entries are short, else with GMP.
  Quartic<PooledInteger> g;
  Quadratic<PooledInteger> h;
  if (words) {
    small_pencil_polynomials(ws.pw, ws.ew, g, h);
  } else if (!small_pencil_polynomials(ws.pz, ws.ez, g, h)) {
    g = exact_characteristic_polynomial<PooledInteger>(ws.pz, ws.ez);
    h = exact_special_polynomial<PooledInteger>(ws.pz, ws.ez);
  }
  reported_polynomials(g, h, ws.sp, ws.se, ws.lp, ws.le, f, s, ws.f_multiple, ws.s_multiple);
  return lambda_s_of_pencil(h, ws.sp, ws.se, s);
}

// The integer forms, without a rational matrix: as machine words for doubles whose forms fit, else
// written straight into the scratch's pooled integers (the generic formulas without heap traffic for
// temporaries), from the doubles or from the quadric's exact source with the scale's split (each
// scale's rest kept as its denominators' factors: every gcd of the reduction is short).
void EvidencePencil::write_integer_forms(const Ellipsoid& e, const Paraboloid& p,
                                         const std::optional<DoubleMatrix4>& pd, const std::optional<DoubleMatrix4>& ed,
                                         bool closed, bool scales_only, EvidenceScratch& ws) {
  // Doubles whose integer forms fit in machine words (nearly all): those forms with their scales'
  // exponents straight from the doubles, and none in GMP (lp and le are not read: the scales are
  // powers of two; the certificate forms its own from the doubles when it needs one).
  words = pd && ed && forms::small_integer_form(*pd, ws.pw, ws.sp.twos) &&
          forms::small_integer_form(*ed, ws.ew, ws.se.twos);
  if (words) return;
  // Else in pooled integers (a scale of doubles is a power of two: its split is its exponent; an
  // exact source writes its scale in place, so that one is a fresh Integer).
  if (pd) {
    forms::integer_form(*pd, forms::entries(ws.pz), ws.lp);
    ws.sp.twos = mpz_scan1(ws.lp.mpz(), 0);
  } else {
    ws.lp = Integer();
    forms::integer_form_of(storage_of(p), {forms::entries(ws.pz), ws.lp, ws.sp, !closed, !scales_only, !scales_only});
  }
  if (ed) {
    forms::integer_form(*ed, forms::entries(ws.ez), ws.le);
    ws.se.twos = mpz_scan1(ws.le.mpz(), 0);
  } else {
    ws.le = Integer();
    forms::integer_form_of(storage_of(e), {forms::entries(ws.ez), ws.le, ws.se, !closed, !scales_only, !scales_only});
  }
  forms_written = !scales_only;
}

}  // namespace relpos::detail
