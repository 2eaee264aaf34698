// tolerance.hpp.
#include "oracle/tolerance.hpp"

#include "oracle/json_text.hpp"
#include "relpos/error.hpp"

namespace relpos::detail::oracle {

namespace {

Rational number(const Json& j, const std::string& name) {
  if (!j.contains(name)) throw InputError("margin: \"" + name + "\" is missing");
  const Json& v = j[name];
  if (v.is_string()) return parse_rational(v.get<std::string>());
  if (v.is_number_integer()) return Rational(Integer(v.dump()));
  throw InputError("margin: \"" + name + "\" must be an exact number as a string (\"p/q\")");
}

/// The sign of the polynomial at x, exactly (Horner on rationals).
int sign_at(const std::vector<Integer>& p, const Rational& x) {
  Rational v(0);
  for (std::size_t k = p.size(); k-- > 0;) v = v * x + Rational(p[k]);
  return CGAL::sign(v);
}

}  // namespace

MarginValue margin_from_json(const Json& j) {
  if (!j.is_object()) throw InputError("margin: expected an object");
  MarginValue m;
  m.lo = number(j, "lo");
  m.hi = number(j, "hi");
  if (m.lo > m.hi) throw InputError("margin: lo > hi");
  if (m.lo < 0) throw InputError("margin: lo < 0 (s* is not negative)");
  if (m.lo == m.hi) return m;
  if (!j.contains("polynomial") || !j["polynomial"].is_array())
    throw InputError("margin: lo < hi needs the \"polynomial\" whose root s* is");
  for (const Json& c : j["polynomial"]) {
    const Rational r = c.is_string() ? parse_rational(c.get<std::string>())
                                     : (c.is_number_integer() ? Rational(Integer(c.dump())) : Rational(1, 3));
    if (r.denominator() != 1) throw InputError("margin: the polynomial's coefficients must be integers");
    m.polynomial.push_back(r.numerator());
  }
  if (sign_at(m.polynomial, m.lo) * sign_at(m.polynomial, m.hi) >= 0)
    throw InputError("margin: the polynomial does not change sign between lo and hi");
  return m;
}

int compare_with(const Rational& t, const MarginValue& m) {
  if (m.lo == m.hi) return CGAL::sign(t - m.lo);
  if (t <= m.lo) return -1;  // s* lies strictly inside (lo, hi): the polynomial is not 0 at its ends
  if (t >= m.hi) return 1;
  const int at = sign_at(m.polynomial, t);
  if (at == 0) return 0;
  return at == sign_at(m.polynomial, m.lo) ? -1 : 1;  // no sign change on [lo, t]: s* beyond t
}

bool within_tolerance(Position answer, CentreSide side, const MarginValue& m, const Rational& tau) {
  const bool on_surface = side == CentreSide::On || (m.lo == 0 && m.hi == 0);
  if (on_surface) return answer == Position::C;
  const int low = compare_with(1 - tau, m), high = compare_with(1 + tau, m);  // signs of (1 -+ tau) - s*
  switch (answer) {
    case Position::I:
    case Position::E:
      return (answer == Position::I) == (side == CentreSide::Inside) && low < 0;
    case Position::TI:
    case Position::TE:
      return (answer == Position::TI) == (side == CentreSide::Inside) && low <= 0 && high >= 0;
    case Position::C:
      return high > 0;
  }
  return false;
}

}  // namespace relpos::detail::oracle
