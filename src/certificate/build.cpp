#include "certificate/build.hpp"

#include "certificate/curve.hpp"
#include "certificate/kinds.hpp"

namespace relpos::detail::certificate {

void build(const detail::PairContext& pair, Position position, Certificate& c) {
  switch (position) {
    case Position::E:
    case Position::I:
      return definite(pair, position, c);
    case Position::TE:
    case Position::TI:
      return tangent(pair, position, c);
    case Position::C:
      return crossing_points(pair, c);
  }
  throw internal_error("no certificate for a pair classified " + to_string(position));
}

Certificate build(const Ellipsoid& e, const Paraboloid& p, Position position) {
  const detail::PairContext pair(e, p);
  Certificate c;
  build(pair, position, c);
  return c;
}

}  // namespace relpos::detail::certificate
