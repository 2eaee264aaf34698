// relpos_motion_bench: certified first contact (relpos::first_contact) against a float baseline on
// random translation paths, including exact and near grazing paths (doc/performance.md, "Motion").
//
//   relpos_motion_bench [--seed N] [--n PATHS] [--quick] [--exact-only]
//
// Float baseline ("march + bisect"): the user's usual code. E(t) in doubles, f(l) = det(l P + E(t))
// and its Sturm-Habicht sequence in doubles (the library's generic formulas instantiated with
// double), "exterior" = two distinct positive roots by Sturm counting; march t over K equal steps
// of [t0, t1], and at the first step that is not exterior bisect 52 times on the same predicate.
// K = 64 and K = 1024. A double predicate that cannot count (defective sequence) is read as
// "not exterior" (the conservative choice for contact detection).
//
// Families (all exact rationals; the float code sees the nearest doubles):
//   crossing  random ellipsoid (semi-axes in [1/10, 1/2], random rotation), random paraboloid
//             z' = x^2/a^2 + y^2/b^2 (a, b in [1/2, 2]), straight path from a random exterior point
//             through a random point inside the cup; contact time generic (algebraic).
//   grazing   sphere of radius r touching z = x^2 + y^2 from outside at a point with a rational unit
//             normal, moving along the tangent plane: TE at exactly one rational instant tau, E
//             before and after.
//   near-graze-d  the grazing path pushed by d (1e-4, 1e-8) into the cup along the normal: it
//             crosses during an interval of length ~ sqrt(d).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algebra/pencil.hpp"
#include "algebra/sturm.hpp"
#include "motion/polynomial_motion.hpp"
#include "relpos/classify.hpp"
#include "relpos/motion.hpp"

using namespace relpos;

/// Per-thread CPU time in microseconds: the machine is shared, and CPU time does not count the time
/// the thread waits for a core (wall time would).
double cpu_us() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
}

namespace {

struct Case {
  Ellipsoid e0;
  Paraboloid p;
  RigidMotion m;
  Rational t0, t1;
  std::optional<Rational> expected;  ///< the contact time by construction (grazing family)
};

// ---------------------------------------------------------------------------------------------
// Float baseline.

struct DMat {
  std::array<double, 16> a;
  const double& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// The moving ellipsoid at time t in doubles: E(t) = T^-T E0 T^-1 with T^-1 = [[I, -c], [0, 1]].
struct FloatPath {
  DMat e0, p;
  std::array<std::array<double, 4>, 3> c;  // translation coefficients (degree <= 3)

  DMat at(double t) const {
    double cx[3];
    for (int i = 0; i < 3; ++i) {
      const auto& k = c[static_cast<std::size_t>(i)];
      cx[i] = ((k[3] * t + k[2]) * t + k[1]) * t + k[0];
    }
    // K = T^-1; E = K^T E0 K.
    double k[16] = {1, 0, 0, -cx[0], 0, 1, 0, -cx[1], 0, 0, 1, -cx[2], 0, 0, 0, 1};
    double ek[16], out[16];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        double v = 0;
        for (int l = 0; l < 4; ++l) v += e0(i, l) * k[4 * l + j];
        ek[4 * i + j] = v;
      }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        double v = 0;
        for (int l = 0; l < 4; ++l) v += k[4 * l + i] * ek[4 * l + j];
        out[4 * i + j] = v;
      }
    DMat m;
    std::copy(out, out + 16, m.a.begin());
    return m;
  }

  bool exterior(double t) const {
    const DMat e = at(t);
    const Quartic<double> f = characteristic_polynomial<double>(p, e);
    SturmHabicht<double> sh(f);
    auto counts = count_roots(f, sh);
    if (!counts) return false;
    return counts->real == 4 && counts->positive == 2 && sh.discriminant() > 0;
  }
};

FloatPath float_path(const Case& k) {
  FloatPath fp;
  for (std::size_t i = 0; i < 16; ++i) {
    fp.e0.a[i] = CGAL::to_double(k.e0.matrix().a[i]);
    fp.p.a[i] = CGAL::to_double(k.p.matrix().a[i]);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    fp.c[i] = {0, 0, 0, 0};
    for (std::size_t d = 0; d < k.m.translation[i].size() && d < 4; ++d)
      fp.c[i][d] = CGAL::to_double(k.m.translation[i][d]);
  }
  return fp;
}

/// March + bisect. Returns the first non-exterior time, or nullopt.
std::optional<double> float_first_contact(const FloatPath& fp, double t0, double t1, int steps) {
  if (!fp.exterior(t0)) return t0;
  double prev = t0;
  for (int k = 1; k <= steps; ++k) {
    const double t = t0 + (t1 - t0) * k / steps;
    if (!fp.exterior(t)) {
      double lo = prev, hi = t;
      for (int it = 0; it < 52; ++it) {
        const double mid = 0.5 * (lo + hi);
        (fp.exterior(mid) ? lo : hi) = mid;
      }
      return hi;
    }
    prev = t;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// Families.

Rational dyadic(std::mt19937_64& rng, double lo, double hi, int bits = 10) {
  std::uniform_int_distribution<long> d(0, (1L << bits));
  const long k = d(rng);
  return Rational(lo) + (Rational(hi) - Rational(lo)) * Rational(k, 1L << bits);
}

Case crossing_case(std::mt19937_64& rng) {
  for (;;) {
    const Rational z(0);
    const Paraboloid p = Paraboloid::standard({z, z, z}, dyadic(rng, 0.5, 2), dyadic(rng, 0.5, 2));
    std::uniform_int_distribution<int> qi(-3, 3);
    Quaternion rot{Rational(qi(rng)), Rational(qi(rng)), Rational(qi(rng)), Rational(qi(rng))};
    if (rot[0] == 0 && rot[1] == 0 && rot[2] == 0 && rot[3] == 0) rot[0] = Rational(1);
    const Ellipsoid e0 =
        Ellipsoid::from_axes({z, z, z}, {dyadic(rng, 0.1, 0.5), dyadic(rng, 0.1, 0.5), dyadic(rng, 0.1, 0.5)}, rot);
    // From a random point outside (below/beside the cup) to a random point well inside.
    const Vector3 start{dyadic(rng, -3, 3), dyadic(rng, -3, 3), dyadic(rng, -3, 0)};
    const Vector3 target{dyadic(rng, -0.3, 0.3), dyadic(rng, -0.3, 0.3), dyadic(rng, 1, 3)};
    RigidMotion m;
    for (std::size_t i = 0; i < 3; ++i) m.translation[i] = {start[i], target[i] - start[i]};
    Case k{e0, p, m, Rational(0), Rational(1), std::nullopt};
    if (classify(detail::placed_ellipsoid(e0, m, Rational(0)), p, Evidence::Minimal).verdict.position == Position::E)
      return k;
  }
}

/// Points (x, y) of z = x^2 + y^2 whose normal (2x, 2y, -1) has rational length.
const std::array<std::array<int, 3>, 6> kPythagorean = {
    {{1, 1, 3}, {2, 4, 9}, {4, 2, 9}, {6, 6, 17}, {0, 0, 1}, {-2, 4, 9}}};

Case grazing_case(std::mt19937_64& rng, const Rational& push) {
  const Rational z(0);
  const Paraboloid p = Paraboloid::standard({z, z, z}, Rational(1), Rational(1));  // z = x^2 + y^2
  std::uniform_int_distribution<int> pick(0, static_cast<int>(kPythagorean.size()) - 1);
  const auto& pt = kPythagorean[static_cast<std::size_t>(pick(rng))];
  const Rational x(pt[0]), y(pt[1]), len(pt[2]);
  const Vector3 x0{x, y, x * x + y * y};
  const Vector3 n{Rational(2) * x / len, Rational(2) * y / len, Rational(-1) / len};  // outward unit normal
  const Rational r = dyadic(rng, 0.1, 0.5);
  // Tangent direction v = n x w, w a random integer vector (not parallel to n).
  std::uniform_int_distribution<int> wi(-3, 3);
  Vector3 v;
  do {
    const Rational w0(wi(rng)), w1(wi(rng)), w2(wi(rng));
    v = {n[1] * w2 - n[2] * w1, n[2] * w0 - n[0] * w2, n[0] * w1 - n[1] * w0};
  } while (v[0] == 0 && v[1] == 0 && v[2] == 0);
  const Rational tau = dyadic(rng, 0.2, 0.8, 8);
  RigidMotion m;
  for (std::size_t i = 0; i < 3; ++i) {
    const Rational c = x0[i] + (r - push) * n[i];  // centre at tau
    m.translation[i] = {c - tau * v[i], v[i]};
  }
  return Case{Ellipsoid::sphere({z, z, z}, r),
              p,
              m,
              Rational(0),
              Rational(1),
              push == 0 ? std::optional<Rational>(tau) : std::nullopt};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

struct FamilyResult {
  std::string name;
  int n = 0, exact_contacts = 0;
  int exact_checked = 0, exact_wrong = 0;  ///< against the constructed time (grazing: TE at tau)
  double exact_us = 0, timeline_us = 0;
  struct Float {
    int steps;
    double us;
    int missed = 0, false_alarm = 0, time_off = 0;  // time_off: |t_float - t_exact| > 1e-9
  };
  std::vector<Float> floats;
};

bool g_exact_only = false;  // --exact-only: skip the float baseline (for profiling)

FamilyResult run_family(const std::string& name, const std::vector<Case>& cases, bool with_timeline) {
  FamilyResult res;
  res.name = name;
  res.n = static_cast<int>(cases.size());
  std::vector<double> exact_t, tl_t;
  std::vector<std::optional<double>> truth;
  for (const auto& k : cases) {
    const double a = cpu_us();
    const FirstContact fc = first_contact(k.e0, k.m, k.p, k.t0, k.t1);
    exact_t.push_back(cpu_us() - a);
    if (k.expected) {
      ++res.exact_checked;
      const bool ok = fc.kind == FirstContact::Kind::Contact && fc.time->is_rational() &&
                      *fc.time->exact() == *k.expected && fc.position == Position::TE;
      if (!ok) ++res.exact_wrong;
    }
    if (fc.kind == FirstContact::Kind::Contact) {
      ++res.exact_contacts;
      truth.push_back(fc.time->to_double());
    } else if (fc.kind == FirstContact::Kind::NotExteriorAtStart) {
      truth.push_back(CGAL::to_double(k.t0));
    } else {
      truth.push_back(std::nullopt);
    }
    if (with_timeline) {
      const double c = cpu_us();
      const Timeline tl = timeline(k.e0, k.m, k.p, k.t0, k.t1);
      tl_t.push_back(cpu_us() - c);
    }
  }
  res.exact_us = median(exact_t);
  res.timeline_us = median(tl_t);
  for (int steps : {64, 1024}) {
    FamilyResult::Float fr;
    fr.steps = steps;
    if (g_exact_only) {
      res.floats.push_back(fr);
      continue;
    }
    fr.steps = steps;
    std::vector<double> times;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const FloatPath fp = float_path(cases[i]);
      const double t0 = CGAL::to_double(cases[i].t0), t1 = CGAL::to_double(cases[i].t1);
      // Repeat the query until it lasts >= 0.2 ms for a stable per-query time.
      int reps = 0;
      std::optional<double> got;
      const double a = cpu_us();
      double b = a;
      do {
        got = float_first_contact(fp, t0, t1, steps);
        ++reps;
        b = cpu_us();
      } while (b - a < 200);
      times.push_back((b - a) / reps);
      if (truth[i] && !got) ++fr.missed;
      if (!truth[i] && got) ++fr.false_alarm;
      if (truth[i] && got && std::fabs(*got - *truth[i]) > 1e-9) ++fr.time_off;
    }
    fr.us = median(times);
    res.floats.push_back(fr);
  }
  return res;
}

}  // namespace

int main(int argc, char** argv) {
  unsigned long seed = 20240601;
  int n = 200;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--seed") && i + 1 < argc)
      seed = std::stoul(argv[++i]);
    else if (!std::strcmp(argv[i], "--n") && i + 1 < argc)
      n = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick"))
      n = 40;
    else if (!std::strcmp(argv[i], "--exact-only"))
      g_exact_only = true;
    else {
      std::fprintf(stderr, "usage: relpos_motion_bench [--seed N] [--n PATHS] [--quick] [--exact-only]\n");
      return 2;
    }
  }
  std::printf("relpos_motion_bench: seed %lu, %d paths per family\n", seed, n);
  std::mt19937_64 rng(seed);
  std::vector<FamilyResult> results;
  {
    std::vector<Case> cases;
    for (int i = 0; i < n; ++i) cases.push_back(crossing_case(rng));
    results.push_back(run_family("crossing", cases, true));
  }
  {
    std::vector<Case> cases;
    for (int i = 0; i < n; ++i) cases.push_back(grazing_case(rng, Rational(0)));
    results.push_back(run_family("grazing", cases, true));
  }
  const std::pair<const char*, const char*> pushes[] = {{"1/10000", "1e-4"}, {"1/100000000", "1e-8"}};
  for (const auto& [d, label] : pushes) {
    std::vector<Case> cases;
    for (int i = 0; i < n; ++i) cases.push_back(grazing_case(rng, parse_rational(d)));
    results.push_back(run_family(std::string("near-graze-") + label, cases, false));
  }
  for (const auto& r : results)
    if (r.exact_checked)
      std::printf("exact first contact against the constructed time (%s): %d of %d wrong\n", r.name.c_str(),
                  r.exact_wrong, r.exact_checked);
  std::printf(
      "\nMedian CPU time per query (thread CPU clock, microseconds). missed: exact contact in [t0, t1],\n"
      "float none; false alarm: float contact, exact none; time off: both found contact but\n"
      "|t_float - t_exact| > 1e-9.\n");
  std::printf(
      "\n| family | paths | exact contacts | exact first_contact median us | exact timeline median us |"
      " float K=64 median us | K=64 missed | K=64 false alarm | K=64 time off | float K=1024 median us |"
      " K=1024 missed | K=1024 false alarm | K=1024 time off "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& r : results) {
    std::printf("| %s | %d | %d | %.0f | %s | %.1f | %d | %d | %d | %.1f | %d | %d | %d |\n", r.name.c_str(), r.n,
                r.exact_contacts, r.exact_us,
                r.timeline_us > 0 ? std::to_string(static_cast<int>(r.timeline_us)).c_str() : "-", r.floats[0].us,
                r.floats[0].missed, r.floats[0].false_alarm, r.floats[0].time_off, r.floats[1].us, r.floats[1].missed,
                r.floats[1].false_alarm, r.floats[1].time_off);
  }
  return 0;
}
