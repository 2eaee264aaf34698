#include "relpos/classify.hpp"

#include <CGAL/Interval_nt.h>
#include <gmp.h>

#include <cmath>

#include "relpos/smallness.hpp"
#include "relpos/static_filter.hpp"
#include "relpos/sturm.hpp"

namespace relpos {

std::string to_string(Position p) {
  switch (p) {
    case Position::I: return "I";
    case Position::TI: return "TI";
    case Position::C: return "C";
    case Position::TE: return "TE";
    case Position::E: return "E";
    case Position::Unclassified: return "unclassified";
  }
  return "unclassified";
}

std::string to_string(Stage s) {
  switch (s) {
    case Stage::StaticDouble: return "static-double";
    case Stage::Interval: return "interval";
    case Stage::ExactSigns: return "exact-signs";
    case Stage::ExactRoots: return "exact-roots";
  }
  return "?";
}

namespace {

/// The root facts the decision needs, however they were obtained.
struct Facts {
  int real = 0, negative = 0, positive = 0, nonreal = 0;
  int tangent_negative = 0, tangent_positive = 0;  ///< distinct multiple roots of f~, by sign
  int nonreal_multiple = 0;
};

std::string pattern(const Facts& x) {
  return std::to_string(x.real) + " distinct real roots (" + std::to_string(x.negative) + " negative, " +
         std::to_string(x.positive) + " positive), " + std::to_string(x.nonreal) + " non-real, " +
         std::to_string(x.tangent_negative + x.tangent_positive) + " multiple root(s) of f~";
}

/// The classification table (math.md sections 3 and 6), written once for every stage.
void decide(const Facts& x, int rho_vs_one, Classification& out) {
  out.small = rho_vs_one <= 0;
  out.rho_vs_one = rho_vs_one;
  const int tangencies = x.tangent_negative + x.tangent_positive;
  auto finding = [&](const std::string& why) {
    out.position = Position::Unclassified;
    out.finding = why + ": " + pattern(x);
    out.rule = "root pattern outside the classification table (reported, not guessed)";
  };
  if (x.nonreal_multiple > 0) return finding("f has a multiple non-real root");

  // Valid for any size (math.md section 6, Wang-Wang-Kim through a projective map).
  if (tangencies == 1 && x.tangent_positive == 1) {
    if (x.nonreal != 0) return finding("positive multiple root together with non-real roots");
    out.position = Position::TE;
    out.contact = true;
    out.rule = "f~ has a positive multiple root (lambda3 = lambda4 > 0): tangent from outside";
    return;
  }
  if (tangencies == 0 && x.nonreal == 0 && x.positive == 2) {
    out.position = Position::E;
    out.contact = false;
    out.rule = "f has two distinct positive roots (0 < lambda3 < lambda4): separated";
    return;
  }
  if (!out.small) {
    out.position = Position::Unclassified;
    if (x.nonreal > 0) {
      out.contact = true;
      out.rule = "not small; f has non-real roots, so the surfaces meet (Finsler-Calabi), but the type of "
                 "contact needs the full arrangement classification";
    } else {
      out.contact.reset();
      out.rule = "not small and no positive roots certify separation: interior, tangency from inside and "
                 "two-component intersections are beyond the paper's theorem";
    }
    return;
  }
  // Small: the table of math.md section 3.
  if (tangencies == 0 && x.nonreal == 2) {
    if (x.positive != 0) return finding("non-real pair together with positive real roots");
    out.position = Position::C;
    out.contact = true;
    out.rule = "f has a pair of non-real roots and f~ no multiple root (Disc(f~) < 0): crossing contact";
    return;
  }
  if (tangencies == 1 && x.tangent_negative == 1 && x.nonreal == 0 && x.positive == 0) {
    out.position = Position::TI;
    out.contact = true;
    out.rule = "f~ has a negative multiple root (Disc(f~) = 0), all roots of f real and negative: tangent "
               "from inside";
    return;
  }
  if (tangencies == 0 && x.nonreal == 0 && x.positive == 0) {
    out.position = Position::I;
    out.contact = false;
    out.rule = "f~ is square-free (Disc(f~) > 0) and all roots of f are real and negative: interior";
    return;
  }
  finding("small pair with a root pattern the theorem excludes");
}

/// Matrix view with entries converted to NT, for the generic pencil code.
template <class NT>
struct MatrixOf {
  std::array<NT, 16> a;
  const NT& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

using Interval = CGAL::Interval_nt<false>;

/// Power-of-two exponent that brings the largest entry of m near 1 (guards interval overflow and
/// underflow; a positive scaling of either matrix changes no decision, math.md section 1).
long balancing_exponent(const Matrix4& m) {
  double mx = 0;
  for (const auto& q : m.a) mx = std::max(mx, std::fabs(CGAL::to_double(q)));
  if (mx == 0 || !std::isfinite(mx)) return 0;
  int e;
  std::frexp(mx, &e);
  return -static_cast<long>(e);
}

MatrixOf<Interval> to_intervals(const Matrix4& m) {
  const long k = balancing_exponent(m);
  MatrixOf<Interval> out;
  for (std::size_t i = 0; i < 16; ++i) {
    // Gmpq is reference-counted: write only into a fresh object, never into a shared one.
    Rational q;
    if (k >= 0) mpq_mul_2exp(q.mpq(), m.a[i].mpq(), static_cast<mp_bitcnt_t>(k));
    else mpq_div_2exp(q.mpq(), m.a[i].mpq(), static_cast<mp_bitcnt_t>(-k));
    out.a[i] = Interval(CGAL::to_interval(q));
  }
  return out;
}

/// Both matrices times the same positive integer (lcm of all denominators): f and s are scaled by
/// positive constants and keep their roots.
std::pair<MatrixOf<Integer>, MatrixOf<Integer>> to_integers(const Matrix4& p, const Matrix4& e, Integer& scale) {
  Integer l(1);
  for (const auto* m : {&p, &e})
    for (const auto& q : m->a) mpz_lcm(l.mpz(), l.mpz(), q.denominator().mpz());
  scale = l;
  MatrixOf<Integer> pi, ei;
  for (std::size_t i = 0; i < 16; ++i) {
    pi.a[i] = p.a[i].numerator() * (l / p.a[i].denominator());
    ei.a[i] = e.a[i].numerator() * (l / e.a[i].denominator());
  }
  return {pi, ei};
}

/// The signs of every decision quantity, evaluated in NT (intervals or exact integers).
template <class NT>
DecisionSigns signs_in(const Quartic<NT>& f, const Quadratic<NT>& s) {
  SturmHabicht<NT> sh(f);
  SmallnessQuantities<NT> q(f, s);
  return DecisionSigns{signs_of(f, sh), sign_of(q.vertex), sign_of(q.graeffe)};
}

/// Decision from certified signs when Disc(f) != 0 (then f and f~ are square-free). False when a
/// needed sign is uncertain, Disc(f) = 0 or the Sturm-Habicht sequence is defective.
bool decide_from_signs(const DecisionSigns& d, Classification& out) {
  auto disc = detail::certain(d.quartic.g0);
  if (!disc || *disc == 0) return false;
  auto counts = count_roots(d.quartic);
  if (!counts) return false;
  auto rho = compare_rho_with_one(d.vertex, d.graeffe);
  if (!rho) return false;
  Facts x;
  x.real = counts->real;
  x.negative = counts->negative;
  x.positive = counts->positive;
  x.nonreal = 4 - counts->real;
  out.sign_disc_f = out.sign_disc_ftilde = *disc;  // Disc(f) = Disc(f~) * (positive) when f is square-free
  out.real_roots = x.real;
  out.negative_roots = x.negative;
  out.positive_roots = x.positive;
  out.nonreal_roots = x.nonreal;
  decide(x, *rho, out);
  return true;
}

void fill_full_evidence(const Quartic<Integer>& fi, const Quadratic<Integer>& si, const Integer& scale,
                        Classification& out, const RootStructure* known) {
  out.has_full_evidence = true;
  Rational c4(1);
  for (int i = 0; i < 4; ++i) c4 *= Rational(scale);
  Rational c3 = c4 / Rational(scale);
  for (std::size_t i = 0; i < 5; ++i) out.f[i] = Rational(fi[i]) / c4;
  for (std::size_t i = 0; i < 3; ++i) out.s[i] = Rational(si[i]) / c3;
  RootStructure rs = known ? *known : exact_root_structure(fi, si);
  out.degree_ftilde = rs.degree_ftilde;
  out.roots = rs.real_roots;
  // rho = (f0/f4)(s2/s0) / u1^2 with u1 = smallest root of s(-u); rational iff Disc(s) is a square.
  const Rational k = (out.f[0] / out.f[4]) * (out.s[2] / out.s[0]);
  Integer d = si[1] * si[1] - 4 * si[2] * si[0];
  if (d >= 0 && mpz_perfect_square_p(d.mpz())) {
    Integer r;
    mpz_sqrt(r.mpz(), d.mpz());
    Rational u1(si[1] - r, 2 * si[2]);
    out.rho = k / (u1 * u1);
    out.rho_approx = CGAL::to_double(*out.rho);
  } else {
    const double s2 = CGAL::to_double(out.s[2]), s1 = CGAL::to_double(out.s[1]), s0 = CGAL::to_double(out.s[0]);
    const double u1 = (2 * s0) / (s1 + std::sqrt(s1 * s1 - 4 * s2 * s0));  // stable smaller root
    out.rho_approx = CGAL::to_double(k) / (u1 * u1);
  }
}

Classification classify_impl(const Ellipsoid& e, const Paraboloid& p, Evidence evidence, bool use_filter) {
  // The whole filter -> exact policy: each stage certifies what it can, the next one runs only if
  // a needed sign is still uncertain. All stages evaluate the same generic formulas.
  Classification out;
  bool decided = false;
  if (use_filter && e.doubles() && p.doubles()) {  // stage 1: doubles with static error bounds
    decided = decide_from_signs(static_filter_signs(*p.doubles(), *e.doubles()), out);
    if (decided) out.stage = Stage::StaticDouble;
  }
  if (use_filter && !decided) {  // stage 2: interval arithmetic
    CGAL::Protect_FPU_rounding<true> guard;  // Interval_nt<false> needs rounding towards +inf
    const MatrixOf<Interval> pi = to_intervals(p.matrix()), ei = to_intervals(e.matrix());
    decided = decide_from_signs(signs_in(characteristic_polynomial<Interval>(pi, ei), special_polynomial<Interval>(pi, ei)), out);
    if (decided) out.stage = Stage::Interval;
  }
  Integer scale;
  auto [pz, ez] = to_integers(p.matrix(), e.matrix(), scale);
  Quartic<Integer> fz;
  Quadratic<Integer> sz;
  if (!decided || evidence == Evidence::Full) {
    fz = characteristic_polynomial<Integer>(pz, ez);
    sz = special_polynomial<Integer>(pz, ez);
  }
  if (!decided && decide_from_signs(signs_in(fz, sz), out)) {  // stage 3: exact integer signs
    out.stage = Stage::ExactSigns;
    decided = true;
  }
  if (!decided) {
    // Stage 4: Disc(f) = 0 or a defective Sturm-Habicht sequence: exact factorisation.
    RootStructure rs = exact_root_structure(fz, sz);
    Facts x;
    x.real = static_cast<int>(rs.real_roots.size());
    x.negative = rs.negative();
    x.positive = rs.positive();
    x.nonreal = rs.nonreal;
    x.nonreal_multiple = rs.nonreal_multiple;
    for (const auto& r : rs.real_roots)
      if (r.tangency()) (r.sign < 0 ? x.tangent_negative : x.tangent_positive)++;
    out.sign_disc_f = rs.sign_disc_f;
    out.sign_disc_ftilde = rs.sign_disc_ftilde;
    out.real_roots = x.real;
    out.negative_roots = x.negative;
    out.positive_roots = x.positive;
    out.nonreal_roots = x.nonreal;
    auto rho = compare_rho_with_one(fz, sz);  // exact: always certain
    decide(x, *rho, out);
    out.stage = Stage::ExactRoots;
    if (evidence == Evidence::Full) fill_full_evidence(fz, sz, scale, out, &rs);
    return out;
  }
  if (evidence == Evidence::Full) fill_full_evidence(fz, sz, scale, out, nullptr);
  return out;
}

}  // namespace

Classification classify(const Ellipsoid& e, const Paraboloid& p, Evidence evidence) {
  return classify_impl(e, p, evidence, true);
}

Classification classify_exact(const Ellipsoid& e, const Paraboloid& p, Evidence evidence) {
  return classify_impl(e, p, evidence, false);
}

bool kernel_has_common_point(const Ellipsoid& e, const Paraboloid& p, const Rational& lambda0) {
  // Kernel of K = lambda0 P + E by exact Gaussian elimination over Q; then decide whether the
  // quadratic form X^T E X vanishes at a real non-zero X of the kernel (an indefinite or degenerate
  // restriction). Returns true iff such an X exists.
  Matrix4 k;
  for (std::size_t i = 0; i < 16; ++i) k.a[i] = lambda0 * p.matrix().a[i] + e.matrix().a[i];
  // Row reduce to find a basis of the null space.
  int row = 0;
  std::array<int, 4> pivot_col{-1, -1, -1, -1};
  std::array<bool, 4> is_pivot{false, false, false, false};
  for (int c = 0; c < 4 && row < 4; ++c) {
    int r = row;
    while (r < 4 && k(r, c) == 0) ++r;
    if (r == 4) continue;
    for (int j = 0; j < 4; ++j) std::swap(k(r, j), k(row, j));
    Rational inv = Rational(1) / k(row, c);
    for (int j = 0; j < 4; ++j) k(row, j) *= inv;
    for (int i = 0; i < 4; ++i) {
      if (i == row || k(i, c) == 0) continue;
      Rational factor = k(i, c);
      for (int j = 0; j < 4; ++j) k(i, j) -= factor * k(row, j);
    }
    pivot_col[static_cast<std::size_t>(row)] = c;
    is_pivot[static_cast<std::size_t>(c)] = true;
    ++row;
  }
  std::vector<std::array<Rational, 4>> basis;
  for (int free = 0; free < 4; ++free) {
    if (is_pivot[static_cast<std::size_t>(free)]) continue;
    std::array<Rational, 4> v{};
    v[static_cast<std::size_t>(free)] = Rational(1);
    for (int r = 0; r < row; ++r) v[static_cast<std::size_t>(pivot_col[static_cast<std::size_t>(r)])] = -k(r, free);
    basis.push_back(v);
  }
  if (basis.empty()) return false;
  // Gram matrix G of E restricted to the kernel; a real non-zero X with X^T E X = 0 exists iff G is
  // not definite.
  const std::size_t n = basis.size();
  std::vector<Rational> g(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      Rational acc(0);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) acc += basis[i][static_cast<std::size_t>(a)] * e.matrix()(a, b) * basis[j][static_cast<std::size_t>(b)];
      g[i * n + j] = acc;
    }
  // Definite iff all leading principal minors alternate properly (Sylvester); n <= 3 in practice.
  auto minor = [&](std::size_t m) {
    if (m == 1) return g[0];
    if (m == 2) return g[0] * g[n + 1] - g[1] * g[n];
    return g[0] * (g[n + 1] * g[2 * n + 2] - g[n + 2] * g[2 * n + 1]) - g[1] * (g[n] * g[2 * n + 2] - g[n + 2] * g[2 * n]) +
           g[2] * (g[n] * g[2 * n + 1] - g[n + 1] * g[2 * n]);
  };
  if (n > 3) return true;  // E restricted to all of R^4 is indefinite (ellipsoid has real points)
  bool pos_def = true, neg_def = true;
  for (std::size_t m = 1; m <= n; ++m) {
    Rational d = minor(m);
    if (!(d > 0)) pos_def = false;
    if (!((m % 2 == 1) ? d < 0 : d > 0)) neg_def = false;
  }
  return !(pos_def || neg_def);
}

}  // namespace relpos
