#include "motion/moving_pencil.hpp"

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>

#include <array>
#include <iterator>

#include "algebra/forms.hpp"
#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "base/interrupt.hpp"
#include "motion/polynomial_motion.hpp"

namespace relpos::detail {
namespace {

using BiZ = CGAL::Polynomial<PolyZ>;  // polynomials in l over Z[t] (l is the outer variable)

/// Matrix view for the generic pencil code (pencil.hpp) with entries in Z[t].
using MatZ = forms::MatrixOf<PolyZ>;

/// gcd of the integer coefficients of several polynomials in t (0 for no non-zero coefficient).
Integer integer_content(const PolyZ* first, const PolyZ* last) {
  Integer g(0);
  for (const PolyZ* p = first; p != last; ++p) {
    if (CGAL::is_zero(*p)) continue;
    for (int i = 0; i <= p->degree(); ++i) {
      Integer r;
      mpz_gcd(r.mpz(), g.mpz(), (*p)[i].mpz());
      g = r;
    }
  }
  return g;
}

/// p / c for a positive integer c dividing every coefficient.
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
  make_primitive(out.a.data(), out.a.data() + 16);
  return out;
}

MatZ integer_matrix(const Matrix4& p) {
  Integer l(1);
  forms::lcm_of_denominators(p.a.begin(), p.a.end(), l);
  MatZ out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = PolyZ(Integer(p.a[i].numerator() * (l / p.a[i].denominator())));
  make_primitive(out.a.data(), out.a.data() + 16);
  return out;
}

}  // namespace

void make_primitive(PolyZ* first, PolyZ* last) {
  const Integer g = integer_content(first, last);
  if (g > 1)
    for (PolyZ* p = first; p != last; ++p) *p = divide_exactly(*p, g);
}

MovingPencil::MovingPencil(const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p, const Interrupt* interrupt) {
  const MatZ pz = integer_matrix(p.matrix());
  const MatZ ez = integer_matrix(moving_ellipsoid_matrix(e0, m));
  f = characteristic_polynomial<PolyZ>(pz, ez);
  check(interrupt);
  s = special_polynomial<PolyZ>(pz, ez);
  // f and s divided by their integer contents: positive constants, so every root in l, every
  // multiplicity and the sign of every decision quantity (homogeneous in f and in s) is kept,
  // and every polynomial derived below is much smaller.
  make_primitive(f.data(), f.data() + f.size());
  make_primitive(s.data(), s.data() + s.size());
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
  make_primitive(std::begin(g2), std::end(g2));
  make_primitive(std::begin(g1), std::end(g1));
  for (PolyZ* x : {&disc, &vertex, &graeffe}) make_primitive(x, x + 1);
  disc_zero = CGAL::is_zero(disc);
  instant.emplace(pz, ez, f, g2, g1, disc);
  check(interrupt);
  if (!disc_zero)
    add_square_free_events(interrupt);
  else
    add_multiple_factor_events(interrupt);
  // For a pure translation s and det E are constant, so both quantities are constants: rho does
  // not change (math.md §7). A rotation can change it.
  events.emplace_back(vertex, kCauseSmallness);
  events.emplace_back(graeffe, kCauseSmallness);
}

/// Disc f(., t) != 0: f square-free, its roots distinct and continuous, none crosses 0 (f(0) =
/// det E < 0) and f4 = det P is constant: the root pattern, hence the position (f~ = f has no
/// multiple root), can only change where Disc f = 0. For a body that is not small the position also
/// changes where a root of f crosses lambda_s (math.md §7 and §8): the real zeros of
/// Res_l(f^, s), f^ = f / gcd(f, s) over Q(t).
void MovingPencil::add_square_free_events(const Interrupt* interrupt) {
  merge = disc;
  events.emplace_back(disc, kCauseDiscriminant);
  const BiZ bf(f.begin(), f.end()), bs(s.begin(), s.end());
  const BiZ fhat = CGAL::integral_division_up_to_constant_factor(bf, CGAL::gcd_up_to_constant_factor(bf, bs));
  check(interrupt);
  if (fhat.degree() >= 1) {
    const PolyZ res = CGAL::resultant(fhat, bs);
    if (!CGAL::is_zero(res)) events.emplace_back(res, kCauseSpecialRoot);
  }
}

/// Disc f = 0 for every t: f has a multiple factor over Q(t). Work with r = f / gcd(f, df/dl) (the
/// square-free part, whose lc is constant because f4 is): away from the zeros of Disc r,
/// Res(r / gcd(r, s), s) and Disc s, the roots of f keep their multiplicities in f and in s.
void MovingPencil::add_multiple_factor_events(const Interrupt* interrupt) {
  const BiZ bf(f.begin(), f.end()), bs(s.begin(), s.end());
  const BiZ r =
      CGAL::integral_division_up_to_constant_factor(bf, CGAL::gcd_up_to_constant_factor(bf, CGAL::differentiate(bf)));
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

}  // namespace relpos::detail
