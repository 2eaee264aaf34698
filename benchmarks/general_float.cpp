// The float baselines of general_float.hpp: plain doubles, no certification, no -frounding-math.
#include "general_float.hpp"

#include <algorithm>
#include <cmath>

#include "algebra/sturm_habicht_quartic.hpp"
#include "general/pencil.hpp"

namespace bench {

using relpos::QuadricPosition;
using relpos::QuadricType;

namespace {

struct View {
  const DoubleMatrix4& a;
  double operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

double horner(const double* c, int n, double x) {
  double v = c[n];
  for (int i = n - 1; i >= 0; --i) v = v * x + c[i];
  return v;
}

int sign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

/// Sign variations of a sequence of signs, zeros skipped.
template <int N>
int variations(const int (&s)[N], int n) {
  int count = 0, last = 0;
  for (int i = 0; i < n; ++i) {
    if (s[i] == 0) continue;
    if (last != 0 && s[i] != last) ++count;
    last = s[i];
  }
  return count;
}

/// The classical Sturm sequence of a polynomial of degree n <= 4 in doubles: p0 = p, p1 = p',
/// p_{i+1} = -(p_{i-1} mod p_i), down to a constant (a leading coefficient that is exactly 0 lowers
/// the degree, as a float code's remainder loop would).
struct Sturm {
  double c[5][5] = {};
  int deg[5] = {};
  int len = 0;

  Sturm(const double* p, int n) {
    while (n > 0 && p[n] == 0) --n;
    for (int i = 0; i <= n; ++i) c[0][i] = p[i];
    deg[0] = n;
    len = 1;
    if (n == 0) return;
    for (int i = 1; i <= n; ++i) c[1][i - 1] = i * p[i];
    deg[1] = n - 1;
    len = 2;
    while (deg[len - 1] > 0 && len < 5) {
      double r[5];
      const int da = deg[len - 2], db = deg[len - 1];
      for (int i = 0; i <= da; ++i) r[i] = c[len - 2][i];
      const double* b = c[len - 1];
      for (int i = da - db; i >= 0; --i) {
        const double qi = r[i + db] / b[db];
        for (int j = 0; j <= db; ++j) r[i + j] -= qi * b[j];
      }
      int dr = db - 1;
      while (dr >= 0 && r[dr] == 0) --dr;
      if (dr < 0) break;  // p_{i-1} a multiple of p_i: the chain ends at their gcd
      for (int i = 0; i <= dr; ++i) c[len][i] = -r[i];
      deg[len++] = dr;
    }
  }
  int at(double x) const {
    int s[5];
    for (int i = 0; i < len; ++i) s[i] = sign(horner(c[i], deg[i], x));
    return variations(s, len);
  }
  int at_infinity(bool plus) const {
    int s[5];
    for (int i = 0; i < len; ++i) s[i] = sign(c[i][deg[i]]) * (!plus && deg[i] % 2 ? -1 : 1);
    return variations(s, len);
  }
};

/// The largest root of the real-rooted cubic d (positive leading coefficient): Newton from the
/// Samuelson bound, as the library's filter does (doc/math.md §17).
double largest_root(const double* d) {
  const double s1 = -d[2] / d[3], s2 = s1 * s1 - 2 * d[1] / d[3];
  const double mean = s1 / 3, var = std::max(0.0, s2 / 3 - mean * mean);
  double x = mean + std::sqrt(2 * var) * (1 + 0x1p-20) + std::fabs(mean) * 0x1p-40 + 0x1p-1000;
  for (int i = 0; i < 100; ++i) {
    const double v = horner(d, 3, x), dv = (3 * d[3] * x + 2 * d[2]) * x + d[1];
    if (!(dv > 0)) break;
    const double step = v / dv;
    if (!(step > 0)) break;
    x -= step;
    if (step <= std::fabs(x) * 0x1p-40) break;
  }
  return x;
}

/// 4 - rank Q: the multiplicity of the root 0 of f for each type (doc/math.md §17's table, k).
int zero_multiplicity(QuadricType t) {
  switch (t) {
    case QuadricType::Cone:
    case QuadricType::EllipticCylinder:
    case QuadricType::HyperbolicCylinder:
    case QuadricType::ParabolicCylinder:
      return 1;
    case QuadricType::Slab:
    case QuadricType::HalfSpace:
      return 2;
    default:
      return 0;
  }
}

/// Whether the min side's interval starts at r3 > 0 rather than at 0 (B has an eigenvalue <= 0 and a
/// negative one after the normalization: §17's table, t_lo).
bool min_end_positive(QuadricType t) {
  return t == QuadricType::HyperboloidOneSheet || t == QuadricType::HyperboloidTwoSheets || t == QuadricType::Cone ||
         t == QuadricType::HyperbolicParaboloid || t == QuadricType::HyperbolicCylinder;
}

}  // namespace

QuadricPosition pencil_float(const DoubleMatrix4& e, const DoubleMatrix4& q, QuadricType type) {
  const relpos::Quartic<double> f = relpos::characteristic_polynomial_lanes(e, q);
  const relpos::detail::general::Cubic<double> d = relpos::detail::general::pencil_cubic<double>(View{e}, View{q});
  const int k = zero_multiplicity(type);
  // Var(x) and Var(+-oo) of f / t^k: the Sturm–Habicht sequence for the quartic (the cheapest),
  // the remainder sequence for the cubic and the quadratic left by a type with k > 0.
  double g2[3] = {}, g1[2] = {}, g0 = 0, lead = 1;
  const double fp[4] = {f[1], 2 * f[2], 3 * f[3], 4 * f[4]};
  if (k == 0) {
    relpos::detail::sturm_habicht_quartic_g2_g1(f[0], f[1], f[2], f[3], f[4], g2, g1);
    const double inv_i = 12 * f[0] * f[4] - 3 * f[1] * f[3] + f[2] * f[2];
    const double inv_j = 72 * f[0] * f[2] * f[4] + 9 * f[1] * f[2] * f[3] - 27 * f[0] * f[3] * f[3] -
                         27 * f[4] * f[1] * f[1] - 2 * f[2] * f[2] * f[2];
    g0 = 4 * inv_i * inv_i * inv_i - inv_j * inv_j;  // 27 Disc(f)
    lead = f[4] > 0 ? 1 : -1;
  }
  const Sturm low(f.data() + k, k == 0 ? 0 : 4 - k);  // not built for the quartic
  auto var_at = [&](double x) {
    if (k != 0) return low.at(x);
    const int s[5] = {sign(horner(f.data(), 4, x)), sign(horner(fp, 3, x)),
                      sign(lead * ((g2[0] * x + g2[1]) * x + g2[2])), sign(lead * (g1[0] * x + g1[1])),
                      sign(lead * g0)};
    return variations(s, 5);
  };
  auto var_inf = [&](bool plus) {
    if (k != 0) return low.at_infinity(plus);
    const double v[5] = {f[4], fp[3], lead * g2[0], lead * g1[0], lead * g0};
    int s[5];
    for (int i = 0; i < 5; ++i) s[i] = sign(v[i]) * (!plus && (4 - i) % 2 ? -1 : 1);
    return variations(s, 5);
  };
  // The sides in the order of the decision, each only when the previous one has no root, each root
  // of D found only when its side is reached.
  const double t_lo = min_end_positive(type) ? largest_root(d.data()) : 0;
  const int v_plus = var_inf(true), v_minus = var_inf(false);
  if (var_at(t_lo) - v_plus > 0) return QuadricPosition::E;
  const double mirrored[4] = {-d[0], d[1], -d[2], d[3]};  // D(-x), leading coefficient kept positive
  const double t_hi = type == QuadricType::HalfSpace ? 0 : -largest_root(mirrored);
  if (v_minus - var_at(t_hi) > 0) return QuadricPosition::I;
  if (type == QuadricType::Ellipsoid && var_at(largest_root(d.data())) - var_at(0) > 0) return QuadricPosition::O;
  return QuadricPosition::C;
}

bool wwk_separated(const DoubleMatrix4& e, const DoubleMatrix4& q) {
  // det(Q + tE) by cofactor expansion along the first row, every entry q_ij + t e_ij.
  using Lin = std::array<double, 2>;
  auto entry = [&](int i, int j) {
    return Lin{q[static_cast<std::size_t>(4 * i + j)], e[static_cast<std::size_t>(4 * i + j)]};
  };
  double f[5] = {};
  for (int c = 0; c < 4; ++c) {
    int cols[3], n = 0;
    for (int j = 0; j < 4; ++j)
      if (j != c) cols[n++] = j;
    // The 3x3 minor of rows 1..3 and the columns cols: a cubic.
    double m[4] = {};
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, g = (a + 2) % 3;
      const Lin x = entry(1, cols[a]), y1 = entry(2, cols[b]), y2 = entry(3, cols[g]), z1 = entry(2, cols[g]),
                z2 = entry(3, cols[b]);
      const double p[3] = {y1[0] * y2[0] - z1[0] * z2[0], y1[0] * y2[1] + y1[1] * y2[0] - z1[0] * z2[1] - z1[1] * z2[0],
                           y1[1] * y2[1] - z1[1] * z2[1]};
      m[0] += x[0] * p[0];
      m[1] += x[0] * p[1] + x[1] * p[0];
      m[2] += x[0] * p[2] + x[1] * p[1];
      m[3] += x[1] * p[2];
    }
    const Lin x = entry(0, c);
    const double s = c % 2 ? -1 : 1;
    for (int i = 0; i < 4; ++i) {
      f[i] += s * x[0] * m[i];
      f[i + 1] += s * x[1] * m[i];
    }
  }
  const Sturm chain(f, 4);
  return chain.at(0) - chain.at_infinity(true) > 0;
}

}  // namespace bench
