// float_matrices.hpp. Compiled without -frounding-math (CMakeLists.txt): the code a float program is.
#include "oracle/float_matrices.hpp"

#include "oracle/nearest.hpp"

namespace relpos::detail::oracle {

namespace {

template <std::size_t N>
std::array<double, N> nearest_array(const std::array<Rational, N>& x) {
  std::array<double, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = nearest_double(x[i]);
  return out;
}

template <std::size_t N>
std::array<Rational, N> exact_array(const std::array<double, N>& x) {
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = exact_rational(x[i]);
  return out;
}

using M3 = std::array<std::array<double, 3>, 3>;

M3 rotation(const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double n = w * w + x * x + y * y + z * z;
  M3 r;
  r[0] = {(w * w + x * x - y * y - z * z) / n, 2 * (x * y - w * z) / n, 2 * (x * z + w * y) / n};
  r[1] = {2 * (x * y + w * z) / n, (w * w - x * x + y * y - z * z) / n, 2 * (y * z - w * x) / n};
  r[2] = {2 * (x * z - w * y) / n, 2 * (y * z + w * x) / n, (w * w - x * x - y * y + z * z) / n};
  return r;
}

/// (R diag(d)) R^T, as two matrix products.
M3 rdrt(const M3& r, const std::array<double, 3>& d) {
  M3 rd, out;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) rd[i][k] = r[i][k] * d[k];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = rd[i][0] * r[j][0] + rd[i][1] * r[j][1] + rd[i][2] * r[j][2];
  return out;
}

std::array<double, 3> times(const M3& m, const std::array<double, 3>& v) {
  std::array<double, 3> out;
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return out;
}

double dot(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

DoubleMatrix4 assemble(const M3& m, const std::array<double, 3>& u, double corner) {
  DoubleMatrix4 out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[static_cast<std::size_t>(4 * i + j)] = m[i][j];
    out[static_cast<std::size_t>(4 * i + 3)] = out[static_cast<std::size_t>(12 + i)] = u[i];
  }
  out[15] = corner;
  return out;
}

}  // namespace

DoubleParameters nearest_parameters(const Parameters& p) {
  return {nearest_array(p.centre), nearest_array(p.axes), nearest_array(p.e_rotation), nearest_array(p.vertex),
          nearest_double(p.a),     nearest_double(p.b),   nearest_array(p.p_rotation)};
}

Parameters exact_parameters(const DoubleParameters& d) {
  Parameters p;
  p.centre = exact_array(d.centre);
  p.axes = exact_array(d.axes);
  p.e_rotation = exact_array(d.e_rotation);
  p.vertex = exact_array(d.vertex);
  p.a = exact_rational(d.a);
  p.b = exact_rational(d.b);
  p.p_rotation = exact_array(d.p_rotation);
  return p;
}

DoubleMatrix4 ellipsoid_matrix(const DoubleParameters& d) {
  const M3 m = rdrt(rotation(d.e_rotation),
                    {1 / (d.axes[0] * d.axes[0]), 1 / (d.axes[1] * d.axes[1]), 1 / (d.axes[2] * d.axes[2])});
  const std::array<double, 3> mc = times(m, d.centre);
  return assemble(m, {-mc[0], -mc[1], -mc[2]}, dot(d.centre, mc) - 1);
}

DoubleMatrix4 paraboloid_matrix(const DoubleParameters& d) {
  const M3 r = rotation(d.p_rotation);
  const M3 a = rdrt(r, {1 / (d.a * d.a), 1 / (d.b * d.b), 0.0});
  const std::array<double, 3> av = times(a, d.vertex), axis{r[0][2], r[1][2], r[2][2]};
  return assemble(a, {-av[0] - axis[0] / 2, -av[1] - axis[1] / 2, -av[2] - axis[2] / 2},
                  dot(d.vertex, av) + dot(axis, d.vertex));
}

DoubleMatrix4 upper_triangle(const DoubleMatrix4& m) {
  DoubleMatrix4 out = m;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < i; ++j) out[4 * i + j] = m[4 * j + i];
  return out;
}

}  // namespace relpos::detail::oracle
