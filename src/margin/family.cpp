#include "margin/family.hpp"

#include <stdexcept>
#include <utility>

#include "algebra/centre.hpp"
#include "relpos/error.hpp"
#include "relpos/margin.hpp"

namespace relpos {
namespace detail {

ScaledFamily scaled_family(const Matrix4& e) {
  const std::optional<Vector3> c = centre_of(e);
  if (!c) throw std::logic_error("internal error: scaled_family: the ellipsoid's M is singular");
  ScaledFamily f;
  f.centre = *c;
  // e(c) = e0 + m.c at the centre (M c = -m): the corner of E0 is e0 + k = -m.c.
  Rational mc(0);
  for (int i = 0; i < 3; ++i) mc += e(i, 3) * f.centre[static_cast<std::size_t>(i)];
  f.k = -(e(3, 3) + mc);
  if (!(f.k > 0)) throw std::logic_error("internal error: scaled_family: not a real ellipsoid");
  f.point = e;
  f.point(3, 3) = -mc;
  return f;
}

Matrix4 ScaledFamily::at_square(const Rational& v) const {
  Matrix4 m = point;
  m(3, 3) = point(3, 3) - v * k;
  return m;
}

}  // namespace detail

Ellipsoid detail::scaled_about_centre(const Ellipsoid& e, const Rational& factor) {
  if (!(factor > 0)) throw InputError("the scale factor must be positive, got " + to_string(factor));
  // M is unchanged and det E_q = -q^2 k det M < 0: a real ellipsoid, sign-normalized as E is.
  return detail::make_ellipsoid(detail::QuadricMatrix(detail::scaled_family(e.matrix()).at(factor)));
}

}  // namespace relpos
