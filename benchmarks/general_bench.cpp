// general_bench: an ellipsoid against another ellipsoid (and the other quadrics) on relpos's general
// path against the float decision in the same run (doc/performance.md, "General quadrics").
//
// The float decision is the decision of math.md §16–§17 in plain doubles, nothing certified: the
// characteristic quartic f = det(Q + t E) (the library's fastest double code, two terms at a time in
// vector lanes) and the cubic D = det(B + t M), the extreme roots of D by Newton, and the sign rule --
// the Sturm–Habicht sign variations of f at those roots, at 0 and at +-oo, the sides taken in the
// order of the decision and each only when the previous one is empty. relpos's decide_position runs
// the same formulas with certified bounds (and the exact stage when they cannot certify).
//
// Usage: general_bench [pairs] [rounds] [prebuilt]   (defaults 20000, 7; `prebuilt`: skip from_doubles)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "algebra/sturm_habicht_quartic.hpp"
#include "general/pencil.hpp"
#include "relpos/general_classify.hpp"

using namespace relpos;

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

/// The largest root of the real-rooted cubic d (positive leading coefficient): Newton from the
/// Samuelson bound, as the filter does.
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

/// The float decision for two ellipsoids (E, TE never told apart from E, C by a float: no tangency
/// is ever reported, as a float code would not).
QuadricPosition float_decision(const DoubleMatrix4& e, const DoubleMatrix4& q) {
  const Quartic<double> f = characteristic_polynomial_lanes(e, q);
  const general::Cubic<double> d = general::pencil_cubic<double>(View{e}, View{q});
  double g2[3], g1[2];
  detail::sturm_habicht_quartic_g2_g1(f[0], f[1], f[2], f[3], f[4], g2, g1);
  const double inv_i = 12 * f[0] * f[4] - 3 * f[1] * f[3] + f[2] * f[2];
  const double inv_j = 72 * f[0] * f[2] * f[4] + 9 * f[1] * f[2] * f[3] - 27 * f[0] * f[3] * f[3] -
                       27 * f[4] * f[1] * f[1] - 2 * f[2] * f[2] * f[2];
  const double g0[1] = {4 * inv_i * inv_i * inv_i - inv_j * inv_j};  // 27 Disc(f)
  const double fp[4] = {f[1], 2 * f[2], 3 * f[3], 4 * f[4]};
  const double lead = f[4] > 0 ? 1 : -1;
  auto var_at = [&](double x) {
    const double s[5] = {horner(f.data(), 4, x), horner(fp, 3, x), lead * ((g2[0] * x + g2[1]) * x + g2[2]),
                         lead * (g1[0] * x + g1[1]), lead * g0[0]};
    int n = 0, last = 0;
    for (double v : s) {
      const int sg = v > 0 ? 1 : (v < 0 ? -1 : 0);
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++n;
      last = sg;
    }
    return n;
  };
  auto var_inf = [&](bool plus) {
    const double s[5] = {f[4], fp[3], lead * g2[0], lead * g1[0], lead * g0[0]};
    const int deg[5] = {4, 3, 2, 1, 0};
    int n = 0, last = 0;
    for (int i = 0; i < 5; ++i) {
      int sg = s[i] > 0 ? 1 : (s[i] < 0 ? -1 : 0);
      if (!plus && deg[i] % 2 == 1) sg = -sg;
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++n;
      last = sg;
    }
    return n;
  };
  // The sides in the order of the decision, each only when the previous one has no root.
  const int v0 = var_at(0), v_plus = var_inf(true), v_minus = var_inf(false);
  if (v0 - v_plus > 0) return QuadricPosition::E;
  const double mirrored[4] = {-d[0], d[1], -d[2], d[3]};  // D(-x), leading coefficient kept positive
  const double r1 = -largest_root(mirrored);
  if (v_minus - var_at(r1) > 0) return QuadricPosition::I;
  if (var_at(largest_root(d.data())) - v0 > 0) return QuadricPosition::O;
  return QuadricPosition::C;
}

/// A random ordinary ellipsoid as doubles: semi-axes in [0.2, 2], a random rotation, a centre in the
/// cube [-2, 2]^3 (the two bodies overlap, nest or lie apart).
DoubleMatrix4 random_ellipsoid(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ax(0.2, 2.0), c(-2.0, 2.0), qd(-1.0, 1.0);
  double w = qd(rng), x = qd(rng), y = qd(rng), z = qd(rng);
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  const double a[3] = {ax(rng), ax(rng), ax(rng)};
  const double centre[3] = {c(rng), c(rng), c(rng)};
  DoubleMatrix4 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += r[i][k] * r[j][k] / (a[k] * a[k]);
      m[static_cast<std::size_t>(4 * i + j)] = s;
    }
  for (int i = 0; i < 3; ++i) {
    double s = 0;
    for (int j = 0; j < 3; ++j) s += m[static_cast<std::size_t>(4 * i + j)] * centre[j];
    m[static_cast<std::size_t>(4 * i + 3)] = m[static_cast<std::size_t>(12 + i)] = -s;
  }
  double s = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += centre[i] * m[static_cast<std::size_t>(4 * i + j)] * centre[j];
  m[15] = s;
  for (int i = 0; i < 3; ++i)  // exactly symmetric
    for (int j = 0; j < i; ++j) m[static_cast<std::size_t>(4 * i + j)] = m[static_cast<std::size_t>(4 * j + i)];
  return m;
}

/// The thread's CPU time of f (not wall-clock time: on a shared machine, the time the thread was
/// descheduled would count for whichever loop it fell in).
template <class F>
double seconds(F&& f) {
  timespec t0, t1;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
  f();
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
  return static_cast<double>(t1.tv_sec - t0.tv_sec) + 1e-9 * static_cast<double>(t1.tv_nsec - t0.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 20000;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 7;
  const bool from = !(argc > 3 && std::string(argv[3]) == "prebuilt");
  std::mt19937_64 rng(36);
  std::vector<DoubleMatrix4> em, qm;
  std::vector<Ellipsoid> es;
  std::vector<Quadric> qs;
  for (std::size_t i = 0; i < n; ++i) {
    em.push_back(random_ellipsoid(rng));
    qm.push_back(random_ellipsoid(rng));
    es.push_back(Ellipsoid::from_doubles(em.back()));
    qs.push_back(Quadric::from_doubles(qm.back()));
  }
  // Answers: relpos's against the exact stage (must agree) and the float decision's error rate.
  std::size_t filtered = 0, float_wrong = 0, counts[8] = {};
  for (std::size_t i = 0; i < n; ++i) {
    const QuadricVerdict v = decide_position(es[i], qs[i]), x = decide_position_exact(es[i], qs[i]);
    if (v.position != x.position) {
      std::printf("MISMATCH at pair %zu\n", i);
      return 1;
    }
    filtered += v.stage == QuadricStage::Filter;
    float_wrong += float_decision(em[i], qm[i]) != x.position;
    ++counts[static_cast<int>(x.position)];
  }
  std::printf("pairs %zu: I %zu, C %zu, E %zu, O %zu (others %zu); filter decided %zu; float decision wrong on %zu\n",
              n, counts[0], counts[2], counts[4], counts[5], counts[1] + counts[3] + counts[6] + counts[7], filtered,
              float_wrong);
  std::vector<double> t_float, t_decide, t_from;
  volatile int sink = 0;
  for (int r = 0; r < rounds; ++r) {
    t_float.push_back(seconds([&] {
      int s = 0;
      for (std::size_t i = 0; i < n; ++i) s += static_cast<int>(float_decision(em[i], qm[i]));
      sink = sink + s;
    }));
    t_decide.push_back(seconds([&] {
      int s = 0;
      for (std::size_t i = 0; i < n; ++i) s += static_cast<int>(decide_position(es[i], qs[i]).position);
      sink = sink + s;
    }));
    if (from)
      t_from.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i = 0; i < n; ++i)
          s += static_cast<int>(decide_position(Ellipsoid::from_doubles(em[i]), Quadric::from_doubles(qm[i])).position);
        sink = sink + s;
      }));
  }
  // The same per position (pairs of one position timed together, the float decision on the same pairs).
  for (QuadricPosition p : {QuadricPosition::E, QuadricPosition::C}) {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < n; ++i)
      if (decide_position(es[i], qs[i]).position == p) idx.push_back(i);
    std::vector<double> tf, td;
    for (int r = 0; r < rounds; ++r) {
      tf.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i : idx) s += static_cast<int>(float_decision(em[i], qm[i]));
        sink = sink + s;
      }));
      td.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i : idx) s += static_cast<int>(decide_position(es[i], qs[i]).position);
        sink = sink + s;
      }));
    }
    const double a = median(tf) / static_cast<double>(idx.size()) * 1e9,
                 b = median(td) / static_cast<double>(idx.size()) * 1e9;
    std::printf("  %s pairs (%zu): float %.1f ns, decide_position %.1f ns (%.2fx)\n", to_string(p).c_str(), idx.size(),
                a, b, b / a);
  }
  const double f = median(t_float) / n * 1e9, d = median(t_decide) / n * 1e9;
  const double fr = from ? median(t_from) / n * 1e9 : 0;
  std::printf("ellipsoid-ellipsoid, ns of thread CPU time a pair (median of %d rounds, same run):\n", rounds);
  std::printf("  float decision (quartic, cubic, sign rule; nothing certified)  %8.1f\n", f);
  std::printf("  decide_position(e, q), prebuilt objects                        %8.1f  (%.2fx)\n", d, d / f);
  if (from)
    std::printf("  from_doubles + decide_position                                 %8.1f  (%.2fx)\n", fr, fr / f);
  // Scaled matrices: the same pairs with E times 3 and Q times 1/3 (rationals that are not doubles:
  // the filter reads enclosures) against E times 10^300 and Q times 10^-300, on the filter and on the
  // exact stage (each matrix's own primitive integer form: the same integers, math.md §17).
  {
    const std::size_t m = std::min<std::size_t>(n, 2000);
    Rational big(1);
    for (int i = 0; i < 300; ++i) big *= 10;
    auto scaled = [](const DoubleMatrix4& d, const Rational& s) {
      Matrix4 out;
      for (std::size_t i = 0; i < 16; ++i) out.a[i] = Rational(d[i]) * s;
      return out;
    };
    std::vector<Ellipsoid> e3, eb;
    std::vector<Quadric> q3, qb;
    for (std::size_t i = 0; i < m; ++i) {
      e3.push_back(Ellipsoid::from_matrix(scaled(em[i], Rational(3))));
      q3.push_back(Quadric::from_matrix(scaled(qm[i], Rational(1, 3))));
      eb.push_back(Ellipsoid::from_matrix(scaled(em[i], big)));
      qb.push_back(Quadric::from_matrix(scaled(qm[i], Rational(1) / big)));
    }
    for (std::size_t i = 0; i < m; ++i)
      if (decide_position(e3[i], q3[i]).position != decide_position(eb[i], qb[i]).position) {
        std::printf("MISMATCH (scaled) at pair %zu\n", i);
        return 1;
      }
    std::vector<double> t3, tb, x3, xb;
    for (int r = 0; r < rounds; ++r) {
      t3.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i = 0; i < m; ++i) s += static_cast<int>(decide_position(e3[i], q3[i]).position);
        sink = sink + s;
      }));
      tb.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i = 0; i < m; ++i) s += static_cast<int>(decide_position(eb[i], qb[i]).position);
        sink = sink + s;
      }));
      if (r < 3) {
        x3.push_back(seconds([&] {
          int s = 0;
          for (std::size_t i = 0; i < m; ++i) s += static_cast<int>(decide_position_exact(e3[i], q3[i]).position);
          sink = sink + s;
        }));
        xb.push_back(seconds([&] {
          int s = 0;
          for (std::size_t i = 0; i < m; ++i) s += static_cast<int>(decide_position_exact(eb[i], qb[i]).position);
          sink = sink + s;
        }));
      }
    }
    const double k = 1e9 / static_cast<double>(m);
    std::printf("scaled matrices (%zu pairs as rationals), ns a pair:\n", m);
    std::printf("  decide_position, E x 3, Q x 1/3          %10.1f\n", median(t3) * k);
    std::printf("  decide_position, E x 1e300, Q x 1e-300   %10.1f  (%.2fx)\n", median(tb) * k,
                median(tb) / median(t3));
    std::printf("  exact stage, E x 3, Q x 1/3              %10.1f\n", median(x3) * k);
    std::printf("  exact stage, E x 1e300, Q x 1e-300       %10.1f  (%.2fx)\n", median(xb) * k,
                median(xb) / median(x3));
  }
  return 0;
}
