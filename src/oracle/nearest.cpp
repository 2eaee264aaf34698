// nearest.hpp: rounding to nearest on the tight enclosure CGAL computes (MPFR), decided exactly.
#include "oracle/nearest.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "relpos/error.hpp"

namespace relpos::detail::oracle {

namespace {

bool even_significand(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return (bits & 1) == 0;
}

}  // namespace

double nearest_double(const Rational& q) {
  const std::pair<double, double> e = CGAL::to_interval(q);  // the two doubles around q (or q itself)
  if (!std::isfinite(e.first) || !std::isfinite(e.second))
    throw InputError("the number " + to_decimal(q, 6) + " is beyond the range of a double");
  if (e.first == e.second) return e.first;
  // q lies strictly between two neighbours: the nearer one; at the midpoint, the even one.
  const Rational twice = q * 2, sum = exact_rational(e.first) + exact_rational(e.second);
  if (twice < sum) return e.first;
  if (twice > sum) return e.second;
  return even_significand(e.first) ? e.first : e.second;
}

std::string exact_text(double x) { return to_string(exact_rational(x)); }

}  // namespace relpos::detail::oracle
