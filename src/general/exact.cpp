// The exact stage of a general pair (math.md §17) on CGAL's univariate algebraic kernel: the real
// roots of the integer quartic f and cubic D with their multiplicities, compared with each other
// exactly (an equality of roots of different polynomials is decided by their gcd, never by a
// tolerance).
#include "general/exact.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>

#include <iterator>
#include <stdexcept>
#include <utility>

#include "algebra/between.hpp"
#include "algebra/roots.hpp"

namespace relpos::detail::general {
namespace {

using AK = CGAL::Algebraic_kernel_d_1<Integer>;
using Poly = AK::Polynomial_1;
using Root = AK::Algebraic_real_1;
using Roots = std::vector<std::pair<Root, AK::Multiplicity_type>>;

std::logic_error internal_error(const std::string& what) { return std::logic_error("relpos internal error: " + what); }

template <std::size_t N>
Poly make_poly(const std::array<Integer, N>& c) {
  return Poly(c.begin(), c.end());
}

Rational evaluate(const Poly& p, const Rational& x) {
  Rational v(0);
  for (int i = p.degree(); i >= 0; --i) v = v * x + Rational(p[i]);
  return v;
}

/// The root itself when it is rational: a rational root n/k (lowest terms) of an integer polynomial
/// has k | lc, so lc * root is an integer; refine below width 1/(2 |lc|), round and test exactly.
std::optional<Rational> rational_value(const AK& ak, const Root& root, const Poly& p) {
  Integer lc = p.lcoeff();
  if (lc < 0) lc = -lc;
  const int bits = static_cast<int>(mpz_sizeinbase(lc.mpz(), 2)) + 4;
  const auto iv = ak.approximate_absolute_1_object()(root, bits);
  const Rational scaled = (iv.first + iv.second) / 2 * Rational(lc) + Rational(1, 2);
  Integer m;
  mpz_fdiv_q(m.mpz(), scaled.numerator().mpz(), scaled.denominator().mpz());
  const Rational candidate(m, lc);
  if (candidate < iv.first || candidate > iv.second || evaluate(p, candidate) != 0) return std::nullopt;
  return candidate;
}

/// The roots the decision reads: f's and D's, with the ends of the three sides.
struct Analysis {
  AK ak;
  Poly f, d;
  Roots fr, dr;
  Root zero;
  bool ellipsoid = false;

  Analysis(const IntegerPencil& p, bool ellipsoid_q) : f(make_poly(p.f)), d(make_poly(p.d)), ellipsoid(ellipsoid_q) {
    solve_on_fitting_stack(ak, f, std::back_inserter(fr));
    solve_on_fitting_stack(ak, d, std::back_inserter(dr));
    // D = det(B + t M) with M positive definite: three real roots, counted with multiplicity (the
    // generalized eigenvalues of the symmetric pencil, math.md §15).
    int real = 0;
    for (const auto& r : dr) real += static_cast<int>(r.second);
    if (real != 3) throw internal_error("D has " + std::to_string(real) + " real roots, expected 3");
    zero = ak.construct_algebraic_real_1_object()(Integer(0));
  }
  int compare(const Root& a, const Root& b) const { return static_cast<int>(ak.compare_1_object()(a, b)); }
  const Root& r1() const { return dr.front().first; }
  const Root& r3() const { return dr.back().first; }
  int m1() const { return static_cast<int>(dr.front().second); }
  int m3() const { return static_cast<int>(dr.back().second); }
  /// t_lo = max(0, r3): 0 for an ellipsoid Q (B positive definite: every root of D negative), r3
  /// otherwise (B has an eigenvalue <= 0, so r3 >= 0).
  const Root& lo() const { return ellipsoid ? zero : r3(); }
  int mult_d_lo() const { return ellipsoid ? 0 : m3(); }

  PencilFacts facts() const {
    PencilFacts out;
    out.ellipsoid = ellipsoid;
    for (const auto& [root, mult_u] : fr) {
      const int mult = static_cast<int>(mult_u);
      const bool odd = mult % 2 == 1;
      const int c_lo = compare(root, lo());
      if (c_lo > 0) {
        out.min.any = true;
        out.min.odd = out.min.odd || odd;
      } else if (c_lo == 0 && mult > mult_d_lo()) {
        out.min.endpoint = true;
      }
      const int c_hi = compare(root, r1());  // t_hi = min(0, r1) = r1: B has an eigenvalue >= 0
      if (c_hi < 0) {
        out.max.any = true;
        out.max.odd = out.max.odd || odd;
      } else if (c_hi == 0 && mult > m1()) {
        out.max.endpoint = true;
      }
      if (ellipsoid) {
        const int c3 = compare(root, r3());
        if (c3 > 0 && compare(root, zero) < 0) {
          out.inner.any = true;
          out.inner.odd = out.inner.odd || odd;
        } else if (c3 == 0 && mult > m3()) {
          out.inner.endpoint = true;
        }
      }
    }
    return out;
  }

  /// Disjoint isolating intervals of a and b (a < b), refined together.
  std::pair<Rational, Rational> separated(const Root& a, const Root& b) const {
    for (int bits = 8;; bits *= 2) {
      const auto ia = ak.approximate_absolute_1_object()(a, bits);
      const auto ib = ak.approximate_absolute_1_object()(b, bits);
      if (ia.second < ib.first) return {ia.second, ib.first};
      if (bits > (1 << 20)) throw internal_error("roots not separated");
    }
  }

  /// A short rational in (a, b) where f > 0: the pieces of (a, b) cut by f's roots are tried in turn,
  /// the sign of f on each read exactly at a short rational inside it.
  std::optional<Rational> definite(const Root& a, const Root& b) const {
    std::vector<Root> cuts{a};
    for (const auto& r : fr)
      if (compare(r.first, a) > 0 && compare(r.first, b) < 0) cuts.push_back(r.first);
    cuts.push_back(b);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const auto [x, y] = separated(cuts[i], cuts[i + 1]);
      const Rational s = detail::rational_inside(x, y, detail::Shortest::Bits);
      if (evaluate(f, s) > 0) return s;
    }
    return std::nullopt;
  }

  /// The same on (-oo, b): below the first root of f the sign is that of f(-oo) < 0, so the pieces
  /// start at the first root of f below b.
  std::optional<Rational> definite_below(const Root& b) const {
    std::vector<Root> cuts;
    for (const auto& r : fr)
      if (compare(r.first, b) < 0) cuts.push_back(r.first);
    if (cuts.empty()) return std::nullopt;
    cuts.push_back(b);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const auto [x, y] = separated(cuts[i], cuts[i + 1]);
      const Rational s = detail::rational_inside(x, y, detail::Shortest::Bits);
      if (evaluate(f, s) > 0) return s;
    }
    return std::nullopt;
  }

  /// (lo, oo) likewise: beyond the last root of f the sign is f(+oo) < 0.
  std::optional<Rational> definite_above(const Root& a) const {
    std::vector<Root> cuts{a};
    for (const auto& r : fr)
      if (compare(r.first, a) > 0) cuts.push_back(r.first);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const auto [x, y] = separated(cuts[i], cuts[i + 1]);
      const Rational s = detail::rational_inside(x, y, detail::Shortest::Bits);
      if (evaluate(f, s) > 0) return s;
    }
    return std::nullopt;
  }

  /// The multiple root of f strictly inside (a, b) (either end may be absent: -oo, +oo).
  std::optional<Rational> even_root(const Root* a, const Root* b) const {
    for (const auto& r : fr) {
      if (a && compare(r.first, *a) <= 0) continue;
      if (b && compare(r.first, *b) >= 0) continue;
      if (r.second >= 2) return rational_value(ak, r.first, f);
    }
    return std::nullopt;
  }

  /// The root `end` of D as a + b sqrt(n): rational, or a root of D's quadratic factor when D has a
  /// rational root (a cubic irrational cannot be the end of a tangency, math.md §18).
  std::pair<QuadraticNumber, Integer> end_value(const Root& end) const {
    if (const auto q = rational_value(ak, end, d)) return {QuadraticNumber{*q, Rational(0)}, Integer(0)};
    for (const auto& r : dr) {
      const auto q = rational_value(ak, r.first, d);
      if (!q) continue;
      // D / (t - q) = c2 t^2 + c1 t + c0 by synthetic division (exact: q is a root); its roots are
      // mid +- sqrt(disc) / (2 |c2|), and sqrt(disc) = sqrt(num(disc) den(disc)) / den(disc).
      const Rational c2(d[3]), c1 = Rational(d[2]) + *q * c2, c0 = Rational(d[1]) + *q * c1;
      const Rational disc = c1 * c1 - 4 * c2 * c0, mid = -c1 / (2 * c2);
      const Integer n = disc.numerator() * disc.denominator();
      const Rational scale = Rational(1) / CGAL::abs(2 * c2 * Rational(disc.denominator()));
      for (int bits = 16; bits <= (1 << 20); bits *= 2) {  // which side of mid the end lies on
        const auto iv = ak.approximate_absolute_1_object()(end, bits);
        if (iv.second < mid) return {QuadraticNumber{mid, -scale}, n};
        if (iv.first > mid) return {QuadraticNumber{mid, scale}, n};
      }
    }
    throw internal_error("the end of a tangency is not a root of degree <= 2 of D");
  }
};

/// The distinct real roots of f and D, merged in increasing order, each with its multiplicities and
/// an isolating interval, the intervals refined until they are disjoint.
std::vector<PencilRoot> merged_roots(const Analysis& a) {
  std::vector<std::pair<Root, PencilRoot>> merged;
  for (const auto& [root, mult] : a.dr) {
    PencilRoot r;
    r.multiplicity_d = static_cast<int>(mult);
    r.exact = rational_value(a.ak, root, a.d);
    merged.emplace_back(root, r);
  }
  for (const auto& [root, mult] : a.fr) {
    bool found = false;
    for (auto& m : merged)
      if (a.compare(m.first, root) == 0) {
        m.second.multiplicity_f = static_cast<int>(mult);
        found = true;
      }
    if (found) continue;
    PencilRoot r;
    r.multiplicity_f = static_cast<int>(mult);
    r.exact = rational_value(a.ak, root, a.f);
    auto at = merged.begin();
    while (at != merged.end() && a.compare(at->first, root) < 0) ++at;
    merged.insert(at, {root, r});
  }
  for (int bits = 32;; bits *= 2) {
    for (auto& [root, r] : merged) {
      const auto iv = a.ak.approximate_absolute_1_object()(root, bits);
      r.lower = r.exact ? *r.exact : iv.first;
      r.upper = r.exact ? *r.exact : iv.second;
    }
    bool disjoint = true;
    for (std::size_t i = 1; i < merged.size(); ++i)
      if (!(merged[i - 1].second.upper < merged[i].second.lower)) disjoint = false;
    if (disjoint) break;
    if (bits > (1 << 20)) throw internal_error("roots of f and D not separated");
  }
  std::vector<PencilRoot> out;
  for (auto& m : merged) out.push_back(m.second);
  return out;
}

/// The certificate's numbers for the rule that decided (math.md §18).
void certificate_numbers(const Analysis& a, ExactEvidence& ev) {
  switch (ev.verdict.rule) {
    case QuadricRule::OddRootAboveLo:
      ev.definite = a.definite_above(a.lo());
      break;
    case QuadricRule::OddRootBelowHi:
      ev.definite = a.definite_below(a.r1());
      break;
    case QuadricRule::OddRootInner:
      ev.definite = a.definite(a.r3(), a.zero);
      break;
    case QuadricRule::EvenRootAboveLo:
      ev.tangent = a.even_root(&a.lo(), nullptr);
      break;
    case QuadricRule::EvenRootBelowHi:
      ev.tangent = a.even_root(nullptr, &a.r1());
      break;
    case QuadricRule::EvenRootInner:
      ev.tangent = a.even_root(&a.r3(), &a.zero);
      break;
    case QuadricRule::EndpointLo:
    case QuadricRule::EndpointHi:
    case QuadricRule::EndpointInner: {
      const Root& end = ev.verdict.rule == QuadricRule::EndpointHi ? a.r1() : a.r3();
      auto [x, n] = a.end_value(end);
      ev.endpoint = x;
      ev.d = n;
      break;
    }
    case QuadricRule::Equal:
    case QuadricRule::NoRoot:
      break;
  }
}

}  // namespace

PencilFacts exact_facts(const IntegerPencil& p, bool ellipsoid) { return Analysis(p, ellipsoid).facts(); }

ExactEvidence exact_evidence(const IntegerPencil& p, bool ellipsoid) {
  const Analysis a(p, ellipsoid);
  ExactEvidence ev;
  ev.facts = a.facts();
  ev.verdict = decide(ev.facts);
  ev.verdict.stage = QuadricStage::Exact;
  ev.roots = merged_roots(a);
  certificate_numbers(a, ev);
  return ev;
}

}  // namespace relpos::detail::general
