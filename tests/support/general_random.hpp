// Random general pairs (doc/testing.md): general placements, axis-aligned ones and concentric ones,
// for every type of quadric, with small rational numbers (exact doubles or not), and tangencies built
// by hand and nudged by 10^-6 ... 10^-35.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "support/general_cases.hpp"

namespace relpos::testing {

enum class Family { General, AxisAligned, Concentric };

struct RandomPair {
  Ellipsoid e;
  Quadric q;
};

class GeneralPairs {
 public:
  explicit GeneralPairs(std::uint64_t seed) : rng_(seed) {}

  Rational number(int lo, int hi, int den) { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng_), den); }
  /// Denominators 64 (exact doubles) or 3 * 64 (not): both input paths of the filter.
  int den() { return rng_() % 3 == 0 ? 192 : 64; }
  Rational positive() { return number(8, 192, den()); }
  Vector3 point(int spread) {
    const int d = den();
    return {number(-spread * d, spread * d, d), number(-spread * d, spread * d, d), number(-spread * d, spread * d, d)};
  }
  Quaternion rotation(Family f) {
    if (f == Family::AxisAligned) return {Rational(1), Rational(0), Rational(0), Rational(0)};
    std::uniform_int_distribution<int> d(-5, 5);
    Quaternion q;
    do {
      for (Rational& x : q) x = Rational(d(rng_));
    } while (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0);
    return q;
  }

  /// One pair of the family with Q of the given type.
  RandomPair pair(Family f, QuadricType t) {
    const Vector3 c = point(2);
    const Vector3 qc = f == Family::Concentric ? c : point(2);
    const Ellipsoid e = Ellipsoid::from_axes(c, {positive(), positive(), positive()}, rotation(f));
    return {e, quadric(f, t, qc)};
  }

  Quadric quadric(Family f, QuadricType t, const Vector3& c) {
    const Quaternion r = rotation(f);
    switch (t) {
      case QuadricType::Ellipsoid:
        return Quadric::ellipsoid(c, {positive(), positive(), positive()}, r);
      case QuadricType::HyperboloidOneSheet:
        return Quadric::hyperboloid_one_sheet(c, {positive(), positive(), positive()}, r);
      case QuadricType::HyperboloidTwoSheets:
        return Quadric::hyperboloid_two_sheets(c, {positive(), positive(), positive()}, r);
      case QuadricType::Cone:
        return Quadric::cone(c, positive(), positive(), r);
      case QuadricType::EllipticParaboloid:
        return Quadric::elliptic_paraboloid(c, positive(), positive(), r);
      case QuadricType::HyperbolicParaboloid:
        return Quadric::hyperbolic_paraboloid(c, positive(), positive(), r);
      case QuadricType::EllipticCylinder:
        return Quadric::elliptic_cylinder(c, positive(), positive(), r);
      case QuadricType::HyperbolicCylinder:
        return Quadric::hyperbolic_cylinder(c, positive(), positive(), r);
      case QuadricType::ParabolicCylinder:
        return Quadric::parabolic_cylinder(c, positive(), r);
      case QuadricType::Slab: {
        Vector3 n = f == Family::AxisAligned ? Vector3{Rational(0), Rational(0), Rational(1)} : point(1);
        if (n[0] == 0 && n[1] == 0 && n[2] == 0) n[2] = Rational(1);
        Rational mid(0);
        for (std::size_t i = 0; i < 3; ++i) mid += n[i] * c[i];
        const Rational w = positive();
        return Quadric::slab(n, mid - w, mid + w);
      }
      case QuadricType::HalfSpace: {
        Vector3 n = f == Family::AxisAligned ? Vector3{Rational(0), Rational(0), Rational(1)} : point(1);
        if (n[0] == 0 && n[1] == 0 && n[2] == 0) n[2] = Rational(1);
        Rational off(0);
        for (std::size_t i = 0; i < 3; ++i) off += n[i] * c[i];
        return Quadric::half_space(n, off);
      }
    }
    throw std::logic_error("no such type");
  }

  std::mt19937_64& rng() { return rng_; }

 private:
  std::mt19937_64 rng_;
};

/// A tangency built by hand and nudged: the ball of a tangent constructed case with its squared
/// radius multiplied by (1 + s 10^-k), s = +-1, and the position that follows by construction
/// (growing a ball that touches from outside makes it cross, shrinking frees it; and so on).
struct Nudged {
  std::string name;
  Matrix4 e;
  Quadric q;
  QuadricPosition expected;
};

/// exponents: the k of 10^-k (general_bench --edge sweeps more of them).
inline std::vector<Nudged> nudged_tangencies(const std::vector<int>& exponents = {6, 12, 20, 35}) {
  using P = QuadricPosition;
  std::vector<Nudged> out;
  for (const GeneralCase& k : constructed_cases()) {
    if (k.expected != P::TE && k.expected != P::TI && k.expected != P::TO) continue;
    if (k.e(0, 0) != 1 || k.e(1, 1) != 1 || k.e(2, 2) != 1 || k.e(0, 1) != 0 || k.e(0, 2) != 0 || k.e(1, 2) != 0)
      continue;  // balls only: their radius is the knob
    for (int exponent : exponents) {
      for (int s : {-1, 1}) {
        Rational eps(1);
        for (int i = 0; i < exponent; ++i) eps /= 10;
        // |x - c|^2 - r2 with r2 = |c|^2 - e33: r2 (1 + s eps).
        Rational c2(0);
        for (int i = 0; i < 3; ++i) c2 += k.e(i, 3) * k.e(i, 3);
        const Rational r2 = c2 - k.e(3, 3);
        Matrix4 m = k.e;
        m(3, 3) = c2 - r2 * (1 + s * eps);
        // Growing (s > 0): a ball touching from outside (TE) crosses, one inside (TI) crosses, one
        // holding the quadric inside (TO) holds it strictly (O). Shrinking: E, I, C.
        P expected = P::C;
        if (k.expected == P::TE) expected = s > 0 ? P::C : P::E;
        if (k.expected == P::TI) expected = s > 0 ? P::C : P::I;
        if (k.expected == P::TO) expected = s > 0 ? P::O : P::C;
        out.push_back(
            {k.name + " nudged by " + (s > 0 ? "+" : "-") + "1e-" + std::to_string(exponent), m, k.q, expected});
      }
    }
  }
  return out;
}

}  // namespace relpos::testing
