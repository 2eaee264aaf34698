// general_bench: an ellipsoid against another ellipsoid (and the other quadrics) on relpos's general
// path against the float decisions in the same run (doc/performance.md, "General quadrics").
//
// The float decisions are those of general_float.hpp, nothing certified: the decision of math.md
// §16–§17 in plain doubles (the characteristic quartic f = det(Q + t E) in the library's vector lanes,
// the cubic D = det(B + t M), the extreme roots of D by Newton, and the sign rule -- Sturm sequence
// variations of f at those roots, at 0 and at +-oo, the sides taken in the order of the decision and
// each only when the previous one is empty), and Wang–Wang–Kim's separation test in doubles for two
// ellipsoids. relpos's decide_position runs the same formulas with certified bounds (and the exact
// stage when they cannot certify).
//
// Usage: general_bench [pairs] [rounds] [prebuilt]   (defaults 20000, 7; `prebuilt`: skip from_doubles)
//        general_bench --edge OUT [maps]             (the error rates near tangency -> OUT/general_edge.csv)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "general/decision.hpp"
#include "general_float.hpp"
#include "oracle/nearest.hpp"
#include "relpos/general_classify.hpp"
#include "support/general_random.hpp"

using namespace relpos;
using bench::pencil_float;
using bench::wwk_separated;

namespace {

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

DoubleMatrix4 doubles_of(const Matrix4& m) {
  DoubleMatrix4 d{};
  for (std::size_t i = 0; i < 16; ++i) d[i] = oracle::nearest_double(m.a[i]);
  return d;
}

/// H^T Q H for x = L u + t, H = [[L, t], [0, 1]]: the solid's preimage, the same type (an affine
/// congruence). With dyadic L and t and a quadric of small dyadic entries, every entry is a double.
Matrix4 congruent(const Matrix4& q, const Matrix3& l, const Vector3& t) {
  Matrix4 h;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) h(i, j) = l(i, j);
    h(i, 3) = t[static_cast<std::size_t>(i)];
  }
  h(3, 3) = Rational(1);
  Matrix4 qh, out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) qh(i, j) += q(i, k) * h(k, j);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) out(i, j) += h(k, i) * qh(k, j);
  return out;
}

/// A random dyadic affine map: entries of L in {-8, ..., 8} / 8 with |det L| >= 1/4, t in [-2, 2] / 8ths.
void dyadic_map(std::mt19937_64& rng, Matrix3& l, Vector3& t) {
  std::uniform_int_distribution<int> d(-8, 8), td(-16, 16);
  do {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) l(i, j) = Rational(d(rng), 8);
  } while (CGAL::abs(l(0, 0) * (l(1, 1) * l(2, 2) - l(1, 2) * l(2, 1)) -
                     l(0, 1) * (l(1, 0) * l(2, 2) - l(1, 2) * l(2, 0)) +
                     l(0, 2) * (l(1, 0) * l(2, 1) - l(1, 1) * l(2, 0))) < Rational(1, 4));
  for (Rational& x : t) x = Rational(td(rng), 8);
}

/// The canonical quadric of each type (axes 1, centre 0).
Quadric canonical(QuadricType t) {
  const Vector3 o{Rational(0), Rational(0), Rational(0)}, ones{Rational(1), Rational(1), Rational(1)};
  const Rational one(1);
  switch (t) {
    case QuadricType::Ellipsoid:
      return Quadric::ellipsoid(o, ones);
    case QuadricType::HyperboloidOneSheet:
      return Quadric::hyperboloid_one_sheet(o, ones);
    case QuadricType::HyperboloidTwoSheets:
      return Quadric::hyperboloid_two_sheets(o, ones);
    case QuadricType::Cone:
      return Quadric::cone(o, one, one);
    case QuadricType::EllipticParaboloid:
      return Quadric::elliptic_paraboloid(o, one, one);
    case QuadricType::HyperbolicParaboloid:
      return Quadric::hyperbolic_paraboloid(o, one, one);
    case QuadricType::EllipticCylinder:
      return Quadric::elliptic_cylinder(o, one, one);
    case QuadricType::HyperbolicCylinder:
      return Quadric::hyperbolic_cylinder(o, one, one);
    case QuadricType::ParabolicCylinder:
      return Quadric::parabolic_cylinder(o, one);
    case QuadricType::Slab:
      return Quadric::slab({Rational(0), Rational(0), one}, -one, one);
    case QuadricType::HalfSpace:
      return Quadric::half_space({Rational(0), Rational(0), one}, Rational(0));
  }
  return Quadric::sphere(o, one);
}

/// general_bench --edge OUT [maps]: the tangencies of tests/support/general_random.hpp (balls touching
/// every type of quadric, known by construction) nudged by 10^-k, each under `maps` random rational
/// congruences (rotations from integer quaternions, scalings, reflections): relpos decides the exact
/// matrices, the float methods read their nearest doubles. Counts of wrong answers per type and k.
int edge(const std::string& out, int maps) {
  const std::vector<int> ks = {2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 25, 35};
  std::mt19937_64 rng(3636);
  struct Row {
    long n = 0, relpos_wrong = 0, pencil_wrong = 0, wwk_wrong = 0;
  };
  std::vector<std::vector<Row>> rows(general::kAllQuadricTypes.size(), std::vector<Row>(ks.size()));
  for (std::size_t ki = 0; ki < ks.size(); ++ki)
    for (const testing::Nudged& k : testing::nudged_tangencies({ks[ki]})) {
      const std::size_t ti = static_cast<std::size_t>(
          std::find(general::kAllQuadricTypes.begin(), general::kAllQuadricTypes.end(), k.q.type()) -
          general::kAllQuadricTypes.begin());
      for (int m = 0; m < maps; ++m) {
        const testing::AffineMap map = testing::random_map(rng, false);
        const Quadric qe = Quadric::from_map(Quadric::from_matrix(k.e), map.l, map.t);
        const Quadric qq = Quadric::from_map(k.q, map.l, map.t);
        const Ellipsoid e = Ellipsoid::from_matrix(qe.matrix());
        const DoubleMatrix4 ed = doubles_of(qe.matrix()), qd = doubles_of(qq.matrix());
        Row& r = rows[ti][ki];
        ++r.n;
        r.relpos_wrong += decide_position(e, qq).position != k.expected;
        r.pencil_wrong += pencil_float(ed, qd, qq.type()) != k.expected;
        r.wwk_wrong += wwk_separated(ed, qd) != (k.expected == QuadricPosition::E);
      }
    }
  std::ofstream csv(out + "/general_edge.csv");
  csv << "type,k,n,relpos_wrong,pencil_float_wrong,wwk_wrong\n";
  for (std::size_t ti = 0; ti < rows.size(); ++ti)
    for (std::size_t ki = 0; ki < ks.size(); ++ki) {
      const Row& r = rows[ti][ki];
      if (r.n == 0) continue;
      csv << to_string(general::kAllQuadricTypes[ti]) << "," << ks[ki] << "," << r.n << "," << r.relpos_wrong << ","
          << r.pencil_wrong << "," << r.wwk_wrong << "\n";
      std::printf("%-24s 1e-%-3d n %4ld  relpos wrong %ld  pencil float wrong %4ld  WWK wrong %4ld\n",
                  to_string(general::kAllQuadricTypes[ti]).c_str(), ks[ki], r.n, r.relpos_wrong, r.pencil_wrong,
                  r.wwk_wrong);
    }
  long wrong = 0;
  for (const auto& t : rows)
    for (const Row& r : t) wrong += r.relpos_wrong;
  return wrong == 0 ? 0 : 1;
}

/// Ordinary pairs per type: the canonical quadric and the unit ball, each under its own dyadic affine
/// map (every entry a double): float decisions and decide_position in alternating rounds.
void per_type(std::size_t n, int rounds) {
  std::mt19937_64 rng(3600);
  std::printf("per type, %zu ordinary pairs each, ns of thread CPU time a pair (median of %d rounds, same run):\n", n,
              rounds);
  std::printf("  %-24s %8s %8s %8s %7s %7s  %s\n", "type", "float", "WWK", "relpos", "/float", "/WWK",
              "positions; float wrong, WWK wrong, filter decided");
  for (QuadricType type : general::kAllQuadricTypes) {
    const Quadric base = canonical(type);
    const Matrix4 ball = Quadric::sphere({Rational(0), Rational(0), Rational(0)}, Rational(1)).matrix();
    std::vector<DoubleMatrix4> em, qm;
    std::vector<Ellipsoid> es;
    std::vector<Quadric> qs;
    while (em.size() < n) {
      Matrix3 l;
      Vector3 t;
      dyadic_map(rng, l, t);
      const Matrix4 q = congruent(base.matrix(), l, t);
      dyadic_map(rng, l, t);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) l(i, j) *= 2;  // balls of radius about 1/2
      const Matrix4 e = congruent(ball, l, t);
      const Quadric qq = Quadric::from_matrix(q);
      if (qq.type() != type) continue;
      em.push_back(doubles_of(e));
      qm.push_back(doubles_of(q));
      es.push_back(Ellipsoid::from_doubles(em.back()));
      qs.push_back(Quadric::from_doubles(qm.back()));
    }
    std::size_t counts[8] = {}, float_wrong = 0, wwk_wrong = 0, filtered = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const QuadricVerdict v = decide_position(es[i], qs[i]);
      ++counts[static_cast<int>(v.position)];
      filtered += v.stage == QuadricStage::Filter;
      float_wrong += pencil_float(em[i], qm[i], type) != v.position;
      wwk_wrong += wwk_separated(em[i], qm[i]) != (v.position == QuadricPosition::E);
    }
    std::vector<double> tf, tw, td;
    volatile int sink = 0;
    for (int r = 0; r < rounds; ++r) {
      tf.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i = 0; i < n; ++i) s += static_cast<int>(pencil_float(em[i], qm[i], type));
        sink = sink + s;
      }));
      tw.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i = 0; i < n; ++i) s += wwk_separated(em[i], qm[i]);
        sink = sink + s;
      }));
      td.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i = 0; i < n; ++i) s += static_cast<int>(decide_position(es[i], qs[i]).position);
        sink = sink + s;
      }));
    }
    const double k = 1e9 / static_cast<double>(n), f = median(tf) * k, w = median(tw) * k, d = median(td) * k;
    std::string pos;
    for (int p = 0; p < 8; ++p)
      if (counts[p]) pos += to_string(static_cast<QuadricPosition>(p)) + " " + std::to_string(counts[p]) + " ";
    std::printf("  %-24s %8.1f %8.1f %8.1f %6.2fx %6.2fx  %s; %zu, %zu, %zu\n", to_string(type).c_str(), f, w, d, d / f,
                d / w, pos.c_str(), float_wrong, wwk_wrong, filtered);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 2 && std::string(argv[1]) == "--edge") return edge(argv[2], argc > 3 ? std::atoi(argv[3]) : 6);
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
  const QuadricType ell = QuadricType::Ellipsoid;
  // Answers: relpos's against the exact stage (must agree) and the float decisions' error rates.
  std::size_t filtered = 0, float_wrong = 0, wwk_wrong = 0, counts[8] = {};
  for (std::size_t i = 0; i < n; ++i) {
    const QuadricVerdict v = decide_position(es[i], qs[i]), x = decide_position_exact(es[i], qs[i]);
    if (v.position != x.position) {
      std::printf("MISMATCH at pair %zu\n", i);
      return 1;
    }
    filtered += v.stage == QuadricStage::Filter;
    float_wrong += pencil_float(em[i], qm[i], ell) != x.position;
    wwk_wrong += wwk_separated(em[i], qm[i]) != (x.position == QuadricPosition::E);
    ++counts[static_cast<int>(x.position)];
  }
  std::printf(
      "pairs %zu: I %zu, C %zu, E %zu, O %zu (others %zu); filter decided %zu; float decision wrong on %zu, "
      "WWK wrong on %zu\n",
      n, counts[0], counts[2], counts[4], counts[5], counts[1] + counts[3] + counts[6] + counts[7], filtered,
      float_wrong, wwk_wrong);
  std::vector<double> t_float, t_wwk, t_decide, t_from;
  volatile int sink = 0;
  for (int r = 0; r < rounds; ++r) {
    t_float.push_back(seconds([&] {
      int s = 0;
      for (std::size_t i = 0; i < n; ++i) s += static_cast<int>(pencil_float(em[i], qm[i], ell));
      sink = sink + s;
    }));
    t_wwk.push_back(seconds([&] {
      int s = 0;
      for (std::size_t i = 0; i < n; ++i) s += wwk_separated(em[i], qm[i]);
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
  // The same per position (pairs of one position timed together, the float decisions on the same pairs).
  for (QuadricPosition p : {QuadricPosition::E, QuadricPosition::C}) {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < n; ++i)
      if (decide_position(es[i], qs[i]).position == p) idx.push_back(i);
    std::vector<double> tf, tw, td;
    for (int r = 0; r < rounds; ++r) {
      tf.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i : idx) s += static_cast<int>(pencil_float(em[i], qm[i], ell));
        sink = sink + s;
      }));
      tw.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i : idx) s += wwk_separated(em[i], qm[i]);
        sink = sink + s;
      }));
      td.push_back(seconds([&] {
        int s = 0;
        for (std::size_t i : idx) s += static_cast<int>(decide_position(es[i], qs[i]).position);
        sink = sink + s;
      }));
    }
    const double k = 1e9 / static_cast<double>(idx.size()), a = median(tf) * k, w = median(tw) * k, b = median(td) * k;
    std::printf("  %s pairs (%zu): float %.1f ns, WWK %.1f ns, decide_position %.1f ns (%.2fx float, %.2fx WWK)\n",
                to_string(p).c_str(), idx.size(), a, w, b, b / a, b / w);
  }
  const double f = median(t_float) / n * 1e9, w = median(t_wwk) / n * 1e9, d = median(t_decide) / n * 1e9;
  const double fr = from ? median(t_from) / n * 1e9 : 0;
  std::printf("ellipsoid-ellipsoid, ns of thread CPU time a pair (median of %d rounds, same run):\n", rounds);
  std::printf("  float decision (quartic, cubic, sign rule; nothing certified)  %8.1f\n", f);
  std::printf("  Wang-Wang-Kim in doubles (separated or not; nothing certified) %8.1f\n", w);
  std::printf("  decide_position(e, q), prebuilt objects                        %8.1f  (%.2fx float, %.2fx WWK)\n", d,
              d / f, d / w);
  if (from)
    std::printf("  from_doubles + decide_position                                 %8.1f  (%.2fx float)\n", fr, fr / f);
  per_type(std::max<std::size_t>(n / 4, 1), rounds);
  // Scaled matrices: the same pairs with E times 3 and Q times 1/3 (rationals that are not doubles:
  // the filter reads enclosures) against E times 10^300 and Q times 10^-300, on the filter and on the
  // exact stage (each matrix's own primitive integer form: the same integers, math.md §17).
  {
    const std::size_t m = std::min<std::size_t>(n, 2000);
    Rational big(1);
    for (int i = 0; i < 300; ++i) big *= 10;
    auto scaled = [](const DoubleMatrix4& x, const Rational& s) {
      Matrix4 out;
      for (std::size_t i = 0; i < 16; ++i) out.a[i] = Rational(x[i]) * s;
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
