// The demo / benchmark scene of relpos scene --generate and benchmarks/scene_bench.cpp:
// particles in the parabolic container x^2/a^2 + y^2/b^2 <= z (doc/performance.md, "Scenes").
//
// Reproducible across platforms: only std::mt19937_64 (its output sequence is fixed by the
// standard) and integer / power-of-two arithmetic on its output; no std::*_distribution.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "relpos/scene.hpp"
#include "scene/demo.hpp"

namespace relpos {

Ellipsoid DemoBody::ellipsoid() const {
  return kind == Kind::Sphere ? Ellipsoid::sphere(centre, radius) : Ellipsoid::from_coefficients(coefficients);
}

// Named (not anonymous): DemoSceneGenerator::State holds them, and a unity build compiles this file
// inside another's translation unit, where GCC warns of a class with members of internal linkage.
namespace detail::demo {

class Random {
 public:
  explicit Random(std::uint64_t seed) : g_(seed) {}
  /// Uniform in [0, 1), 53 random bits.
  double unit() { return static_cast<double>(g_() >> 11) * 0x1p-53; }
  /// Uniform integer in [lo, hi] (the modulo bias is irrelevant for a demo).
  long integer(long lo, long hi) { return lo + static_cast<long>(g_() % static_cast<std::uint64_t>(hi - lo + 1)); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }

 private:
  std::mt19937_64 g_;
};

struct Container {
  double a2, b2;  // a^2, b^2 as doubles (sampling only)
  double l;       // min(a, b)^2: twice the smallest radius of curvature
  double h;       // height of the rim
  int grid;       // centres on multiples of 2^grid
  Rational rl;    // l, exactly
  double f(double x, double y, double z) const { return x * x / a2 + y * y / b2 - z; }
};

}  // namespace detail::demo

namespace {

using detail::demo::Container;
using detail::demo::Random;

Rational frac(long n, long d) { return Rational(Integer(n), Integer(d)); }

/// x rounded to a multiple of 2^e: an exact double, then its exact rational value.
Rational on_grid(double x, int e) { return exact_rational(std::ldexp(std::nearbyint(std::ldexp(x, -e)), e)); }

DemoBody sphere(Vector3 c, Rational r) {
  DemoBody b;
  b.kind = DemoBody::Kind::Sphere;
  b.centre = std::move(c);
  b.radius = std::move(r);
  return b;
}

/// (x - c)^T M (x - c) = 1 with M = (B^T B + I/4) / r^2, B with entries in {-1, -7/8, .., 1} and
/// r = l 2^-j: semi-axes between about r/3 and 2r; every coefficient is dyadic.
DemoBody ellipsoid(Random& g, const Vector3& c, const Container& k) {
  const Rational r = k.rl * exact_rational(std::ldexp(1.0, -static_cast<int>(g.integer(3, 6))));
  Rational bm[3][3];
  for (auto& row : bm)
    for (auto& x : row) x = frac(g.integer(-8, 8), 8);
  Rational m[3][3];
  const Rational inv_r2 = Rational(1) / (r * r);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational s = i == j ? Rational(1, 4) : Rational(0);
      for (int t = 0; t < 3; ++t) s += bm[t][i] * bm[t][j];
      m[i][j] = s * inv_r2;
    }
  Rational mc[3];
  for (int i = 0; i < 3; ++i) mc[i] = m[i][0] * c[0] + m[i][1] * c[1] + m[i][2] * c[2];
  DemoBody b;
  b.kind = DemoBody::Kind::Coefficients;
  b.coefficients = {m[0][0],     m[1][1],    m[2][2],    2 * m[0][1], 2 * m[0][2],
                    2 * m[1][2], -2 * mc[0], -2 * mc[1], -2 * mc[2],  mc[0] * c[0] + mc[1] * c[1] + mc[2] * c[2] - 1};
  return b;
}

/// A centre on the grid, uniformly in the box |x| <= a sqrt(h), |y| <= b sqrt(h), z in [zlo, h],
/// with the sign of F wanted (inside: F < 0, outside: F > 0).
Vector3 centre(Random& g, const Container& k, bool inside, double zlo) {
  const double xm = std::sqrt(k.a2 * k.h), ym = std::sqrt(k.b2 * k.h);
  for (;;) {
    const double x = g.uniform(-xm, xm), y = g.uniform(-ym, ym), z = g.uniform(zlo, k.h);
    if ((k.f(x, y, z) < 0) == inside) return {on_grid(x, k.grid), on_grid(y, k.grid), on_grid(z, k.grid)};
  }
}

/// Small radius l k / 512, k in [8, 64]: r in [l/64, l/8], so 2r <= a^2 (small).
Rational small_radius(Random& g, const Container& k) { return k.rl * frac(g.integer(8, 64), 512); }

/// A sphere resting against the wall (inside or outside) at a gap r 2^-j, j in [1, 12] (w < 0.45), or
/// crossing it (centre within r of the wall): the centre is rounded to the grid, so the gap is only
/// approximate -- the exact answer comes from the classifier.
DemoBody at_the_wall(Random& g, const Container& k, double w) {
  const double x0 = g.uniform(-1, 1) * std::sqrt(k.a2 * k.h) * 0.9;
  const double y0 = g.uniform(-1, 1) * std::sqrt(k.b2 * k.h) * 0.9;
  const double z0 = x0 * x0 / k.a2 + y0 * y0 / k.b2;
  double nx = 2 * x0 / k.a2, ny = 2 * y0 / k.b2, nz = -1;  // outward normal (grad F)
  const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
  nx /= len, ny /= len, nz /= len;
  const Rational r = small_radius(g, k);
  const double rd = CGAL::to_double(r);
  double dist;
  if (w < 0.45)
    dist = (g.integer(0, 1) ? 1 : -1) * rd * (1 + std::ldexp(1.0, -static_cast<int>(g.integer(1, 12))));
  else
    dist = g.uniform(-rd, rd);
  return sphere({on_grid(x0 + dist * nx, k.grid), on_grid(y0 + dist * ny, k.grid), on_grid(z0 + dist * nz, k.grid)}, r);
}

/// An exact tangency (`exact`), or a near-tangency at relative gap +-2^-j, j in [10, 40], at a point
/// of the surface whose normal has rational length (construct.hpp, tangent_point): s, t rational,
/// D = 1 - s^2 - t^2, (u, v) = (2s, 2t)/D, x0 = (u a^2/2, v b^2/2, ...), n = (u, v, -1),
/// |n| = |1 + s^2 + t^2| / |D|. Exact rationals, not doubles in general.
DemoBody near_tangent(Random& g, const Container& k, const Rational& a, const Rational& b, bool exact) {
  Rational s, t;
  do {
    s = frac(g.integer(-12, 12), 8);
    t = frac(g.integer(-12, 12), 8);
  } while (s * s + t * t == 1);
  const Rational dd = 1 - s * s - t * t, uu = 2 * s / dd, vv = 2 * t / dd;
  const Rational mm = CGAL::abs((1 + s * s + t * t) / dd);
  const Vector3 x0{uu * a * a / 2, vv * b * b / 2, uu * uu * a * a / 4 + vv * vv * b * b / 4};
  const Vector3 nn{uu, vv, Rational(-1)};
  const Rational r = small_radius(g, k);
  Rational dist = g.integer(0, 1) ? r : -r;  // > 0: outside (TE), < 0: inside (TI)
  if (!exact) {
    Rational rel = exact_rational(std::ldexp(1.0, -static_cast<int>(g.integer(10, 40))));
    if (g.integer(0, 1)) rel = -rel;
    dist = dist * (1 + rel);
  }
  return sphere({x0[0] + dist * nn[0] / mm, x0[1] + dist * nn[1] / mm, x0[2] + dist * nn[2] / mm}, r);
}

}  // namespace

struct DemoSceneGenerator::State {
  Random g;
  Container k;
  Rational a, b;
  double wall;
  State(std::uint64_t seed, const Rational& a_, const Rational& b_, double wall_)
      : g(seed), a(a_), b(b_), wall(std::clamp(wall_, 1e-9, 0.9)) {
    k.a2 = CGAL::to_double(a * a);
    k.b2 = CGAL::to_double(b * b);
    k.rl = a < b ? a * a : b * b;
    k.l = CGAL::to_double(k.rl);
    k.h = 4 * k.l;
    k.grid = std::ilogb(k.l) - 16;
  }
};

DemoSceneGenerator::DemoSceneGenerator(std::uint64_t seed, const Rational& a, const Rational& b, double wall)
    : s_(std::make_unique<State>(seed, a, b, wall)) {}

DemoSceneGenerator::~DemoSceneGenerator() = default;

DemoBody DemoSceneGenerator::next() {
  Random& g = s_->g;
  const Container& k = s_->k;
  // The mix (fractions of all bodies): exact tangencies 10^-4, not small 0.5 %, at the wall
  // `wall` (45 % resting against it, 45 % crossing it, 10 % rational near-tangencies), spilled
  // outside 8 %, and the rest bulk in the cup (80 % spheres, 20 % ellipsoids).
  const double u = g.unit();
  const double t0 = 1e-4, t1 = t0 + 0.005, t2 = t1 + s_->wall, t3 = t2 + 0.08;
  const double w = u >= t1 && u < t2 ? (u - t1) / s_->wall : 1;  // position within the wall band
  if (u >= t3) {  // bulk: small spheres and ellipsoids anywhere in the cup (some cross the wall)
    if (g.integer(0, 9) < 8) return sphere(centre(g, k, true, 0), small_radius(g, k));
    return ellipsoid(g, centre(g, k, true, 0), k);
  } else if (u >= t2) {  // spilled: outside the cup, near it
    const Vector3 c = centre(g, k, false, -k.l);
    return g.integer(0, 9) < 7 ? sphere(c, small_radius(g, k)) : ellipsoid(g, c, k);
  } else if (u >= t1 && w < 0.9) {
    return at_the_wall(g, k, w);
  } else if (u < t0 || u >= t1) {
    return near_tangent(g, k, s_->a, s_->b, u < t0);
  } else {  // t0 <= u < t1
    // Not small: radius in [l, 2l] (rho >= 4), anywhere around the container.
    const Rational r = k.rl * frac(g.integer(64, 128), 64);
    const Vector3 c = centre(g, k, g.integer(0, 1) == 1, -2 * k.l);
    return sphere(c, r);
  }
}

std::vector<DemoBody> demo_container_scene(std::size_t n, std::uint64_t seed, const Rational& a, const Rational& b,
                                           double wall) {
  DemoSceneGenerator gen(seed, a, b, wall);
  std::vector<DemoBody> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(gen.next());
  return out;
}

}  // namespace relpos
