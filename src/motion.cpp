#include "relpos/motion.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>

#include <stdexcept>
#include <utility>

#include "relpos/error.hpp"
#include "relpos/pencil.hpp"
#include "relpos/roots.hpp"
#include "relpos/smallness.hpp"
#include "relpos/sturm.hpp"

namespace relpos {
namespace {

using PolyZ = CGAL::Polynomial<Integer>;  // polynomials in t
using BiZ = CGAL::Polynomial<PolyZ>;      // polynomials in l over Z[t] (l is the outer variable)
using AK = CGAL::Algebraic_kernel_d_1<Integer>;
using Alg = AK::Algebraic_real_1;

/// Matrix view for the generic pencil code (pencil.hpp) with entries in Z[t].
struct MatZ {
  std::array<PolyZ, 16> a;
  const PolyZ& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// lcm of l and d, into a fresh object (Gmpz shares representations).
Integer lcm(const Integer& l, const Integer& d) {
  Integer r;
  mpz_lcm(r.mpz(), l.mpz(), d.mpz());
  return r;
}

/// The matrix times the lcm of all coefficient denominators: a positive multiple, same roots.
MatZ integer_matrix(const TimeMatrix4& e) {
  Integer l(1);
  for (const auto& p : e)
    for (const auto& c : p) l = lcm(l, c.denominator());
  MatZ out;
  for (std::size_t i = 0; i < 16; ++i) {
    std::vector<Integer> c;
    for (const auto& x : e[i]) c.push_back(x.numerator() * (l / x.denominator()));
    out.a[i] = c.empty() ? PolyZ(Integer(0)) : PolyZ(c.begin(), c.end());
  }
  return out;
}

MatZ integer_matrix(const Matrix4& p) {
  Integer l(1);
  for (const auto& c : p.a) l = lcm(l, c.denominator());
  MatZ out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = PolyZ(Integer(p.a[i].numerator() * (l / p.a[i].denominator())));
  return out;
}

/// The pencil of the moving pair with coefficients in Z[t] and the polynomials in t that decide
/// (math.md section 7). f = det(l P + E(t)) and s = det(l A + M(t)) up to positive factors.
struct MovingPencil {
  Quartic<PolyZ> f;
  Quadratic<PolyZ> s;
  // Sturm-Habicht sequence of f in l (sturm.hpp): StHa_j = (non-zero constant) * g_j, so the
  // principal coefficients g2[0], g1[0], disc are the principal subresultant coefficients of f and
  // df/dl up to non-zero constants, and StHa_1 = g1[0] l + g1[1], StHa_2 = g2[0] l^2 + g2[1] l + g2[2].
  PolyZ g2[3], g1[2], disc;
  PolyZ vertex, graeffe;  // smallness quantities (smallness.hpp), polynomials in t
  bool disc_zero = false;
  PolyZ merge;  // real zeros contain every t where two roots of f meet (Disc f, or Disc of sqf(f))
  std::vector<std::pair<PolyZ, unsigned>> events;  // every candidate instant, with its cause

  MovingPencil(const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p) {
    const MatZ pz = integer_matrix(p.matrix());
    const MatZ ez = integer_matrix(moving_ellipsoid_matrix(e0, m));
    f = characteristic_polynomial<PolyZ>(pz, ez);
    s = special_polynomial<PolyZ>(pz, ez);
    SturmHabicht<PolyZ> sh(f);
    for (int i = 0; i < 3; ++i) g2[i] = sh.g2[i];
    for (int i = 0; i < 2; ++i) g1[i] = sh.g1[i];
    disc = sh.discriminant();
    SmallnessQuantities<PolyZ> q(f, s);
    vertex = q.vertex;
    graeffe = q.graeffe;
    disc_zero = CGAL::is_zero(disc);
    if (!disc_zero) {
      // Disc f(., t) != 0: f square-free, its roots distinct and continuous, none crosses 0 (f(0) =
      // det E < 0) and f4 = det P is constant: the root pattern, hence the position (f~ = f has no
      // multiple root), can only change where Disc f = 0.
      merge = disc;
      events.emplace_back(disc, kCauseDiscriminant);
    } else {
      // Disc f = 0 for every t: f has a multiple factor over Q(t). Work with r = f / gcd(f, df/dl)
      // (the square-free part, whose lc is constant because f4 is): away from the zeros of Disc r,
      // Res(r / gcd(r, s), s) and Disc s, the roots of f keep their multiplicities in f and in s.
      const BiZ bf(f.begin(), f.end()), bs(s.begin(), s.end());
      const BiZ r = CGAL::integral_division_up_to_constant_factor(
          bf, CGAL::gcd_up_to_constant_factor(bf, CGAL::differentiate(bf)));
      merge = r.degree() >= 2 ? PolyZ(CGAL::resultant(r, CGAL::differentiate(r))) : PolyZ(Integer(1));
      events.emplace_back(merge, kCauseDiscriminant);
      const BiZ rhat = CGAL::integral_division_up_to_constant_factor(r, CGAL::gcd_up_to_constant_factor(r, bs));
      if (rhat.degree() >= 1) events.emplace_back(PolyZ(CGAL::resultant(rhat, bs)), kCauseSpecialRoot);
      const PolyZ ds = CGAL::resultant(bs, CGAL::differentiate(bs));
      if (!CGAL::is_zero(ds)) events.emplace_back(ds, kCauseSpecialRoot);
    }
    // For a pure translation s and det E are constant, so both quantities are constants: rho does
    // not change (math.md section 7). A rotation can change it.
    events.emplace_back(vertex, kCauseSmallness);
    events.emplace_back(graeffe, kCauseSmallness);
  }
};

int sgn_at(const AK& ak, const PolyZ& p, const Alg& a) { return static_cast<int>(ak.sign_at_1_object()(p, a)); }

/// The rational value of an algebraic real when it is rational. A rational root m/q (lowest terms)
/// of an integer polynomial has q | lc, so x * lc is an integer: approximate x within 1/(16 lc),
/// take the nearest candidate k/lc and test it exactly (as in roots.cpp).
std::optional<Rational> rational_value(const AK& ak, const Alg& a) {
  if (a.low() == a.high()) return a.low();
  const PolyZ p = a.polynomial();
  if (p.degree() == 1) return Rational(-p[0], p[1]);
  const Integer lc = p.lcoeff() < 0 ? Integer(-p.lcoeff()) : p.lcoeff();
  const int bits = static_cast<int>(mpz_sizeinbase(lc.mpz(), 2)) + 4;
  const auto iv = ak.approximate_absolute_1_object()(a, bits);
  const Rational shifted = (iv.first + iv.second) / 2 * Rational(lc) + Rational(1, 2);
  Integer k;
  mpz_fdiv_q(k.mpz(), shifted.numerator().mpz(), shifted.denominator().mpz());
  const Rational candidate(k, lc);
  if (candidate < iv.first || candidate > iv.second) return std::nullopt;
  if (p.sign_at(candidate) != CGAL::ZERO) return std::nullopt;
  return candidate;
}

/// The public exact form of an instant: rational, or square-free polynomial + isolating interval
/// whose ends show a strict sign change.
AlgebraicReal to_public(const AK& ak, const Alg& a) {
  if (auto q = rational_value(ak, a)) return AlgebraicReal::rational(*q);
  const PolyZ p = a.polynomial();
  for (int guard = 0; guard < 10000; ++guard) {
    const CGAL::Sign sl = p.sign_at(a.low()), sh = p.sign_at(a.high());
    if (sl != CGAL::ZERO && sh != CGAL::ZERO && sl != sh) {
      std::vector<Integer> c;
      for (int i = 0; i <= p.degree(); ++i) c.push_back(p[i]);
      return AlgebraicReal::root(std::move(c), a.low(), a.high());
    }
    a.refine();
  }
  throw std::logic_error("motion: could not isolate an irrational instant with a sign change");
}

Integer floor_of(const Rational& q) {
  Integer r;
  mpz_fdiv_q(r.mpz(), q.numerator().mpz(), q.denominator().mpz());
  return r;
}

/// The simplest rational (smallest denominator, then numerator) in the open interval (x, y), x < y;
/// y empty means +infinity. Continued fractions (Stern-Brocot descent).
Rational simplest_between(const Rational& x, const std::optional<Rational>& y) {
  if (y && x < 0 && *y > 0) return Rational(0);
  if (y && *y <= 0) return -simplest_between(-*y, Rational(-x));
  const Integer n = floor_of(x);  // x >= 0 here
  const Rational next(n + 1);
  if (!y || next < *y) return next;
  // (x, y) lies in [n, n + 1]: recurse on the reciprocals of the fractional parts.
  const Rational lo = Rational(1) / (*y - Rational(n));
  std::optional<Rational> hi;
  if (x > Rational(n)) hi = Rational(1) / (x - Rational(n));
  return Rational(n) + Rational(1) / simplest_between(lo, hi);
}

/// A simple rational strictly between two algebraic reals a < b (their isolating intervals are
/// refined until disjoint). CGAL's Bound_between needs a big-float interval type; this does not.
Rational rational_between(const Alg& a, const Alg& b) {
  while (!(a.high() < b.low())) {
    if (a.low() != a.high()) a.refine();
    if (b.low() != b.high()) b.refine();
  }
  // a <= a.high() < b.low() <= b: any number strictly between the two ends will do.
  return simplest_between(a.high(), Rational(b.low()));
}

/// A candidate instant (a real zero of an event polynomial) with its causes.
struct Candidate {
  Alg t;
  unsigned causes = 0;
};

/// Merge the real zeros of p in [lo, hi] into the sorted list `out` (exact comparisons; a zero
/// shared by several polynomials is kept once with all its causes).
void add_zeros(const AK& ak, const PolyZ& p, unsigned cause, const Rational& lo, const Rational& hi,
               std::vector<Candidate>& out) {
  if (CGAL::is_zero(p) || p.degree() < 1) return;
  const PolyZ sq = ak.make_square_free_1_object()(p);
  std::vector<Alg> zeros;
  ak.solve_1_object()(sq, true, lo, hi, std::back_inserter(zeros));
  const auto cmp = ak.compare_1_object();
  for (const Alg& z : zeros) {
    std::size_t i = 0;
    while (i < out.size() && cmp(out[i].t, z) == CGAL::SMALLER) ++i;
    if (i < out.size() && cmp(out[i].t, z) == CGAL::EQUAL)
      out[i].causes |= cause;
    else
      out.insert(out.begin() + static_cast<std::ptrdiff_t>(i), Candidate{z, cause});
  }
}

int total_degree(const std::vector<std::pair<PolyZ, unsigned>>& polys) {
  int d = 0;
  for (const auto& [p, cause] : polys)
    if (!CGAL::is_zero(p) && p.degree() > 0) d += p.degree();
  return d;
}

/// The classification table of math.md sections 3 and 6 applied to root facts (the same rules as
/// classify(); tests compare the two at rational instants).
Position position_from(const RootFacts& x, int rho_vs_one) {
  const bool small = rho_vs_one <= 0;
  const int tangencies = x.tangent_negative + x.tangent_positive;
  if (x.nonreal_multiple > 0) return Position::Unclassified;  // a finding
  // Any size (section 6): a positive multiple root of f~ is outer tangency, two distinct positive
  // roots separation.
  if (tangencies == 1 && x.tangent_positive == 1) return x.nonreal ? Position::Unclassified : Position::TE;
  if (tangencies == 0 && x.nonreal == 0 && x.positive == 2) return Position::E;
  if (!small) return Position::Unclassified;
  if (tangencies == 0 && x.nonreal == 2) return x.positive ? Position::Unclassified : Position::C;
  if (tangencies == 1 && x.tangent_negative == 1 && x.nonreal == 0 && x.positive == 0) return Position::TI;
  if (tangencies == 0 && x.nonreal == 0 && x.positive == 0) return Position::I;
  return Position::Unclassified;
}

/// Root facts of f(., t*) relative to s(., t*) at an instant t* (rational or algebraic), from signs
/// of polynomials in t at t* (math.md section 7).
struct InstantFacts {
  RootFacts roots;
  int j = 0;           ///< degree of gcd(f, df/dl) at t*
  int rho_vs_one = 0;  ///< sign of rho(t*) - 1
  std::string how;
};

void count_root(RootFacts& x, int sign) { ++(sign < 0 ? x.negative : x.positive); }
void count_tangency(RootFacts& x, int sign) { ++(sign < 0 ? x.tangent_negative : x.tangent_positive); }
const char* sign_word(int s) { return s < 0 ? "negative" : "positive"; }

[[noreturn]] void impossible(const std::string& what) {
  throw std::logic_error("motion: impossible root configuration at an instant (" + what + ")");
}

/// nullopt when f(., t*) is square-free and no neighbour is given (its root counts are then those
/// of the neighbouring interval: no root merges at t*).
std::optional<InstantFacts> facts_at(const MovingPencil& mp, const AK& ak, const Alg& a,
                                     const Classification* neighbour) {
  InstantFacts out;
  RootFacts& x = out.roots;
  auto at = [&](const PolyZ& p) { return sgn_at(ak, p, a); };
  out.rho_vs_one = *compare_rho_with_one(USign(static_cast<CGAL::Sign>(at(mp.vertex))),
                                         USign(static_cast<CGAL::Sign>(at(mp.graeffe))));
  const PolyZ &f0 = mp.f[0], &f3 = mp.f[3], &f4 = mp.f[4];
  const PolyZ &s0 = mp.s[0], &s1 = mp.s[1], &s2 = mp.s[2];
  // s(u/v) * v^2 and s'(u/v) * v: is the rational-in-t root u/v a root of s, and a double one?
  auto s_at = [&](const PolyZ& u, const PolyZ& v) { return s2 * u * u + s1 * u * v + s0 * v * v; };
  auto ds_at = [&](const PolyZ& u, const PolyZ& v) { return PolyZ(Integer(2)) * s2 * u + s1 * v; };

  // j = deg gcd(f, f') at t* = the first non-vanishing principal subresultant coefficient
  // (specialisation commutes with subresultants because f4 = det P is a non-zero constant).
  if (at(mp.disc) != 0) {
    out.j = 0;
    if (!neighbour) return std::nullopt;
    x.real = neighbour->real_roots;
    x.negative = neighbour->negative_roots;
    x.positive = neighbour->positive_roots;
    x.nonreal = neighbour->nonreal_roots;
    x.sign_disc_f = x.sign_disc_ftilde = neighbour->sign_disc_f;
    out.how = "f is square-free at t*: root counts of the neighbouring interval (no root merges at t*)";
    return out;
  }
  x.sign_disc_f = 0;
  if (at(mp.g1[0]) != 0) {
    // One double root l* = -S1_0 / S1_1 (S1 = StHa_1); f = f4 (l - l*)^2 g with g = f4 l^2 + g1 l + g0,
    // g1 = f3 + 2 f4 l*, g0 = f0 / l*^2 (compare coefficients of l^3 and l^0).
    out.j = 1;
    const PolyZ u = -mp.g1[1], v = mp.g1[0];
    const int su = at(u), sv = at(v);
    if (su == 0) impossible("double root at l = 0");
    const int lam = su * sv;
    const bool on_s = at(s_at(u, v)) == 0;
    const PolyZ w = v * f3 + PolyZ(Integer(2)) * f4 * u;                           // v * g1
    const PolyZ dg = w * w * u * u - PolyZ(Integer(4)) * f4 * f0 * v * v * v * v;  // Disc g * u^2 v^2
    const int sg = at(dg);
    if (sg == 0) impossible("j = 1 but g has a double root");
    x.real = 1;
    count_root(x, lam);
    if (sg > 0) {
      // g0 / g2 = f0 / (f4 l*^2) > 0: both roots of g have the sign of their sum -g1/g2, i.e. of g1.
      const int sr = at(w) * sv;
      x.real += 2;
      count_root(x, sr);
      count_root(x, sr);
    } else {
      x.nonreal = 2;
    }
    if (!on_s) count_tangency(x, lam);
    out.how = std::string("Disc f = 0: one double root l* = -S1_0/S1_1 of f, ") + sign_word(lam) +
              (on_s ? ", also a root of s (special root, not a tangency)" : ", not a root of s: a tangency");
    x.sign_disc_ftilde = on_s ? (sg > 0 ? 1 : -1) : 0;
    return out;
  }
  if (at(mp.g2[0]) != 0) {
    out.j = 2;
    const PolyZ &A = mp.g2[0], &B = mp.g2[1], &C = mp.g2[2];  // gcd(f, f') = A l^2 + B l + C at t*
    const int sd = at(B * B - PolyZ(Integer(4)) * A * C);
    if (sd == 0) {
      // Triple root l* = -B/(2A); f = f4 (l - l*)^3 (l - mu), mu = -f3/f4 - 3 l*.
      const PolyZ u = -B, v = PolyZ(Integer(2)) * A;
      const int lam = at(u) * at(v);
      const int mu = at(-f3 * v - PolyZ(Integer(3)) * f4 * u) * at(f4) * at(v);
      if (lam == 0 || mu == 0) impossible("triple root or its cofactor at l = 0");
      const int ms = at(s_at(u, v)) != 0 ? 0 : (at(ds_at(u, v)) != 0 ? 1 : 2);
      x.real = 2;
      count_root(x, lam);
      count_root(x, mu);
      if (3 - ms >= 2) count_tangency(x, lam);
      out.how = std::string("Disc f = 0: a triple root of f, ") + sign_word(lam) + ", of multiplicity " +
                std::to_string(ms) + " in s" + (3 - ms >= 2 ? ": a tangency" : ": not a tangency");
      return out;
    }
    if (sd < 0) {
      x.nonreal = 4;
      x.nonreal_multiple = 4;
      out.how = "Disc f = 0: f is the square of a quadratic with non-real roots (outside the table)";
      return out;
    }
    // Two real double roots a != b, the roots of A l^2 + B l + C.
    const int sp = at(C) * at(A), ss = -at(B) * at(A);
    if (sp == 0) impossible("double root at l = 0");
    int sa, sb;
    if (sp > 0) {
      if (ss == 0) impossible("two double roots of the same sign with sum 0");
      sa = sb = ss;
    } else {
      sa = -1;
      sb = 1;
    }
    x.real = 2;
    count_root(x, sa);
    count_root(x, sb);
    // Res(A l^2 + B l + C, s) = (A s0 - C s2)^2 - (A s1 - B s2)(B s0 - C s1).
    const PolyZ p1 = A * s0 - C * s2, p2 = A * s1 - B * s2, p3 = B * s0 - C * s1;
    if (at(p1 * p1 - p2 * p3) != 0) {
      count_tangency(x, sa);
      count_tangency(x, sb);
      out.how = "Disc f = 0: two real double roots of f, neither a root of s: two tangencies (outside the table)";
    } else if (at(p2) == 0 && at(p1) == 0) {
      out.how = "Disc f = 0: two real double roots of f, both roots of s (special roots, no tangency)";
    } else {
      // Exactly one is a root of s, hence negative; the other is the tangency.
      if (sa > 0 && sb > 0) impossible("a positive root of s");
      count_tangency(x, sa == sb ? -1 : 1);
      out.how = std::string("Disc f = 0: two real double roots of f, one a root of s; the other, ") +
                sign_word(sa == sb ? -1 : 1) + ", is a tangency";
    }
    return out;
  }
  // gcd(f, f') = f' at t*: f = f4 (l - l*)^4 with l* = -f3 / (4 f4); mult_s <= 2 so always a tangency.
  out.j = 3;
  const int lam = -at(f3) * at(f4);
  if (lam == 0) impossible("quadruple root at l = 0");
  x.real = 1;
  count_root(x, lam);
  count_tangency(x, lam);
  out.how = std::string("Disc f = 0: a quadruple root of f, ") + sign_word(lam) + ": a tangency";
  return out;
}

/// Positions that a limit of configurations in position p can have (the contact set is closed,
/// E, I and C are open conditions; an ellipsoid cannot lie both inside-or-on and outside-or-on).
unsigned closure(Position p) {
  auto bit = [](Position q) { return 1u << static_cast<unsigned>(q); };
  switch (p) {
    case Position::E:
      return bit(Position::E) | bit(Position::TE);
    case Position::I:
      return bit(Position::I) | bit(Position::TI);
    case Position::C:
      return bit(Position::C) | bit(Position::TI) | bit(Position::TE);
    case Position::TE:
      return bit(Position::TE);
    case Position::TI:
      return bit(Position::TI);
    case Position::Unclassified:
      break;
  }
  return ~0u;
}

Classification classify_at(const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p, const Rational& t) {
  return classify(placed_ellipsoid(e0, m, t), p, Evidence::Minimal);
}

std::string classify_how(const Classification& c) {
  return "classified exactly at the rational instant (" + to_string(c.stage) + ")";
}

}  // namespace

std::vector<std::string> cause_names(unsigned causes) {
  std::vector<std::string> out;
  if (causes & kCauseStart) out.emplace_back("start");
  if (causes & kCauseEnd) out.emplace_back("end");
  if (causes & kCauseDiscriminant) out.emplace_back("discriminant");
  if (causes & kCauseSpecialRoot) out.emplace_back("special-root");
  if (causes & kCauseSmallness) out.emplace_back("smallness");
  return out;
}

FirstContact first_contact(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                           const Rational& t1) {
  validate_motion(motion, t0, t1);
  FirstContact out;
  const Classification c0 = classify_at(e0, motion, p, t0);
  out.start_position = c0.position;
  if (c0.position != Position::E) {
    out.kind = FirstContact::Kind::NotExteriorAtStart;
    out.time = AlgebraicReal::rational(t0);
    out.position = c0.position;
    out.how = classify_how(c0);
    return out;
  }
  // Separation (two distinct positive roots) is open and is decided for any size; it can only end
  // where two roots of f meet, i.e. at a real zero of `merge` (math.md section 7).
  const MovingPencil mp(e0, motion, p);
  AK ak;
  std::vector<Candidate> zeros;
  add_zeros(ak, mp.merge, kCauseDiscriminant, t0, t1, zeros);
  const auto cmp = ak.compare_1_object();
  const Alg a0(t0);
  for (const Candidate& z : zeros) {
    if (cmp(z.t, a0) == CGAL::EQUAL) continue;  // t0 itself: classified above
    Position pos;
    std::string how;
    if (auto q = rational_value(ak, z.t)) {
      const Classification c = classify_at(e0, motion, p, *q);
      pos = c.position;
      how = classify_how(c);
    } else {
      auto facts = facts_at(mp, ak, z.t, nullptr);
      if (!facts) continue;  // no root merges: still E
      pos = position_from(facts->roots, facts->rho_vs_one);
      how = facts->how;
    }
    if (pos != Position::E) {
      out.kind = FirstContact::Kind::Contact;
      out.time = to_public(ak, z.t);
      out.position = pos;
      out.how = how;
      return out;
    }
  }
  out.kind = FirstContact::Kind::None;
  return out;
}

Timeline timeline(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                  const Rational& t1) {
  validate_motion(motion, t0, t1);
  Timeline out;
  out.t0 = t0;
  out.t1 = t1;
  const MovingPencil mp(e0, motion, p);
  out.discriminant_identically_zero = mp.disc_zero;
  out.event_degree = total_degree(mp.events);
  AK ak;

  // Candidate instants in [t0, t1], with t0 and t1 themselves.
  std::vector<Candidate> cands{{Alg(t0), kCauseStart}};
  if (t1 > t0)
    cands.push_back({Alg(t1), kCauseEnd});
  else
    cands.front().causes |= kCauseEnd;
  for (const auto& [poly, cause] : mp.events) add_zeros(ak, poly, cause, t0, t1, cands);

  // Open intervals: classified exactly at a rational sample strictly inside. The classifications
  // are kept: their root counts serve the square-free instants.
  std::vector<Classification> interval_class;
  for (std::size_t i = 0; i + 1 < cands.size(); ++i) {
    MotionInterval iv;
    iv.sample = rational_between(cands[i].t, cands[i + 1].t);
    interval_class.push_back(classify_at(e0, motion, p, iv.sample));
    iv.position = interval_class.back().position;
    iv.small = interval_class.back().small;
    out.intervals.push_back(std::move(iv));
  }

  for (std::size_t i = 0; i < cands.size(); ++i) {
    const Candidate& z = cands[i];
    MotionInstant inst{to_public(ak, z.t), Position::Unclassified, false, z.causes, ""};
    if (inst.time.is_rational()) {
      const Classification c = classify_at(e0, motion, p, *inst.time.exact());
      inst.position = c.position;
      inst.small = c.small;
      inst.how = classify_how(c);
    } else {
      // Irrational instants are interior (t0, t1 are rational), so interval i-1 exists.
      auto facts = facts_at(mp, ak, z.t, &interval_class[i - 1]);
      inst.position = position_from(facts->roots, facts->rho_vs_one);
      inst.small = facts->rho_vs_one <= 0;
      inst.how = "at the algebraic instant: " + facts->how;
    }
    // Cross-check with the neighbours (closure of positions, see `closure`): a violation would mean
    // a defect or a gap in the theory, so the instant is reported unclassified, never guessed.
    if (inst.position != Position::Unclassified) {
      const unsigned bit = 1u << static_cast<unsigned>(inst.position);
      bool ok = true;
      if (i > 0) ok = ok && (closure(out.intervals[i - 1].position) & bit);
      if (i + 1 < cands.size()) ok = ok && (closure(out.intervals[i].position) & bit);
      if (!ok) {
        inst.how += " [inconsistent with the neighbouring intervals: reported unclassified]";
        inst.position = Position::Unclassified;
      }
    }
    out.instants.push_back(std::move(inst));
  }
  return out;
}

std::optional<Position> position_by_subresultants(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p,
                                                  const Rational& t) {
  const MovingPencil mp(e0, motion, p);
  AK ak;
  auto facts = facts_at(mp, ak, Alg(t), nullptr);
  if (!facts) return std::nullopt;
  return position_from(facts->roots, facts->rho_vs_one);
}

std::vector<PositionChange> Timeline::changes() const {
  std::vector<PositionChange> out;
  for (std::size_t i = 0; i < instants.size(); ++i) {
    PositionChange c{instants[i].time, std::nullopt, instants[i].position, std::nullopt};
    if (i > 0) c.before = intervals[i - 1].position;
    if (i < intervals.size()) c.after = intervals[i].position;
    const bool changed = (c.before && *c.before != c.at) || (c.after && *c.after != c.at);
    if (changed) out.push_back(std::move(c));
  }
  return out;
}

std::vector<PositionSpan> Timeline::spans() const {
  std::vector<PositionSpan> out;
  auto extend = [&](const AlgebraicReal& from, bool from_closed, const AlgebraicReal& to, bool to_closed,
                    Position pos) {
    if (!out.empty() && out.back().position == pos) {
      out.back().to = to;
      out.back().to_closed = to_closed;
    } else {
      out.push_back(PositionSpan{from, to, from_closed, to_closed, pos});
    }
  };
  for (std::size_t i = 0; i < instants.size(); ++i) {
    extend(instants[i].time, true, instants[i].time, true, instants[i].position);
    if (i < intervals.size()) extend(instants[i].time, false, instants[i + 1].time, false, intervals[i].position);
  }
  return out;
}

Position Timeline::position_at(const Rational& t) const {
  if (t < t0 || t > t1) throw InputError("time " + to_string(t) + " is outside [t0, t1]");
  for (std::size_t i = 0; i < instants.size(); ++i) {
    const int c = instants[i].time.compare(t);
    if (c == 0) return instants[i].position;
    if (c > 0) return intervals[i - 1].position;  // i > 0 because instants[0] = t0 <= t
  }
  return instants.back().position;
}

}  // namespace relpos
