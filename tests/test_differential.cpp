// Differential tests at scale (doc/testing.md): thousands of random pairs per run, each classified by
// the adaptive path and the exact path and compared with
//   - an independent method: f and s recomputed by Gaussian elimination and interpolation, smallness
//     by the closed-form root of s, and the roots of f located by MPFR Aberth iteration and certified
//     by the Gerschgorin / Braess-Hadeler inclusion theorem evaluated in exact arithmetic
//     (support/certified_roots.hpp); where every root is isolated and its kind and sign decided, the
//     position follows from the table of math.md §3 and §6 (f is then square-free);
//   - the kernel tangency test (kernel_has_common_point) on every rational multiple root;
//   - the position known by construction (exact tangencies and their neighbours, near-tangent
//     perturbations, spheres on the axis, geometric certificates);
//   - itself under random rational affine congruences, positive rescaling, sign flips, signed
//     permutations of the coordinates, and exact conversions of double inputs (doubles vs the same
//     numbers as exact decimal strings or fractions through the JSON reader, and vs a non-dyadic
//     rescaling that bypasses the double filter).
// Pairs that are not small (math.md §6) are included: only E, TE and contact: true may be
// claimed for them.
//
// The seed is printed; RELPOS_SEED=<n> reruns or varies it.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <string>
#include <vector>

#include "support/certified_roots.hpp"
#include "support/checks.hpp"
#include "support/construct.hpp"
#include "support/oracles.hpp"
#include "support/printers.hpp"
#include "support/scale.hpp"
#include "support/secular.hpp"
#include "support/seed.hpp"

using namespace rt;
using relpos::Classification;
using relpos::Ellipsoid;
using relpos::Paraboloid;
using relpos::Verdict;

using relpos::testing::secular_position;

namespace {

std::uint64_t run_seed() {
  static const std::uint64_t seed = relpos::testing::announced_seed("test_differential", 20240611ULL);
  return seed;
}

/// A pair and what its construction says.
struct Case {
  std::string name;
  Matrix4 e, p;
  bool truth_known = false;
  Position truth = Position::C;  ///< read only when truth_known
  bool tangency = false;         ///< an exact tangency by construction (TI or TE)
};

struct Stats {
  int cases = 0, variants = 0, certified = 0, position_by_certificate = 0, partial = 0, kernel = 0, truth = 0,
      not_small = 0;
  int by_position[5] = {0, 0, 0, 0, 0};
};

Stats& stats() {
  static Stats s;
  return s;
}

// ---- the independent position -------------------------------------------------------------------

/// The table of math.md §3 and §6 for a square-free f whose roots are all certified; nullopt
/// when the root pattern alone does not decide (not small and not E, or outside the table).
std::optional<Position> position_from_certificate(const RootCertificate& c, int rho_sign,
                                                  std::optional<bool>* contact) {
  const int nonreal = c.count(-1), positive = c.count(1, 1);
  if (nonreal == 0 && positive == 2) {
    *contact = false;
    return Position::E;  // any size
  }
  if (rho_sign > 0) {  // not small: nothing else is claimed; non-real roots certify contact
    *contact = nonreal > 0 ? std::optional<bool>(true) : std::nullopt;
    return std::nullopt;
  }
  if (nonreal == 2 && positive == 0) {
    *contact = true;
    return Position::C;
  }
  if (nonreal == 0 && positive == 0) {
    *contact = false;
    return Position::I;
  }
  *contact = std::nullopt;
  return std::nullopt;  // a finding
}

/// Everything the independent method says about c (the Full classification of e, p).
void check_independent(const Ellipsoid& e, const Paraboloid& p, const Classification& c) {
  // f and s by interpolation, smallness by the closed form.
  const Quartic<Rational> f = interpolated_f(e.matrix(), p.matrix());
  const auto s = interpolated_s(e.matrix(), p.matrix());
  REQUIRE(s.has_value());
  for (std::size_t i = 0; i < 5; ++i) CHECK(c.f[i] == f[i]);
  for (std::size_t i = 0; i < 3; ++i) CHECK(c.s[i] == (*s)[i]);
  const int rho = rho_vs_one(f, *s);
  CHECK(c.verdict.rho_vs_one == rho);
  CHECK(c.verdict.small == (rho <= 0));

  const RootCertificate cert = certify_roots(f);
  REQUIRE(cert.valid);
  if (cert.complete()) {
    ++stats().certified;
    const int nonreal = cert.count(-1);
    CHECK(c.verdict.nonreal_roots == nonreal);
    CHECK(c.verdict.real_roots == 4 - nonreal);
    CHECK(c.verdict.negative_roots == cert.count(1, -1));
    CHECK(c.verdict.positive_roots == cert.count(1, 1));
    CHECK(c.verdict.sign_disc_f == ((nonreal / 2) % 2 ? -1 : 1));  // square-free: (-1)^(non-real pairs)
    CHECK(c.verdict.sign_disc_ftilde == c.verdict.sign_disc_f);
    std::optional<bool> contact;
    std::optional<Position> want = position_from_certificate(cert, rho, &contact);
    if (!want && rho > 0) {
      // Not small and not E: the root pattern alone does not decide; the secular method does
      // (math.md §8), for any size.
      want = secular_position(e, p);
      contact = truth_has_contact(*want);
    }
    CHECK(want.has_value());
    CHECK(want == c.verdict.position);
    if (contact) CHECK(truth_has_contact(c.verdict.position) == *contact);
    ++stats().position_by_certificate;
  } else {
    ++stats().partial;
    // What is certified still bounds the exact answer.
    CHECK(c.verdict.nonreal_roots >= cert.count(-1));
    CHECK(c.verdict.negative_roots >= cert.count(1, -1));
    CHECK(c.verdict.positive_roots >= cert.count(1, 1));
  }
  // Every isolated real disk meets the isolating interval of a simple real root of the right sign;
  // every rational multiple root of f lies in a cluster of at least that many disks.
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& d = cert.disks[k];
    if (d.cluster_size != 1 || d.kind != 1) continue;
    // The root lies in the disk and in its own isolating interval: some interval meets the disk,
    // and if only one does, it is that root's.
    std::vector<const relpos::RealRoot*> hits;
    for (const auto& r : c.roots)
      if (interval_meets_disk(cert, k, r.lower, r.upper)) hits.push_back(&r);
    REQUIRE(!hits.empty());
    if (hits.size() == 1) {
      CHECK(hits[0]->multiplicity_f == 1);
      if (d.sign != 0) CHECK(hits[0]->sign == d.sign);
    }
  }
  for (const auto& r : c.roots) {
    if (r.multiplicity_f < 2 || !r.exact) continue;
    int best = 0;
    for (std::size_t k = 0; k < 4; ++k)
      if (cert.contains(k, {*r.exact, Rational(0)})) best = std::max(best, cert.disks[k].cluster_size);
    CHECK(best >= r.multiplicity_f);
  }
}

// ---- one case -------------------------------------------------------------------------------------

void check_same_verdict(const Verdict& a, const Verdict& b) {
  CHECK(a.position == b.position);
  CHECK(a.small == b.small);
  CHECK(a.rho_vs_one == b.rho_vs_one);
  CHECK(a.negative_roots == b.negative_roots);
  CHECK(a.positive_roots == b.positive_roots);
  CHECK(a.nonreal_roots == b.nonreal_roots);
  CHECK(a.sign_disc_f == b.sign_disc_f);
  CHECK(a.sign_disc_ftilde == b.sign_disc_ftilde);
}

/// A signed permutation of the coordinates plus a translation.
Matrix4 signed_permutation(Rng& g) {
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int* perm = perms[g.uniform(0, 5)];
  Matrix3 l;
  for (int i = 0; i < 3; ++i) l(i, perm[i]) = g.chance(50) ? Rational(-1) : Rational(1);
  return affine_matrix(l, {g.rational(-3, 3, 2), g.rational(-3, 3, 2), g.rational(-3, 3, 2)});
}

Classification run_case(const Case& k, Rng& g) {
  INFO(k.name);
  ++stats().cases;
  const Ellipsoid e = Ellipsoid::from_matrix(k.e);
  const Paraboloid p = Paraboloid::from_matrix(k.p);
  const Classification c = relpos::classify(e, p);
  // Adaptive == exact on everything the verdict holds (the Full evidence of both comes from the same
  // exact root code, so the exact path runs with Minimal evidence).
  const Classification x = relpos::classify_exact(e, p, relpos::Evidence::Minimal);
  CHECK(x.verdict.stage != relpos::Stage::Interval);
  CHECK(c.verdict.position == x.verdict.position);
  CHECK(c.verdict.small == x.verdict.small);
  CHECK(c.verdict.rho_vs_one == x.verdict.rho_vs_one);
  CHECK(c.verdict.rule == x.verdict.rule);
  CHECK(c.verdict.sign_disc_f == x.verdict.sign_disc_f);
  CHECK(c.verdict.sign_disc_ftilde == x.verdict.sign_disc_ftilde);
  CHECK(c.verdict.real_roots == x.verdict.real_roots);
  CHECK(c.verdict.negative_roots == x.verdict.negative_roots);
  CHECK(c.verdict.positive_roots == x.verdict.positive_roots);
  CHECK(c.verdict.nonreal_roots == x.verdict.nonreal_roots);
  const Verdict v = relpos::decide_position(e, p);
  CHECK(v.position == c.verdict.position);
  CHECK(v.small == c.verdict.small);
  // A zero is never certified by a float filter, only by an exact stage (GMP roots or the exact
  // multiple-root witness on machine integers).
  if (c.verdict.sign_disc_f == 0)
    CHECK((c.verdict.stage == relpos::Stage::ExactRoots || c.verdict.stage == relpos::Stage::MultipleRootWitness));
  ++stats().by_position[static_cast<int>(c.verdict.position)];

  check_independent(e, p, c);

  if (!c.verdict.small) {
    ++stats().not_small;
    CHECK(c.verdict.position == secular_position(e, p));
  }
  if (k.truth_known) {
    ++stats().truth;
    CHECK(c.verdict.position == k.truth);
  }
  // The kernel test on rational multiple roots (small pairs; for TE at any size on the tangency).
  int tangent_kernel = 0;
  for (const auto& r : c.roots) {
    if (r.multiplicity_f < 2 || !r.exact) continue;
    const bool kernel = relpos::detail::oracle::kernel_has_common_point(e, p, *r.exact);
    if (c.verdict.small) CHECK(kernel == r.tangency());
    if (kernel) ++tangent_kernel;
    ++stats().kernel;
  }
  if (k.tangency && (c.verdict.small || k.truth == Position::TE)) CHECK(tangent_kernel >= 1);

  // Invariance: a random congruence with positive rescaling and sign flips, a signed permutation.
  const Transformed t = transform(k.e, k.p, g, g.chance(30));
  check_same_verdict(relpos::decide_position(Ellipsoid::from_matrix(t.e), Paraboloid::from_matrix(t.p)), v);
  const Matrix4 h = signed_permutation(g);
  const Ellipsoid e2 = Ellipsoid::from_matrix(congruence(k.e, h));
  const Paraboloid p2 = Paraboloid::from_matrix(congruence(k.p, h));
  check_same_verdict(relpos::decide_position(e2, p2), v);
  CHECK(relpos::classify(e2, p2, relpos::Evidence::Minimal).verdict.position == c.verdict.position);
  stats().variants += 3;
  return c;
}

// ---- case families --------------------------------------------------------------------------------

Case from_config(const Config& k, bool truth_known) {
  Case c;
  c.name = describe(k);
  c.e = k.e();
  c.p = k.p();
  c.truth_known = truth_known;
  c.truth = k.expected;
  c.tangency = truth_known && (k.expected == Position::TI || k.expected == Position::TE);
  return c;
}

/// The same case in a random affine frame (the truth does not change).
Case moved(Case c, Rng& g) {
  const Transformed t = transform(c.e, c.p, g, g.chance(50));
  c.e = t.e;
  c.p = t.p;
  c.name += " (random frame)";
  return c;
}

/// Truth in the standard frame for any size, where an argument gives it: the axis (test_properties's
/// oracle), a point of the cup inside the ball (contact; C), a separating tangent plane (E).
bool oracle(const Config& k, Position* truth) {
  if (k.c[0] == 0 && k.c[1] == 0) {
    const Rational a2 = k.amin() * k.amin(), z = k.c[2];
    if (z < k.r) {
      *truth = axis_position(z, k.r);
    } else {
      const Rational d2 = z <= a2 / 2 ? z * z : a2 * z - a2 * a2 / 4;
      *truth = d2 > k.r * k.r ? Position::I : (d2 == k.r * k.r ? Position::TI : Position::C);
    }
    return true;
  }
  if (crossing_certificate(k)) {
    *truth = Position::C;
    return true;
  }
  if (separation_certificate(k)) {
    *truth = Position::E;
    return true;
  }
  return false;
}

Case oracle_case(Config k, const char* name) {
  k.name = name;
  Position truth = Position::C;  // set when known
  const bool known = oracle(k, &truth);
  k.expected = truth;
  return from_config(k, known);
}

/// Standard-frame sphere configurations biased towards degenerate ones (axis, symmetry planes,
/// circular cups, vertex tangencies, centres on the surface, rho = 1).
Config random_config(Rng& g, bool large) {
  static const Rational ab[] = {Q(1, 2), Q(1), Q(3, 2), Q(2), Q(5, 4)};
  Config k;
  k.a = ab[g.uniform(0, 4)];
  k.b = g.chance(25) ? k.a : ab[g.uniform(0, 4)];
  k.c = {Q(g.uniform(-8, 8), 4), Q(g.uniform(-8, 8), 4), Q(g.uniform(-8, 8), 4)};
  const Rational a2 = k.amin() * k.amin();
  // Small: 2r <= a^2. Large: 2r > a^2.
  k.r = large ? a2 / 2 + a2 * Q(g.uniform(1, 24), 8) : a2 * Q(g.uniform(1, 16), 32);
  const long kind = g.uniform(0, 99);
  if (kind < 12)
    k.c[0] = 0;
  else if (kind < 24)
    k.c[1] = 0;
  else if (kind < 40)
    k.c[0] = k.c[1] = 0;
  else if (kind < 50) {
    k.c[0] = k.c[1] = 0;
    k.c[2] = g.chance(50) ? k.r : -k.r;
  } else if (kind < 58) {
    k.c[2] = paraboloid_value(k.a, k.b, {k.c[0], k.c[1], Rational(0)});
  } else if (kind < 64 && !large) {
    k.r = a2 / 2;  // rho = 1
  }
  return k;
}

void generic_cases(Rng& g, int n) {
  for (int i = 0; i < n; ++i) {
    const Vector3 c{g.rational(-6, 6, 2), g.rational(-6, 6, 2), g.rational(-3, 6, 2)};
    const Vector3 axes{g.positive_rational(4, 4), g.positive_rational(4, 4), g.positive_rational(4, 4)};
    Case k;
    k.name = "generic " + std::to_string(i);
    k.e = Ellipsoid::from_axes(c, axes, random_quaternion(g)).matrix();
    k.p = Paraboloid::standard({g.rational(-2, 2, 2), g.rational(-2, 2, 2), g.rational(-2, 2, 2)},
                               g.positive_rational(4, 2), g.positive_rational(4, 2), random_quaternion(g))
              .matrix();
    run_case(k, g);
  }
}

void frame_cases(Rng& g, int n, bool large) {
  for (int i = 0; i < n; ++i) {
    Case k = oracle_case(random_config(g, large), large ? "standard frame, not small" : "standard frame");
    run_case(g.chance(30) ? moved(k, g) : k, g);
  }
}

/// Exact tangencies at points with rational normals and the nine neighbours of each (small), or
/// the TE / E members for spheres of any size.
void tangency_cases(Rng& g, int points, bool large) {
  for (int i = 0; i < points; ++i) {
    const Rational a = Q(g.uniform(2, 8), 4), b = g.chance(25) ? a : Q(g.uniform(2, 8), 4);
    const auto [s, t] = random_st(g, g.chance(20));
    const TangentPoint tp = tangent_point(a, b, s, t);
    const Rational a2 = rmin(a, b) * rmin(a, b);
    const Rational r = large ? a2 * Q(g.uniform(3, 24), 4) : random_tangent_radius(g, a, b);
    const auto family = tangency_family(tp, r, g.uniform(1, 7));
    for (std::size_t m = 0; m < family.size(); ++m) {
      // Beyond smallness the truth of the family holds for the outer members only (TE at the
      // point and the E spheres inside its open ball): a large inner sphere is not tangent.
      const bool outer = family[m].expected == Position::TE || family[m].expected == Position::E;
      if (large && !outer) continue;
      const Case k = from_config(family[m], true);
      run_case(g.chance(40) ? moved(k, g) : k, g);
    }
  }
}

/// TI and TE spheres with the radius multiplied by 1 -+ eps, eps = 2^-k or 10^-k: I / C and E / C
/// by construction, with roots of f a distance ~sqrt(eps) apart.
void near_tangent_cases(Rng& g, int n) {
  for (int i = 0; i < n; ++i) {
    const Rational a = Q(g.uniform(2, 8), 4), b = g.chance(25) ? a : Q(g.uniform(2, 8), 4);
    const auto [s, t] = random_st(g, g.chance(20));
    const TangentPoint tp = tangent_point(a, b, s, t);
    const Rational r = random_tangent_radius(g, a, b);
    const bool inside = g.chance(50), grow = g.chance(50);
    Rational eps(1);
    if (g.chance(50))
      for (long j = g.uniform(10, 160); j > 0; --j) eps /= 2;
    else
      for (long j = g.uniform(3, 45); j > 0; --j) eps /= 10;
    Config k;
    k.a = a;
    k.b = b;
    k.c = tp.along(inside ? -r : r);
    k.r = grow ? r * (1 + eps) : r * (1 - eps);
    k.expected = grow ? Position::C : (inside ? Position::I : Position::E);
    k.name = std::string("near-tangent ") + (inside ? "TI" : "TE") + (grow ? " grown" : " shrunk") + " by " +
             relpos::to_decimal(eps, 3);
    const Case c = from_config(k, true);
    run_case(g.chance(30) ? moved(c, g) : c, g);
  }
}

/// -a^2 (plane x = 0) and -b^2 (plane y = 0) double roots of f that are roots of s (math.md
/// §3): no tangency unless f~ keeps a multiple root.
void special_root_cases(Rng& g, int n) {
  for (int i = 0; i < n; ++i) {
    Config k;
    k.a = Q(g.uniform(2, 8), 4);
    do k.b = Q(g.uniform(2, 8), 4);
    while (k.b == k.a);
    k.r = rmin(k.a, k.b) * rmin(k.a, k.b) * Q(g.uniform(1, 8), 16);
    const Rational a2 = k.a * k.a, b2 = k.b * k.b;
    if (g.chance(50)) {
      const Rational yc = Q(g.uniform(-8, 8), 8);
      k.c = {Rational(0), yc, yc * yc / (b2 - a2) + k.r * k.r / a2 + a2 / 4};
    } else {
      const Rational xc = Q(g.uniform(-12, 12), 8);
      k.c = {xc, Rational(0), xc * xc / (a2 - b2) + k.r * k.r / b2 + b2 / 4};
    }
    const Case c = oracle_case(k, "special root of s");
    run_case(g.chance(30) ? moved(c, g) : c, g);
  }
}

// ---- doubles ----------------------------------------------------------------------------------------

/// The exact decimal expansion of a double (m / 2^k = m 5^k / 10^k).
std::string exact_decimal(double x) {
  const Rational q = relpos::exact_rational(x);
  Integer den = q.denominator();
  unsigned long k = 0;
  while (den % 2 == 0) {
    den = den / 2;
    ++k;
  }
  Integer five;
  mpz_ui_pow_ui(five.mpz(), 5, k);
  const Integer m = q.numerator() * five;
  std::string digits = relpos::to_string(m < 0 ? Integer(-m) : m);
  if (k > 0) {
    if (digits.size() <= k) digits = std::string(k - digits.size() + 1, '0') + digits;
    digits.insert(digits.size() - k, ".");
  }
  return (m < 0 ? "-" : "") + digits;
}

double random_double(Rng& g, int lo_exp, int hi_exp) {
  const double mantissa = static_cast<double>(g.uniform(1L << 52, (1L << 53) - 1));
  const double x = std::ldexp(mantissa, static_cast<int>(g.uniform(lo_exp, hi_exp)) - 52);
  return g.chance(50) ? -x : x;
}

/// A random ellipsoid and paraboloid whose matrix entries are doubles, fed in four ways that must
/// give the same exact matrices and the same answer: exact_rational of the doubles, their exact
/// decimal expansions and their fractions through the JSON reader, and the matrices scaled by 1/3
/// (no longer doubles: the static filter is skipped) or by 2^k (still doubles).
void double_cases(Rng& g, int n) {
  int done = 0;
  while (done < n) {
    std::array<double, 16> de{}, dp{};
    auto sym = [](std::array<double, 16>& m, int i, int j, double v) { m[4 * i + j] = m[4 * j + i] = v; };
    const int scale = static_cast<int>(g.uniform(-30, 30));
    for (int i = 0; i < 3; ++i) sym(de, i, i, std::ldexp(std::fabs(random_double(g, 0, 1)), scale));
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) sym(de, i, j, g.chance(50) ? 0.0 : random_double(g, -4, -2) * de[0]);
    for (int i = 0; i < 3; ++i) sym(de, i, 3, random_double(g, -2, 2) * de[4 * i + i]);
    de[15] = random_double(g, -3, 3) * de[0];
    sym(dp, 0, 0, std::fabs(random_double(g, -2, 2)));
    sym(dp, 1, 1, std::fabs(random_double(g, -2, 2)));
    for (int i = 0; i < 3; ++i) sym(dp, i, 3, random_double(g, -2, 2));
    dp[15] = random_double(g, -3, 3);
    Matrix4 me, mp;
    for (std::size_t i = 0; i < 16; ++i) {
      me.a[i] = relpos::exact_rational(de[i]);
      mp.a[i] = relpos::exact_rational(dp[i]);
    }
    std::optional<Ellipsoid> e;
    std::optional<Paraboloid> p;
    try {
      e = Ellipsoid::from_matrix(me);
      p = Paraboloid::from_matrix(mp);
    } catch (const relpos::InputError&) {
      continue;  // not an ellipsoid (det E >= 0) or a degenerate paraboloid: draw again
    }
    ++done;
    REQUIRE(e->doubles().has_value());
    REQUIRE(p->doubles().has_value());
    Case k;
    k.name = "doubles";
    k.e = me;
    k.p = mp;
    const Classification c = run_case(k, g);

    // The same numbers as text: exact decimals (JSON numbers, read from their text) and fractions.
    auto text = [](const std::array<double, 16>& d, const Matrix4& m, bool fractions) {
      std::string out = "[";
      for (std::size_t i = 0; i < 16; ++i) {
        out += i % 4 == 0 ? (i ? "],[" : "[") : ",";
        out += fractions ? "\"" + relpos::to_string(m.a[i]) + "\"" : exact_decimal(d[i]);
      }
      return out + "]]";
    };
    for (bool fractions : {false, true}) {
      const Ellipsoid e2 = relpos::io::ellipsoid_from_json(text(de, me, fractions));
      const Paraboloid p2 = relpos::io::paraboloid_from_json(text(dp, mp, fractions));
      CHECK(e2.matrix() == e->matrix());
      CHECK(p2.matrix() == p->matrix());
    }
    // Non-dyadic rescaling: same answer through intervals / exact integers.
    const Ellipsoid e3 = Ellipsoid::from_matrix(scaled(me, Q(1, 3)));
    const Paraboloid p3 = Paraboloid::from_matrix(scaled(mp, Q(5, 7)));
    CHECK_FALSE(e3.doubles().has_value());
    check_same_verdict(relpos::decide_position(e3, p3), relpos::decide_position(*e, *p));
    // Power-of-two rescaling: still doubles, same answer.
    const Ellipsoid e4 = Ellipsoid::from_matrix(scaled(me, Q(1L << g.uniform(0, 40))));
    CHECK(e4.doubles().has_value());
    CHECK(relpos::decide_position(e4, *p).position == c.verdict.position);
    stats().variants += 4;
  }
}

}  // namespace

TEST_CASE("differential: adaptive vs exact vs certified MPFR roots vs constructions, invariances",
          "[differential][random]") {
  Rng g(run_seed());
  CAPTURE(g.seed);
  // A quarter of the mix under AddressSanitizer (support/scale.hpp).
  const int n = relpos::testing::kSanitizerShare;
  generic_cases(g, 600 / n);
  frame_cases(g, 700 / n, false);
  frame_cases(g, 300 / n, true);
  tangency_cases(g, 70 / n, false);
  tangency_cases(g, 60 / n, true);
  near_tangent_cases(g, 500 / n);
  special_root_cases(g, 300 / n);
  double_cases(g, 400 / n);
  const Stats& s = stats();
  std::cout << "test_differential: " << s.cases << " cases (+" << s.variants << " transformed / re-encoded variants); "
            << s.certified << " with every root certified by MPFR + inclusion disks (" << s.position_by_certificate
            << " positions compared), " << s.partial << " partly certified; " << s.kernel << " kernel tests; "
            << s.truth << " positions known by construction; " << s.not_small
            << " not small; answers I/TI/C/TE/E = " << s.by_position[0] << "/" << s.by_position[1] << "/"
            << s.by_position[2] << "/" << s.by_position[3] << "/" << s.by_position[4] << std::endl;
  // Every position occurs, and the independent method decides most generic cases.
  for (int k = 0; k < 5; ++k) CHECK(s.by_position[k] > 20 / n);
  CHECK(s.certified * 3 > s.cases);
  CHECK(s.truth * 2 > s.cases);
}

TEST_CASE("the independent method itself: certified roots of quartics with known roots", "[differential]") {
  // Simple real roots of both signs: complete, with the right counts and signs.
  RootCertificate c = certify_roots(quartic_from_roots(Q(-3), {Q(-3), Q(-1, 2), Q(1), Q(2)}));
  REQUIRE(c.complete());
  CHECK(c.count(1, -1) == 2);
  CHECK(c.count(1, 1) == 2);
  // (l^2 + 1)(l - 1)(l + 2): a non-real pair.
  const Quartic<Rational> g{Q(-2), Q(1), Q(-1), Q(1), Q(1)};  // (l^2 + 1)(l^2 + l - 2)
  c = certify_roots(g);
  REQUIRE(c.complete());
  CHECK(c.count(-1) == 2);
  CHECK(c.count(1, 1) == 1);
  CHECK(c.count(1, -1) == 1);
  // Roots 2^-40 apart are still separated at 256 bits.
  const Rational eps = Q(1, 1L << 40);
  c = certify_roots(quartic_from_roots(Q(1), {Q(-1), Q(-1) + eps, Q(3), Q(5)}));
  CHECK(c.complete());
  // A double root: a cluster of two disks containing it, never two isolated roots.
  c = certify_roots(quartic_from_roots(Q(-2), {Q(-1, 3), Q(-1, 3), Q(2), Q(-7)}));
  REQUIRE(c.valid);
  CHECK_FALSE(c.complete());
  int in_pair = 0;
  for (std::size_t k = 0; k < 4; ++k)
    if (c.disks[k].cluster_size == 2 && c.contains(k, {Q(-1, 3), Q(0)})) ++in_pair;
  CHECK(in_pair >= 1);
  CHECK(c.count(1, 1) == 1);
  CHECK(c.count(1, -1) == 1);
  // The closed-form smallness agrees with rho = 4 r^2 / a^4 in the standard frame.
  for (const auto& [r, want] : {std::pair{Q(1, 4), -1}, std::pair{Q(1, 2), 0}, std::pair{Q(3, 4), 1}}) {
    const Config k{"", Q(1), Q(2), {Q(0), Q(0), Q(1)}, r, Position::C};  // expected not used
    CHECK(rho_vs_one(paper_f(k.a, k.b, k.c, k.r), paper_s(k.a, k.b)) == want);
    const auto s = interpolated_s(k.e(), k.p());
    REQUIRE(s.has_value());
    CHECK(interpolated_f(k.e(), k.p()) == paper_f(k.a, k.b, k.c, k.r));
  }
}
