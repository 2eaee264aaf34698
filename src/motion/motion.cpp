#include "relpos/motion.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>
#include <mpfi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "algebra/between.hpp"
#include "algebra/forms.hpp"
#include "algebra/pencil.hpp"
#include "algebra/roots.hpp"
#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "decide/unchecked.hpp"
#include "motion/instant_position.hpp"
#include "motion/polynomial_motion.hpp"
#include "motion/subresultant_position.hpp"
#include "relpos/error.hpp"

namespace relpos {
namespace {

using PolyZ = CGAL::Polynomial<Integer>;  // polynomials in t
using BiZ = CGAL::Polynomial<PolyZ>;      // polynomials in l over Z[t] (l is the outer variable)
using AK = CGAL::Algebraic_kernel_d_1<Integer>;
using Alg = AK::Algebraic_real_1;

/// Matrix view for the generic pencil code (pencil.hpp) with entries in Z[t].
using MatZ = forms::MatrixOf<PolyZ>;

/// gcd of the integer coefficients of several polynomials in t (0 for no non-zero coefficient).
template <class Range>
Integer integer_content(const Range& polys) {
  Integer g(0);
  for (const PolyZ& p : polys) {
    if (CGAL::is_zero(p)) continue;
    for (int i = 0; i <= p.degree(); ++i) {
      Integer r;
      mpz_gcd(r.mpz(), g.mpz(), p[i].mpz());
      g = r;
    }
  }
  return g;
}

/// p / c for a positive integer c dividing every coefficient (a positive multiple: signs, roots
/// and ratios of polynomials divided by the same c are kept).
PolyZ divide_exactly(const PolyZ& p, const Integer& c) {
  if (CGAL::is_zero(p) || c == 1) return p;
  std::vector<Integer> q;
  for (int i = 0; i <= p.degree(); ++i) {
    Integer r;
    mpz_divexact(r.mpz(), p[i].mpz(), c.mpz());
    q.push_back(r);
  }
  return PolyZ(q.begin(), q.end());
}

template <class Array>
void make_primitive(Array& polys) {
  const Integer g = integer_content(polys);
  if (g > 1)
    for (auto& p : polys) p = divide_exactly(p, g);
}

/// The matrix times the lcm of all coefficient denominators, divided by the integer content: a
/// positive multiple, same roots.
MatZ integer_matrix(const TimeMatrix4& e) {
  Integer l(1);
  for (const auto& p : e) forms::lcm_of_denominators(p.begin(), p.end(), l);
  MatZ out;
  for (std::size_t i = 0; i < 16; ++i) {
    std::vector<Integer> c;
    for (const auto& x : e[i]) c.push_back(x.numerator() * (l / x.denominator()));
    out.a[i] = c.empty() ? PolyZ(Integer(0)) : PolyZ(c.begin(), c.end());
  }
  make_primitive(out.a);
  return out;
}

MatZ integer_matrix(const Matrix4& p) {
  Integer l(1);
  forms::lcm_of_denominators(p.a.begin(), p.a.end(), l);
  MatZ out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = PolyZ(Integer(p.a[i].numerator() * (l / p.a[i].denominator())));
  make_primitive(out.a);
  return out;
}

/// The pencil of the moving pair with coefficients in Z[t] and the polynomials in t that decide
/// (math.md §7). f = det(l P + E(t)) and s = det(l A + M(t)) up to positive factors.
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
  std::vector<std::pair<PolyZ, unsigned>> events;       // every candidate instant, with its cause
  std::optional<motion_detail::InstantPencil> instant;  // the decision at instants where f has a multiple root

  /// `interrupt` is checked between the steps (doc/cli.md, Limits: a step of the largest motions
  /// takes about a second).
  MovingPencil(const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p, const Interrupt* interrupt) {
    const MatZ pz = integer_matrix(p.matrix());
    const MatZ ez = integer_matrix(moving_ellipsoid_matrix(e0, m));
    f = characteristic_polynomial<PolyZ>(pz, ez);
    check(interrupt);
    s = special_polynomial<PolyZ>(pz, ez);
    // f and s divided by their integer contents: positive constants, so every root in l, every
    // multiplicity and the sign of every decision quantity (homogeneous in f and in s) is kept,
    // and every polynomial derived below is much smaller.
    make_primitive(f);
    make_primitive(s);
    check(interrupt);
    SturmHabicht<PolyZ> sh(f);
    check(interrupt);
    for (int i = 0; i < 3; ++i) g2[i] = sh.g2[i];
    for (int i = 0; i < 2; ++i) g1[i] = sh.g1[i];
    disc = sh.discriminant();
    SmallnessQuantities<PolyZ> q(f, s);
    check(interrupt);
    vertex = q.vertex;
    graeffe = q.graeffe;
    // Integer contents removed (positive factors): separately where only signs and zeros are read,
    // jointly for the coefficients of one polynomial in l (its roots are read).
    make_primitive(g2);
    make_primitive(g1);
    for (PolyZ* x : {&disc, &vertex, &graeffe}) {
      std::array<PolyZ, 1> one{*x};
      make_primitive(one);
      *x = one[0];
    }
    disc_zero = CGAL::is_zero(disc);
    instant.emplace(pz, ez, f, g2, g1, disc);
    check(interrupt);
    if (!disc_zero) {
      // Disc f(., t) != 0: f square-free, its roots distinct and continuous, none crosses 0 (f(0) =
      // det E < 0) and f4 = det P is constant: the root pattern, hence the position (f~ = f has no
      // multiple root), can only change where Disc f = 0.
      merge = disc;
      events.emplace_back(disc, kCauseDiscriminant);
      // For a body that is not small the position also changes where a root of f crosses lambda_s
      // (math.md §7 and §8): the real zeros of Res_l(f^, s), f^ = f / gcd(f, s) over Q(t).
      const BiZ bf(f.begin(), f.end()), bs(s.begin(), s.end());
      const BiZ fhat = CGAL::integral_division_up_to_constant_factor(bf, CGAL::gcd_up_to_constant_factor(bf, bs));
      check(interrupt);
      if (fhat.degree() >= 1) {
        const PolyZ res = CGAL::resultant(fhat, bs);
        if (!CGAL::is_zero(res)) events.emplace_back(res, kCauseSpecialRoot);
      }
    } else {
      // Disc f = 0 for every t: f has a multiple factor over Q(t). Work with r = f / gcd(f, df/dl)
      // (the square-free part, whose lc is constant because f4 is): away from the zeros of Disc r,
      // Res(r / gcd(r, s), s) and Disc s, the roots of f keep their multiplicities in f and in s.
      const BiZ bf(f.begin(), f.end()), bs(s.begin(), s.end());
      const BiZ r = CGAL::integral_division_up_to_constant_factor(
          bf, CGAL::gcd_up_to_constant_factor(bf, CGAL::differentiate(bf)));
      check(interrupt);
      merge = r.degree() >= 2 ? PolyZ(CGAL::resultant(r, CGAL::differentiate(r))) : PolyZ(Integer(1));
      events.emplace_back(merge, kCauseDiscriminant);
      check(interrupt);
      const BiZ rhat = CGAL::integral_division_up_to_constant_factor(r, CGAL::gcd_up_to_constant_factor(r, bs));
      check(interrupt);
      if (rhat.degree() >= 1) events.emplace_back(PolyZ(CGAL::resultant(rhat, bs)), kCauseSpecialRoot);
      check(interrupt);
      const PolyZ ds = CGAL::resultant(bs, CGAL::differentiate(bs));
      if (!CGAL::is_zero(ds)) events.emplace_back(ds, kCauseSpecialRoot);
    }
    // For a pure translation s and det E are constant, so both quantities are constants: rho does
    // not change (math.md §7). A rotation can change it.
    events.emplace_back(vertex, kCauseSmallness);
    events.emplace_back(graeffe, kCauseSmallness);
  }
};

/// A candidate instant: a real zero of an event polynomial, with its minimal polynomial (an
/// irreducible factor over Z, found with FLINT) and its value when that factor is linear.
struct Candidate {
  Alg t;
  unsigned causes = 0;
  std::optional<Rational> exact;
  PolyZ minimal;
  std::vector<Integer> minimal_coefficients;
  /// The public exact form (minimal polynomial + isolating interval), built on first use; its
  /// interval is refined by fast bisection on exact integer signs when a sign needs precision.
  mutable std::optional<AlgebraicReal> instant;
};

std::vector<Integer> coefficients_of(const PolyZ& p) {
  std::vector<Integer> c;
  if (CGAL::is_zero(p)) return c;
  for (int i = 0; i <= p.degree(); ++i) c.push_back(p[i]);
  return c;
}

Candidate make_candidate(const Alg& t, unsigned cause, std::optional<Rational> exact, std::vector<Integer> minimal) {
  return Candidate{t, cause, std::move(exact), PolyZ(minimal.begin(), minimal.end()), std::move(minimal), {}};
}

/// The public exact form of an instant: rational, or minimal polynomial + isolating interval whose
/// ends show a strict sign change (CGAL's interval refined until they do).
AlgebraicReal& instant_of(const Candidate& z) {
  if (z.instant) return *z.instant;
  if (z.exact) return z.instant.emplace(AlgebraicReal::rational(*z.exact));
  const PolyZ& p = z.minimal;
  for (int guard = 0; guard < 10000; ++guard) {
    const CGAL::Sign sl = p.sign_at(z.t.low()), sh = p.sign_at(z.t.high());
    if (sl != CGAL::ZERO && sh != CGAL::ZERO && sl != sh)
      return z.instant.emplace(
          AlgebraicReal::root(z.minimal_coefficients, z.t.low(), z.t.high(), /*irreducible=*/true));
    z.t.refine();
  }
  throw std::logic_error("motion: could not isolate an irrational instant with a sign change");
}

/// Refine an instant's interval to a width below 2^-bits times max(1, |bounds|).
void refine_to(AlgebraicReal& x, long bits) {
  if (x.is_rational()) return;
  Rational mag = CGAL::abs(x.lower()) > CGAL::abs(x.upper()) ? CGAL::abs(x.lower()) : CGAL::abs(x.upper());
  if (mag < 1) mag = Rational(1);
  Integer d;
  mpz_setbit(d.mpz(), static_cast<mp_bitcnt_t>(bits));
  x.refine(mag / Rational(d));
}

/// The sign of an integer polynomial over an interval in doubles with outward rounding, the
/// coefficients scaled by one power of two into double range (a positive factor): +1 / -1 when the
/// enclosure excludes 0, else 0.
int double_sign_on(const std::vector<Integer>& c, const Rational& lo, const Rational& hi) {
  long top = 0;
  for (const auto& x : c) top = std::max(top, static_cast<long>(mpz_sizeinbase(x.mpz(), 2)));
  using Interval = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> guard;
  auto coefficient = [&](const Integer& x) {
    if (x == 0) return Interval(0);
    // x = (d + e) 2^k with 0.5 <= |d| < 1 (truncated) and |e| < 2^-53: an exact enclosure.
    long k = 0;
    const double d = mpz_get_d_2exp(&k, x.mpz());
    const long shift = k - top;
    const double tiny = std::ldexp(1.0, -1000);
    if (shift < -1000) return Interval(-tiny, tiny);  // |x 2^-top| < 2^-1000
    const double u = std::ldexp(1.0, -53);
    return Interval(std::ldexp(d - u, static_cast<int>(shift)), std::ldexp(d + u, static_cast<int>(shift)));
  };
  const Interval x(CGAL::to_interval(lo).first, CGAL::to_interval(hi).second);
  Interval v = coefficient(c.back());
  for (std::size_t k = c.size() - 1; k-- > 0;) v = v * x + coefficient(c[k]);
  return v.inf() > 0 ? 1 : (v.sup() < 0 ? -1 : 0);
}

/// The same in MPFI at `prec` bits (outward rounding everywhere).
int mpfi_sign_on(const std::vector<Integer>& c, const Rational& lo, const Rational& hi, mpfr_prec_t prec) {
  mpfi_t x, v;
  mpfi_init2(x, prec);
  mpfi_init2(v, prec);
  mpfi_interv_q(x, lo.mpq(), hi.mpq());
  mpfi_set_z(v, c.back().mpz());
  for (std::size_t k = c.size() - 1; k-- > 0;) {
    mpfi_mul(v, v, x);
    mpfi_add_z(v, v, c[k].mpz());
  }
  const int sg = mpfi_is_strictly_pos(v) ? 1 : (mpfi_is_strictly_neg(v) ? -1 : 0);
  mpfi_clear(x);
  mpfi_clear(v);
  return sg;
}

/// Exact sign of p(t*) at a candidate instant.
///  1. Filters: interval evaluation of p over t*'s isolating interval, in doubles (after refining
///     the interval to ~60 bits) and, for large polynomials, in MPFI at 256 and 1024 bits (interval
///     refined to match). A certified non-zero enclosure decides; most signs read are not zero.
///  2. Exact zero test: p reduced modulo the minimal polynomial m of t* (pseudo-remainder; lc(m) > 0
///     keeps the sign); p(t*) = 0 iff the remainder is 0, since m is irreducible.
///  3. A non-zero value is then signed by MPFI with doubling precision (this ends, the value not
///     being 0), with CGAL's exact Sign_at_1 as the last resort.
int sign_at(const AK& ak, const PolyZ& p, const Candidate& z) {
  if (CGAL::is_zero(p)) return 0;
  if (p.degree() == 0) return static_cast<int>(CGAL::sign(p[0]));
  if (z.exact) return static_cast<int>(p.sign_at(*z.exact));
  std::array<PolyZ, 1> one{p};
  make_primitive(one);  // a positive factor: same sign, smaller numbers
  const std::vector<Integer> pc = coefficients_of(one[0]);
  AlgebraicReal& x = instant_of(z);
  refine_to(x, 60);
  if (x.is_rational()) return static_cast<int>(one[0].sign_at(*x.exact()));
  if (const int sg = double_sign_on(pc, x.lower(), x.upper())) return sg;
  // Small polynomials: the exact zero test is cheap, do it first. Large ones (the pseudo-remainder
  // grows like lc(m)^(deg p)): try the multi-precision filters first.
  std::size_t bits = 0;
  for (const auto& c : pc) bits = std::max(bits, mpz_sizeinbase(c.mpz(), 2));
  const std::size_t lc_bits = mpz_sizeinbase(z.minimal_coefficients.back().mpz(), 2);
  const bool cheap_remainder = bits + pc.size() * lc_bits < 4096;
  if (!cheap_remainder)
    for (long prec : {256L, 1024L}) {
      refine_to(x, prec / 2);
      if (const int sg = mpfi_sign_on(pc, x.lower(), x.upper(), prec)) return sg;
    }
  std::vector<Integer> r = pseudo_remainder(pc, z.minimal_coefficients);
  while (!r.empty() && r.back() == 0) r.pop_back();
  if (r.empty()) return 0;
  if (r.size() == 1) return static_cast<int>(CGAL::sign(r[0]));
  for (long prec = 2048; prec <= (1L << 18); prec *= 2) {
    refine_to(x, prec / 2);
    if (const int sg = mpfi_sign_on(pc, x.lower(), x.upper(), prec)) return sg;
  }
  return static_cast<int>(ak.sign_at_1_object()(PolyZ(r.begin(), r.end()), z.t));
}

/// A simple rational strictly between two algebraic reals a < b (their isolating intervals are
/// refined until disjoint). CGAL's Bound_between needs a big-float interval type; this does not.
Rational rational_between(const Alg& a, const Alg& b) {
  while (!(a.high() < b.low())) {
    if (a.low() != a.high()) a.refine();
    if (b.low() != b.high()) b.refine();
  }
  // a <= a.high() < b.low() <= b: any number strictly between the two ends will do.
  return detail::rational_inside(a.high(), Rational(b.low()), detail::Shortest::Denominator);
}

/// Merge the real zeros of p in [lo, hi] into the sorted list `out` (exact comparisons; a zero
/// shared by several polynomials is kept once with all its causes). p is split into irreducible
/// factors first: a linear factor gives a rational zero at once, and the others are isolated
/// separately (smaller polynomials make every later sign evaluation at the zero cheaper).
void add_zeros(const AK& ak, const PolyZ& p, unsigned cause, const Rational& lo, const Rational& hi,
               std::vector<Candidate>& out, const Interrupt* interrupt) {
  check(interrupt);
  if (CGAL::is_zero(p) || p.degree() < 1) return;
  std::vector<Integer> coeffs;
  for (int i = 0; i <= p.degree(); ++i) coeffs.push_back(p[i]);
  std::vector<Candidate> zeros;
  for (const auto& g : irreducible_factors(coeffs)) {
    check(interrupt);
    const PolyZ gz(g.begin(), g.end());
    if (g.size() == 2) {
      const Rational x(-g[0], g[1]);
      if (lo <= x && x <= hi) zeros.push_back(make_candidate(Alg(x), cause, x, g));
      continue;
    }
    std::vector<Alg> roots;
    ak.solve_1_object()(gz, true, lo, hi, std::back_inserter(roots));
    for (const Alg& z : roots) zeros.push_back(make_candidate(z, cause, std::nullopt, g));
  }
  const auto cmp = ak.compare_1_object();
  for (Candidate& z : zeros) {
    std::size_t i = 0;
    while (i < out.size() && cmp(out[i].t, z.t) == CGAL::SMALLER) ++i;
    if (i < out.size() && cmp(out[i].t, z.t) == CGAL::EQUAL)
      out[i].causes |= cause;
    else
      out.insert(out.begin() + static_cast<std::ptrdiff_t>(i), std::move(z));
  }
}

int total_degree(const std::vector<std::pair<PolyZ, unsigned>>& polys) {
  int d = 0;
  for (const auto& [p, cause] : polys)
    if (!CGAL::is_zero(p) && p.degree() > 0) d += p.degree();
  return d;
}

/// The position at an instant t* where f(., t*) has a multiple root, for any size (instant_position.hpp);
/// nullopt when f(., t*) is square-free there.
/// `interrupt` is checked before every sign.
std::optional<motion_detail::InstantDecision> decide_at(const MovingPencil& mp, const AK& ak, const Candidate& a,
                                                        const Interrupt* interrupt) {
  // A zero of the discriminant polynomial (its minimal polynomial divides Disc f) needs no test.
  const bool known_multiple = mp.disc_zero || ((a.causes & kCauseDiscriminant) && !a.exact);
  return motion_detail::decide_at_instant(
      *mp.instant,
      [&](const PolyZ& q) {
        check(interrupt);
        return sign_at(ak, q, a);
      },
      known_multiple);
}

/// rho(t*) <= 1 at an instant (the two smallness quantities' signs; reported, never needed).
bool small_at(const MovingPencil& mp, const AK& ak, const Candidate& a) {
  return *compare_rho_with_one(USign(static_cast<CGAL::Sign>(sign_at(ak, mp.vertex, a))),
                               USign(static_cast<CGAL::Sign>(sign_at(ak, mp.graeffe, a)))) <= 0;
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
  }
  return 0;
}

/// The cross-check of an instant with its neighbouring intervals (`closure`): a violation is a
/// defect, never an answer.
void check_closure(Position at, const std::optional<Position>& before, const std::optional<Position>& after,
                   const AlgebraicReal& t) {
  const unsigned bit = 1u << static_cast<unsigned>(at);
  for (const auto& n : {before, after})
    if (n && !(closure(*n) & bit))
      throw std::logic_error("internal error: motion: position " + to_string(at) + " at t = " + t.decimals(20) +
                             " is not a limit of the neighbouring position " + to_string(*n));
}

Classification classify_at(const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p, const Rational& t) {
  return detail::classify_unchecked(placed_ellipsoid(e0, m, t), p, Evidence::Minimal);
}

std::string classify_how(const Classification& c) {
  return "classified exactly at the rational instant (" + to_string(c.verdict.stage) + ")";
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

std::string to_string(FirstContact::Kind kind) {
  switch (kind) {
    case FirstContact::Kind::NotExteriorAtStart:
      return "not-exterior-at-start";
    case FirstContact::Kind::Contact:
      return "contact";
    case FirstContact::Kind::None:
      return "none";
  }
  throw std::logic_error("internal error: to_string: not a FirstContact::Kind");
}

FirstContact first_contact(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                           const Rational& t1, const Interrupt* interrupt) {
  validate_motion(motion, t0, t1);
  check(interrupt);
  FirstContact out;
  const Classification c0 = classify_at(e0, motion, p, t0);
  out.start_position = c0.verdict.position;
  if (c0.verdict.position != Position::E) {
    out.kind = FirstContact::Kind::NotExteriorAtStart;
    out.time = AlgebraicReal::rational(t0);
    out.position = c0.verdict.position;
    out.how = classify_how(c0);
    return out;
  }
  // Separation (two distinct positive roots) is open and is decided for any size; it can only end
  // where two roots of f meet, i.e. at a real zero of `merge` (math.md §7).
  const MovingPencil mp(e0, motion, p, interrupt);
  AK ak;
  std::vector<Candidate> zeros;
  add_zeros(ak, mp.merge, kCauseDiscriminant, t0, t1, zeros, interrupt);
  const auto cmp = ak.compare_1_object();
  const Alg a0(t0);
  for (const Candidate& z : zeros) {
    if (cmp(z.t, a0) == CGAL::EQUAL) continue;  // t0 itself: classified above
    check(interrupt);
    Position pos;
    std::string how;
    if (z.exact) {
      const Classification c = classify_at(e0, motion, p, *z.exact);
      pos = c.verdict.position;
      how = classify_how(c);
    } else {
      // The left neighbour is E; E is open, so a square-free f (no root merges) keeps it.
      const auto d = decide_at(mp, ak, z, interrupt);
      if (!d) continue;
      pos = d->position;
      how = "at the algebraic instant: " + d->how;
      check_closure(pos, Position::E, std::nullopt, instant_of(z));
    }
    if (pos != Position::E) {
      out.kind = FirstContact::Kind::Contact;
      out.time = instant_of(z);
      out.position = pos;
      out.how = how;
      return out;
    }
  }
  out.kind = FirstContact::Kind::None;
  return out;
}

Timeline timeline(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                  const Rational& t1, const Interrupt* interrupt) {
  validate_motion(motion, t0, t1);
  Timeline out;
  out.t0 = t0;
  out.t1 = t1;
  const MovingPencil mp(e0, motion, p, interrupt);
  out.discriminant_identically_zero = mp.disc_zero;
  out.event_degree = total_degree(mp.events);
  AK ak;

  // Candidate instants in [t0, t1], with t0 and t1 themselves.
  std::vector<Candidate> cands{make_candidate(Alg(t0), kCauseStart, t0, {-t0.numerator(), t0.denominator()})};
  if (t1 > t0)
    cands.push_back(make_candidate(Alg(t1), kCauseEnd, t1, {-t1.numerator(), t1.denominator()}));
  else
    cands.front().causes |= kCauseEnd;
  for (const auto& [poly, cause] : mp.events) add_zeros(ak, poly, cause, t0, t1, cands, interrupt);

  // Open intervals: classified exactly at a rational sample strictly inside. The classifications
  // are kept: their root counts serve the square-free instants.
  std::vector<Classification> interval_class;
  for (std::size_t i = 0; i + 1 < cands.size(); ++i) {
    check(interrupt);
    MotionInterval iv;
    iv.sample = rational_between(cands[i].t, cands[i + 1].t);
    interval_class.push_back(classify_at(e0, motion, p, iv.sample));
    iv.position = interval_class.back().verdict.position;
    iv.small = interval_class.back().verdict.small;
    out.intervals.push_back(std::move(iv));
  }

  for (std::size_t i = 0; i < cands.size(); ++i) {
    check(interrupt);
    const Candidate& z = cands[i];
    MotionInstant inst{instant_of(z), Position::C, false, z.causes, ""};
    if (inst.time.is_rational()) {
      const Classification c = classify_at(e0, motion, p, *inst.time.exact());
      inst.position = c.verdict.position;
      inst.small = c.verdict.small;
      inst.how = classify_how(c);
    } else {
      // Irrational instants are interior (t0, t1 are rational), so intervals i-1 and i exist. f
      // square-free at t*: no tangency (that needs a multiple root), so the position is open (E, I
      // or C) and equals that of the neighbouring intervals. Otherwise the definiteness test of
      // instant_position.hpp decides, for any size.
      const auto d = decide_at(mp, ak, z, interrupt);
      if (d) {
        inst.position = d->position;
        inst.how = "at the algebraic instant: " + d->how;
      } else {
        inst.position = out.intervals[i - 1].position;
        inst.how =
            "at the algebraic instant: f is square-free (no root merges), the position of the neighbouring "
            "intervals";
      }
      check(interrupt);
      inst.small = small_at(mp, ak, z);
    }
    // Cross-check with the neighbours: E|C forces TE, I|C forces TI, E|I is impossible, ...
    check_closure(inst.position, i > 0 ? std::optional<Position>(out.intervals[i - 1].position) : std::nullopt,
                  i + 1 < cands.size() ? std::optional<Position>(out.intervals[i].position) : std::nullopt, inst.time);
    out.instants.push_back(std::move(inst));
  }
  return out;
}

std::optional<Position> position_by_subresultants(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p,
                                                  const Rational& t) {
  const MovingPencil mp(e0, motion, p, nullptr);
  AK ak;
  const auto d = decide_at(mp, ak, make_candidate(Alg(t), 0, t, {-t.numerator(), t.denominator()}), nullptr);
  if (!d) return std::nullopt;
  return d->position;
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
  if (instants.empty() || intervals.size() + 1 != instants.size())
    throw InputError("Timeline::position_at: an empty or inconsistent timeline (build it with relpos::timeline)");
  if (t < t0 || t > t1) throw InputError("time " + to_string(t) + " is outside [t0, t1]");
  for (std::size_t i = 0; i < instants.size(); ++i) {
    const int c = instants[i].time.compare(t);
    if (c == 0) return instants[i].position;
    if (c > 0) return intervals[i - 1].position;  // i > 0 because instants[0] = t0 <= t
  }
  return instants.back().position;
}

}  // namespace relpos
