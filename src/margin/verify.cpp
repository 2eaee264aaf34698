// verify_margin(): a margin checked with exact arithmetic (math.md §19, doc/certificates.md,
// "Margins"). The enclosure is proven by the certificates of the scaled pairs (verify_certificate,
// which shares no code with the classifier); that s* is the claimed polynomial's root there follows
// from the margin polynomial, of which s* is a root, having no other root in the enclosure.
#include <cmath>
#include <limits>
#include <string>

#include "algebra/irreducible.hpp"
#include "algebra/polynomial_sign.hpp"
#include "margin/descartes.hpp"
#include "margin/family.hpp"
#include "margin/polynomial.hpp"
#include "relpos/margin.hpp"

namespace relpos {
namespace {

/// The position a certificate of a scaled pair claims: Definite with lambda < 0 is I, > 0 E;
/// Tangent likewise TI, TE; HardTangent TI; Crossing C. nullopt for None or lambda = 0.
std::optional<Position> claimed(const Certificate& c) {
  switch (c.kind) {
    case Certificate::Kind::Definite:
      if (c.lambda == 0) return std::nullopt;
      return c.lambda < 0 ? Position::I : Position::E;
    case Certificate::Kind::Tangent:
      if (c.lambda == 0) return std::nullopt;
      return c.lambda < 0 ? Position::TI : Position::TE;
    case Certificate::Kind::HardTangent:
      return Position::TI;
    case Certificate::Kind::Crossing:
      return Position::C;
    case Certificate::Kind::None:
      break;
  }
  return std::nullopt;
}

/// The certificate `c` of the pair scaled by q must prove one of the positions `allowed` describes.
std::optional<std::string> check_scaled(const detail::ScaledFamily& family, const Matrix4& p, const Rational& q,
                                        const Certificate& c, const char* name, bool (*allowed)(Position),
                                        const char* expected) {
  const std::optional<Position> position = claimed(c);
  if (!position || !allowed(*position))
    return std::string(name) + ": expected a certificate of " + expected + " for the ellipsoid scaled by " +
           to_string(q);
  if (auto reason = verify_certificate(family.at(q), p, *position, c))
    return std::string(name) + " (" + to_string(*position) + " scaled by " + to_string(q) + "): " + *reason;
  return std::nullopt;
}

/// approx within one unit in the last place of [lo, hi]: its neighbours below and above bracket a
/// point of the enclosure (+infinity, the nearest double of an s* beyond the double range, has
/// DBL_MAX below it).
bool near_enclosure(double approx, const Rational& lo, const Rational& hi) {
  if (std::isnan(approx) || approx == -std::numeric_limits<double>::infinity()) return false;
  const double below = std::nextafter(approx, -std::numeric_limits<double>::infinity());
  const double above = std::nextafter(approx, std::numeric_limits<double>::infinity());
  return (!std::isfinite(below) || exact_rational(below) <= hi) &&
         (!std::isfinite(above) || exact_rational(above) >= lo);
}

/// The polynomial is the minimal polynomial of some algebraic number: irreducible over Q, primitive,
/// with a positive leading coefficient (FLINT's factorisation returns exactly such factors).
bool minimal_form(const std::vector<Integer>& m) {
  if (m.size() < 2 || m.back() == 0 || m.back() < 0) return false;
  if (detail::proven_irreducible(m)) {  // then primitive when its content is 1
    Integer content(0);
    for (const Integer& c : m) mpz_gcd(content.mpz(), content.mpz(), c.mpz());
    return content == 1;
  }
  const std::vector<std::vector<Integer>> factors = detail::irreducible_factors(m);
  return factors.size() == 1 && factors[0] == m;
}

}  // namespace

std::optional<std::string> verify_margin(const Ellipsoid& e, const Paraboloid& p, const Margin& m) {
  if (!minimal_form(m.polynomial))
    return std::string("the polynomial is not irreducible, primitive and of positive leading coefficient");
  if (m.lo < 0 || m.hi < m.lo)
    return "the enclosure [" + to_string(m.lo) + ", " + to_string(m.hi) + "] is not 0 <= lo <= hi";
  if (!near_enclosure(m.approx, m.lo, m.hi)) return std::string("approx is not within one ulp of the enclosure");
  const detail::ScaledFamily family = detail::scaled_family(e.matrix());
  const Matrix4& pm = p.matrix();
  const bool on_surface = detail::form_at(pm, family.centre) == 0;
  const bool rational = m.lo == m.hi;
  if (rational && (m.below.kind != Certificate::Kind::None || m.above.kind != Certificate::Kind::None))
    return std::string("a rational margin has one certificate, \"at\"");
  if (!rational && m.at.kind != Certificate::Kind::None)
    return std::string("an irrational margin has two certificates, \"below\" and \"above\"");
  if (m.hi == 0) {  // s* = 0: the centre lies on the paraboloid
    if (!on_surface) return std::string("s* = 0 but the ellipsoid's centre is not on the paraboloid");
    if (m.polynomial != std::vector<Integer>{Integer(0), Integer(1)})
      return std::string("s* = 0 but the polynomial is not t");
    if (m.at.kind != Certificate::Kind::None) return std::string("s* = 0 carries no certificate");
    return std::nullopt;
  }
  if (on_surface) return std::string("the ellipsoid's centre lies on the paraboloid, so s* = 0");
  if (m.lo == 0) return std::string("lo = 0 < hi: the enclosure must have lo > 0");
  if (rational) {
    if (detail::sign_of_value(m.polynomial, m.lo) != 0) return std::string("the polynomial does not vanish at lo = hi");
    if (auto reason = check_scaled(
            family, pm, m.lo, m.at, "at", [](Position q) { return q == Position::TI || q == Position::TE; },
            "TI or TE"))
      return reason;
  } else {
    if (detail::sign_of_value(m.polynomial, m.lo) * detail::sign_of_value(m.polynomial, m.hi) >= 0)
      return std::string("the polynomial does not change sign on [lo, hi]");
    if (auto reason = check_scaled(
            family, pm, m.lo, m.below, "below", [](Position q) { return q == Position::I || q == Position::E; },
            "I or E"))
      return reason;
    if (auto reason = check_scaled(
            family, pm, m.hi, m.above, "above", [](Position q) { return q == Position::C; }, "C"))
      return reason;
  }
  // s* is a root of the margin polynomial (math.md §19) and lies in the enclosure: when the claimed
  // polynomial divides it and the rest of it has no root there, s* is the claimed polynomial's root.
  const std::vector<Integer> pi = detail::in_square(detail::margin_polynomial(detail::point_pencil(family, pm)));
  if (rational) {
    if (!detail::pseudo_remainder(pi, m.polynomial).empty())
      return std::string("the polynomial does not divide the pair's margin polynomial");
  } else if (!detail::isolates(pi, m.polynomial, m.lo, m.hi)) {
    return std::string(
        "the enclosure does not isolate a root of the polynomial from the other roots of the pair's margin "
        "polynomial (or the polynomial does not divide it)");
  }
  return std::nullopt;
}

}  // namespace relpos
