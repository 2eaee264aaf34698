// Shared assertions for classification results: everything a case's construction determines
// (position, smallness, rho, f, s, root signs and multiplicities, deg f~, the discriminant signs),
// plus the cross-checks of independent paths (classify_exact, Evidence::Minimal, the kernel
// tangency test, the paper's Table 2 where it applies).
#pragma once

#include <catch2/catch.hpp>
#include <relpos/classify.hpp>
#include <vector>

#include "support/construct.hpp"
#include "support/oracles.hpp"
#include "support/printers.hpp"

namespace rt {

using relpos::Classification;
using relpos::Ellipsoid;
using relpos::Paraboloid;

/// How many multiple rational roots went through kernel_has_common_point (per executable).
inline int g_kernel_checks = 0;
inline int g_kernel_tangent = 0;
/// How many cases were compared with Table 2.
inline int g_table2_checks = 0;

// ---- polynomials as coefficient vectors (index = power) -------------------------------------

using Poly = std::vector<Rational>;

inline void trim(Poly& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

/// p / (l - x), exact (x must be a root).
inline Poly divide_linear(const Poly& p, const Rational& x) {
  const std::size_t n = p.size();
  Poly q(n - 1);
  Rational carry(0);
  for (std::size_t i = n; i-- > 1;) {
    carry = p[i] + carry * x;
    q[i - 1] = carry;
  }
  return q;
}

/// Discriminant of a polynomial of degree 1..4 (classical formulas).
inline Rational discriminant(Poly p) {
  trim(p);
  const std::size_t n = p.size() - 1;
  if (n == 1) return Rational(1);
  if (n == 2) return p[1] * p[1] - 4 * p[2] * p[0];
  if (n == 3) {
    const Rational &a = p[3], &b = p[2], &c = p[1], &d = p[0];
    return b * b * c * c - 4 * a * c * c * c - 4 * b * b * b * d - 27 * a * a * d * d + 18 * a * b * c * d;
  }
  return quartic_discriminant({p[0], p[1], p[2], p[3], p[4]});
}

// ---- expectations ----------------------------------------------------------------------------

struct Expect {
  std::string what;
  Position truth = Position::C;  ///< the geometric position, by construction (when truth_known)
  bool truth_known = true;       ///< false: only the algebra (f, s, rho) is known
  bool small = true;
  Rational rho;
  Quartic<Rational> f;  ///< det(l P + E) of the sign-normalized input, by construction
  Quadratic<Rational> s;
  std::array<Rational, 2> s_roots;   ///< the (rational) roots of s
  bool expect_filter_stage = false;  ///< generic, well-conditioned: the filter must decide
};

inline Expect expect_from(const Config& k) {
  Expect x;
  x.what = describe(k);
  x.truth = k.expected;
  x.small = k.small();
  x.rho = k.rho();
  x.f = paper_f(k.a, k.b, k.c, k.r);
  x.s = paper_s(k.a, k.b);
  x.s_roots = {-k.a * k.a, -k.b * k.b};
  return x;
}

inline Expect expect_from(const Config& k, const Transformed& t) {
  Expect x = expect_from(k);
  x.what += " (transformed: det H = " + relpos::to_string(t.det_h) + ", kE = " + relpos::to_string(t.ke) +
            ", kP = " + relpos::to_string(t.kp) + (t.flip_e ? ", -E" : "") + (t.flip_p ? ", -P" : "") + ")";
  x.f = transformed_f(x.f, t);
  x.s = transformed_s(x.s, t);
  for (auto& r : x.s_roots) r *= t.root_scale();
  return x;
}

/// What relpos answers: the truth, whatever the size (math.md §8).
inline Position answer_for(const Expect& x) { return x.truth; }

inline bool truth_has_contact(Position p) { return p == Position::TI || p == Position::C || p == Position::TE; }

/// The expected degree of f~ = f / gcd(f, s), from the exact multiplicities at the roots of s.
inline int expected_degree_ftilde(const Expect& x, Poly* ftilde = nullptr) {
  Poly ft(x.f.begin(), x.f.end());
  const Poly s(x.s.begin(), x.s.end());
  std::vector<Rational> roots{x.s_roots[0]};
  if (x.s_roots[1] != x.s_roots[0]) roots.push_back(x.s_roots[1]);
  for (const auto& r : roots) {
    const int mf = multiplicity(x.f, r), ms = multiplicity(x.s, r);
    for (int i = 0; i < std::min(mf, ms); ++i) ft = divide_linear(ft, r);
  }
  trim(ft);
  if (ftilde) *ftilde = ft;
  return static_cast<int>(ft.size()) - 1;
}

/// Everything about one classification that the construction determines.
inline void check_against_expectation(const Classification& c, const Expect& x) {
  INFO(x.what);
  // Without a known truth, the root-pattern checks below still hold for whatever was answered.
  const Position want = x.truth_known ? answer_for(x) : c.verdict.position;
  CHECK(c.verdict.position == want);
  CHECK(c.verdict.small == x.small);
  CHECK(c.verdict.rho_vs_one == sgn(x.rho - 1));
  CHECK(!c.rule_text().empty());

  REQUIRE(c.has_full_evidence);
  for (std::size_t i = 0; i < 5; ++i) CHECK(c.f[i] == x.f[i]);
  for (std::size_t i = 0; i < 3; ++i) CHECK(c.s[i] == x.s[i]);
  REQUIRE(c.rho.has_value());  // the roots of s are rational here
  CHECK(*c.rho == x.rho);

  // Discriminants and f~, computed here from the expected polynomials.
  const Rational disc = quartic_discriminant(x.f);
  CHECK(c.verdict.sign_disc_f == sgn(disc));
  Poly ft;
  const int deg = expected_degree_ftilde(x, &ft);
  CHECK(c.degree_ftilde == deg);
  CHECK(c.verdict.sign_disc_ftilde == sgn(discriminant(ft)));
  if (disc != 0) CHECK(c.verdict.sign_disc_ftilde == c.verdict.sign_disc_f);
  if (disc == 0)  // a zero is never certified by a filter, only by an exact stage
    CHECK((c.verdict.stage == relpos::Stage::ExactRoots || c.verdict.stage == relpos::Stage::MultipleRootWitness));

  // Roots: counts, order, intervals, and the multiplicities at every rational root.
  CHECK(c.verdict.real_roots == static_cast<int>(c.roots.size()));
  int with_mult = 0, neg = 0, pos = 0, tangencies = 0;
  for (std::size_t i = 0; i < c.roots.size(); ++i) {
    const auto& r = c.roots[i];
    with_mult += r.multiplicity_f;
    (r.sign < 0 ? neg : pos)++;
    CHECK((r.sign == -1 || r.sign == 1));
    CHECK(r.lower <= r.upper);
    if (i > 0) CHECK(c.roots[i - 1].upper < r.lower);
    if (r.sign < 0) CHECK(r.lower < 0);
    if (r.sign > 0) CHECK(r.upper > 0);
    if (r.tangency()) ++tangencies;
    if (r.exact) {
      CHECK(r.lower <= *r.exact);
      CHECK(*r.exact <= r.upper);
      CHECK(sgn(*r.exact) == r.sign);
      CHECK(multiplicity(x.f, *r.exact) == r.multiplicity_f);
      CHECK(multiplicity(x.s, *r.exact) == r.multiplicity_s);
    }
    if (r.multiplicity_f % 2 == 1 && r.lower < r.upper) CHECK(sgn(eval(x.f, r.lower)) * sgn(eval(x.f, r.upper)) <= 0);
  }
  // Every multiple root of f is rational here or a root of s... not in general: a double root can be
  // irrational only as a conjugate pair; then f = c g^2 and the count below still holds.
  CHECK(with_mult + c.verdict.nonreal_roots == 4);
  CHECK(c.verdict.negative_roots == neg);
  CHECK(c.verdict.positive_roots == pos);
  // Every real root's multiplicities, located by its isolating interval (the only root of f in it):
  // at a root of s (rational here) they are computed exactly; elsewhere mult_s = 0.
  for (const auto& r : c.roots) {
    int ms = 0, mf = -1;
    for (const auto& sr : x.s_roots)
      if (r.lower <= sr && sr <= r.upper && eval(x.f, sr) == 0) {
        ms = multiplicity(x.s, sr);
        mf = multiplicity(x.f, sr);
      }
    CHECK(r.multiplicity_s == ms);
    if (mf >= 0) CHECK(r.multiplicity_f == mf);
  }
  for (const auto& sr : x.s_roots) {
    if (eval(x.f, sr) != 0) continue;
    int found = 0;
    for (const auto& r : c.roots)
      if (r.lower <= sr && sr <= r.upper) ++found;
    CHECK(found == 1);
  }

  // Root pattern of each answer (math.md §3 table): it characterizes every answer of a small
  // pair, and TE and E of any size (math.md §6); I, TI and C of a pair that is not small are decided
  // by math.md §8, not by the root pattern.
  const std::optional<Position> pattern =
      x.small || want == Position::TE || want == Position::E ? std::optional<Position>(want) : std::nullopt;
  if (pattern) switch (*pattern) {
      case Position::I:
        CHECK(c.verdict.nonreal_roots == 0);
        CHECK(c.verdict.positive_roots == 0);
        CHECK(tangencies == 0);
        break;
      case Position::TI:
        CHECK(c.verdict.nonreal_roots == 0);
        CHECK(c.verdict.positive_roots == 0);
        CHECK(tangencies == 1);
        break;
      case Position::C:
        CHECK(c.verdict.nonreal_roots == 2);
        CHECK(c.verdict.positive_roots == 0);
        CHECK(tangencies == 0);
        break;
      case Position::TE:
        CHECK(c.verdict.nonreal_roots == 0);
        CHECK(c.verdict.positive_roots == 1);
        CHECK(tangencies == 1);
        for (const auto& r : c.roots)
          if (r.tangency()) CHECK(r.sign == 1);
        break;
      case Position::E:
        CHECK(c.verdict.nonreal_roots == 0);
        CHECK(c.verdict.positive_roots == 2);
        CHECK(tangencies == 0);
        break;
    }
  if (pattern == Position::TI) {
    for (const auto& r : c.roots)
      if (r.tangency()) CHECK(r.sign == -1);
  }
  if (x.expect_filter_stage)  // a float filter, not exact integers (rational inputs: 1' or 2)
    CHECK((c.verdict.stage == relpos::Stage::SemiStaticDouble || c.verdict.stage == relpos::Stage::Interval ||
           c.verdict.stage == relpos::Stage::StaticDouble));
}

/// classify() and classify_exact() must agree on everything but the stage.
inline void check_same(const Classification& a, const Classification& b) {
  CHECK(a.verdict.position == b.verdict.position);
  CHECK(a.verdict.small == b.verdict.small);
  CHECK(a.verdict.rho_vs_one == b.verdict.rho_vs_one);
  CHECK(a.verdict.sign_disc_f == b.verdict.sign_disc_f);
  CHECK(a.verdict.sign_disc_ftilde == b.verdict.sign_disc_ftilde);
  CHECK(a.verdict.real_roots == b.verdict.real_roots);
  CHECK(a.verdict.negative_roots == b.verdict.negative_roots);
  CHECK(a.verdict.positive_roots == b.verdict.positive_roots);
  CHECK(a.verdict.nonreal_roots == b.verdict.nonreal_roots);
  CHECK(a.has_full_evidence == b.has_full_evidence);
  if (a.has_full_evidence && b.has_full_evidence) {
    for (std::size_t i = 0; i < 5; ++i) CHECK(a.f[i] == b.f[i]);
    for (std::size_t i = 0; i < 3; ++i) CHECK(a.s[i] == b.s[i]);
    CHECK(a.degree_ftilde == b.degree_ftilde);
    REQUIRE(a.roots.size() == b.roots.size());
    for (std::size_t i = 0; i < a.roots.size(); ++i) {
      CHECK(a.roots[i].sign == b.roots[i].sign);
      CHECK(a.roots[i].multiplicity_f == b.roots[i].multiplicity_f);
      CHECK(a.roots[i].multiplicity_s == b.roots[i].multiplicity_s);
      CHECK(a.roots[i].exact.has_value() == b.roots[i].exact.has_value());
      if (a.roots[i].exact && b.roots[i].exact) CHECK(*a.roots[i].exact == *b.roots[i].exact);
    }
    CHECK(a.rho.has_value() == b.rho.has_value());
    if (a.rho && b.rho) CHECK(*a.rho == *b.rho);
  }
}

/// The independent tangency test (math.md §3) on every rational multiple root, for small
/// pairs. (Beyond smallness a root of s can carry a tangential contact point of two crossing
/// surfaces: the kernel test then finds a common point although mult_f - mult_s < 2; see
/// test_classify_constructed, "not small".)
inline void check_kernel(const Ellipsoid& e, const Paraboloid& p, const Classification& c) {
  if (!c.verdict.small) return;
  for (const auto& r : c.roots) {
    if (r.multiplicity_f < 2 || !r.exact) continue;
    INFO("multiple root " << relpos::to_string(*r.exact) << " mult_f " << r.multiplicity_f << " mult_s "
                          << r.multiplicity_s);
    CHECK(relpos::detail::oracle::kernel_has_common_point(e, p, *r.exact) == r.tangency());
    ++g_kernel_checks;
    if (r.tangency()) ++g_kernel_tangent;
  }
}

/// The paper's Table 2, wherever it applies: small, and Disc(f) != 0 or f~ == f.
inline void check_table2(const Classification& c) {
  if (!c.verdict.small || !c.has_full_evidence) return;
  if (c.verdict.sign_disc_f == 0 && c.degree_ftilde != 4) return;
  CHECK(table2(c.f) == c.verdict.position);
  ++g_table2_checks;
}

/// Classify with every path and check everything; returns the Full classify() result.
inline Classification check_all(const Ellipsoid& e, const Paraboloid& p, const Expect& x) {
  INFO(x.what);
  const Classification c = relpos::classify(e, p);
  check_against_expectation(c, x);
  const Classification ce = relpos::classify_exact(e, p);
  CHECK(ce.verdict.stage != relpos::Stage::Interval);
  check_same(c, ce);
  const Classification cm = relpos::classify(e, p, relpos::Evidence::Minimal);
  CHECK_FALSE(cm.has_full_evidence);
  CHECK(cm.verdict.position == c.verdict.position);
  CHECK(cm.verdict.small == c.verdict.small);
  CHECK(cm.verdict.rho_vs_one == c.verdict.rho_vs_one);
  CHECK(cm.verdict.sign_disc_f == c.verdict.sign_disc_f);
  CHECK(cm.verdict.real_roots == c.verdict.real_roots);
  CHECK(cm.verdict.nonreal_roots == c.verdict.nonreal_roots);
  check_kernel(e, p, c);
  check_table2(c);
  return c;
}

inline Classification check_config(const Config& k) {
  const Ellipsoid e = Ellipsoid::from_matrix(k.e());
  const Paraboloid p = Paraboloid::from_matrix(k.p());
  return check_all(e, p, expect_from(k));
}

inline Classification check_config_transformed(const Config& k, Rng& g, bool rigid = false) {
  const Transformed t = transform(k.e(), k.p(), g, rigid);
  const Ellipsoid e = Ellipsoid::from_matrix(t.e);
  const Paraboloid p = Paraboloid::from_matrix(t.p);
  return check_all(e, p, expect_from(k, t));
}

}  // namespace rt
