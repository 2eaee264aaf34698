// Scenes (include/relpos/scene.hpp): every scene answer equals per-pair classify_exact (position,
// rule, contact), the early-outs never fire on a body with contact or of uncertified smallness, the
// certificate polynomials are what math.md §13 says they are (cross-checked in exact arithmetic against
// the pencil code), and 1, 2, 3 threads give identical answers and consistent counts.
#include <CGAL/FPU.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <relpos/scene.hpp>
#include <vector>

#include "filters/running_bound.hpp"
#include "scene/certificates.hpp"
#include "scene/demo.hpp"
#include "scene/scene_pool.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"
#include "support/secular.hpp"

using namespace rt;
using relpos::Classification;
using relpos::Ellipsoid;
using relpos::Evidence;
using relpos::Paraboloid;
using relpos::Rule;
using relpos::Scene;
using relpos::SceneVerdict;
using relpos::Stage;
using relpos::testing::secular_position;

namespace {

/// A named body with its expected answer when known by construction (`expected` is read only when `known`).
struct Body {
  std::string name;
  Ellipsoid e;
  bool known = false;
  Position expected = Position::C;
};

/// The scene verdict must be the core's, field by field (position, rule).
void check_against_exact(const Scene& scene, const Body& b, const SceneVerdict& v) {
  INFO(b.name);
  const Classification x = relpos::classify_exact(b.e, scene.paraboloid(), Evidence::Minimal);
  CHECK(v.position == x.verdict.position);
  CHECK(v.rule == x.verdict.rule);
  if (b.known) CHECK(v.position == b.expected);
  // An early-out certifies "no common point": never on a body that touches or crosses.
  if (v.stage == Stage::InsideCertificate || v.stage == Stage::OutsideCertificate)
    CHECK(relpos::contact_of(x.verdict.position) == relpos::Contact::None);
}

Ellipsoid sphere_at(const Vector3& c, const Rational& r) { return Ellipsoid::sphere(c, r); }

/// An ellipsoid with semi-axes (ra, rb, rc) along the rotation of q, centre c (general path: not a
/// sphere unless the axes are equal).
Ellipsoid axes(const Vector3& c, const Rational& ra, const Rational& rb, const Rational& rc,
               const Quaternion& q = {Q(1), Q(0), Q(0), Q(0)}) {
  return Ellipsoid::from_axes(c, {ra, rb, rc}, q);
}

/// A random ellipsoid E = [[M, -Mc], [-c^T M, c^T M c - k]] with dyadic entries (exact doubles).
Ellipsoid random_dyadic_ellipsoid(Rng& g) {
  Matrix3 l;
  for (auto& x : l.a) x = Q(g.uniform(-8, 8), 8);
  Matrix3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational s = i == j ? Q(1, 16) : Q(0);
      for (int t = 0; t < 3; ++t) s += l(t, i) * l(t, j);
      m(i, j) = s;
    }
  const Vector3 c{Q(g.uniform(-64, 64), 16), Q(g.uniform(-64, 64), 16), Q(g.uniform(-16, 96), 16)};
  const Rational k = Q(g.uniform(1, 32), 64);
  Matrix4 e;
  for (int i = 0; i < 3; ++i) {
    Rational mc(0);
    for (int j = 0; j < 3; ++j) {
      e(i, j) = m(i, j);
      mc += m(i, j) * c[static_cast<std::size_t>(j)];
    }
    set_sym(e, i, 3, -mc);
  }
  Rational cmc(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) cmc += c[static_cast<std::size_t>(i)] * m(i, j) * c[static_cast<std::size_t>(j)];
  e(3, 3) = cmc - k;
  return Ellipsoid::from_matrix(e);
}

/// Bodies with answers known by construction for z = x^2/a^2 + y^2/b^2 (standard frame): the
/// tangency families of construct.hpp (TI, TE, I, E, C at rational-normal points), spheres on the
/// axis barely inside / outside / crossing / tangent, flattened (non-sphere) versions of the same,
/// and bodies that are not small.
std::vector<Body> constructed_bodies(Rng& g, const Rational& a, const Rational& b, int families) {
  std::vector<Body> out;
  for (int f = 0; f < families; ++f) {
    auto [s, t] = random_st(g, true);
    const TangentPoint tp = tangent_point(a, b, s, t);
    const Rational r = random_tangent_radius(g, a, b);
    for (const Config& k : tangency_family(tp, r, g.uniform(1, 7)))
      out.push_back({describe(k), sphere_at(k.c, k.r), true, k.expected});
  }
  const Rational a2 = rmin(a, b) * rmin(a, b);
  const Rational r = a2 / 8;
  for (int k = 1; k <= 60; k += 3) {
    const Rational eps = Rational(1) / pow_q(Q(2), k);
    const std::string tag = " (eps 2^-" + std::to_string(k) + ")";
    // On the axis at height z: I for z > r (z <= a^2/2), C for |z| < r, E for z < -r.
    out.push_back({"axis barely inside" + tag, sphere_at(V(Q(0), Q(0), r * (1 + eps)), r), true, Position::I});
    out.push_back({"axis barely crossing" + tag, sphere_at(V(Q(0), Q(0), r * (1 - eps)), r), true, Position::C});
    out.push_back({"axis barely outside" + tag, sphere_at(V(Q(0), Q(0), -r * (1 + eps)), r), true, Position::E});
    out.push_back({"axis barely crossing below" + tag, sphere_at(V(Q(0), Q(0), -r * (1 - eps)), r), true, Position::C});
    // The same as ellipsoids flattened along z by (1 - eps) (general path): the flattened body lies
    // inside the sphere, so I and E stay I and E, and a body touching at the vertex from inside or
    // outside with vertical semi-axis r' is TI / TE.
    const Rational rf = r * (1 - eps);
    out.push_back({"flat barely inside" + tag, axes(V(Q(0), Q(0), r * (1 + eps)), r, r, rf), true, Position::I});
    out.push_back({"flat barely outside" + tag, axes(V(Q(0), Q(0), -r * (1 + eps)), r, r, rf), true, Position::E});
    out.push_back({"flat TI at the vertex" + tag, axes(V(Q(0), Q(0), rf), r / 2, r / 2, rf), true, Position::TI});
    out.push_back({"flat TE at the vertex" + tag, axes(V(Q(0), Q(0), -rf), r, r, rf), true, Position::TE});
  }
  // Exact tangencies at the vertex.
  out.push_back({"TI vertex", sphere_at(V(Q(0), Q(0), r), r), true, Position::TI});
  out.push_back({"TE vertex", sphere_at(V(Q(0), Q(0), -r), r), true, Position::TE});
  // Well inside / outside (the early-outs should fire; checked in "early-outs fire").
  out.push_back({"deep inside", sphere_at(V(Q(0), Q(0), 4 * a2), r), true, Position::I});
  out.push_back({"far below", sphere_at(V(Q(0), Q(0), -4 * a2), r), true, Position::E});
  // Not small: inside (I: distance^2 to the cup a^2 z - a^4/4 = 31/4 a^4 > r^2 = 4 a^4), outside
  // (E), crossing at the vertex (C); math.md §8 classifies every size.
  out.push_back({"big sphere inside, not small", sphere_at(V(Q(0), Q(0), 8 * a2), 2 * a2), true, Position::I});
  out.push_back({"big sphere below, not small", sphere_at(V(Q(0), Q(0), -3 * a2), 2 * a2), true, Position::E});
  out.push_back({"big sphere at the vertex", sphere_at(V(Q(0), Q(0), Q(0)), 2 * a2), true, Position::C});
  return out;
}

}  // namespace

TEST_CASE("scene: the certificate polynomials are det M, -det E, D^2 P(c), s(l) (exact cross-check)") {
  const std::uint64_t seed = 0x5CE7E001;
  Rng g(seed);
  CAPTURE(seed);
  for (int trial = 0; trial < 40; ++trial) {
    const Paraboloid p = Paraboloid::from_matrix(transform(Matrix4{}, paraboloid_matrix(Q(1), Q(3, 2)), g).p);
    const Ellipsoid e = trial % 2 ? random_dyadic_ellipsoid(g)
                                  : sphere_at(V(g.rational(-4, 4, 3), g.rational(-4, 4, 3), g.rational(-4, 4, 3)),
                                              g.positive_rational(4, 3));
    const Matrix4 &em = e.matrix(), &pm = p.matrix();
    auto ent = [](const Matrix4& m) {
      return relpos::SymmetricEntries<Rational>{m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2),
                                                m(1, 2), m(0, 3), m(1, 3), m(2, 3), m(3, 3)};
    };
    relpos::SymmetricEntries<Rational> adj;
    adj.q00 = pm(1, 1) * pm(2, 2) - pm(1, 2) * pm(1, 2);
    adj.q11 = pm(0, 0) * pm(2, 2) - pm(0, 2) * pm(0, 2);
    adj.q22 = pm(0, 0) * pm(1, 1) - pm(0, 1) * pm(0, 1);
    adj.q01 = pm(0, 2) * pm(1, 2) - pm(0, 1) * pm(2, 2);
    adj.q02 = pm(0, 1) * pm(1, 2) - pm(0, 2) * pm(1, 1);
    adj.q12 = pm(0, 1) * pm(0, 2) - pm(0, 0) * pm(1, 2);
    const relpos::ContainmentQuantities<Rational> q(ent(em), ent(pm), adj);
    // D = det M, K = -det E: the ends of f's and s's coefficient lists (pencil.hpp, independent code).
    const Quadratic<Rational> s = relpos::special_polynomial<Rational>(pm, em);
    CHECK(q.D == s[0]);
    CHECK(q.S1 == s[1]);
    CHECK(q.S2 == s[2]);
    CHECK(q.K == -det4(em));
    // Pn = D^2 P(c) with c = -M^-1 e solved here by Cramer's rule.
    Matrix3 m3;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m3(i, j) = em(i, j);
    const Rational dm = det3(m3);
    const Vector3 c = solve3(m3, {-em(0, 3), -em(1, 3), -em(2, 3)});
    Rational pc = pm(3, 3);
    for (int i = 0; i < 3; ++i) {
      pc += 2 * pm(i, 3) * c[static_cast<std::size_t>(i)];
      for (int j = 0; j < 3; ++j) pc += c[static_cast<std::size_t>(i)] * pm(i, j) * c[static_cast<std::size_t>(j)];
    }
    CHECK(q.Pn == dm * dm * pc);
    // W = (D^3 / 4) g^T M^-1 g with g = grad P(c) = 2 (A c + p): check via M g~ = g solved exactly.
    Vector3 grad;
    for (int i = 0; i < 3; ++i) {
      Rational v = pm(i, 3);
      for (int j = 0; j < 3; ++j) v += pm(i, j) * c[static_cast<std::size_t>(j)];
      grad[static_cast<std::size_t>(i)] = 2 * v;
    }
    const Vector3 sol = solve3(m3, grad);
    const Rational gmg = grad[0] * sol[0] + grad[1] * sol[1] + grad[2] * sol[2];
    CHECK(q.W == dm * dm * dm * gmg / 4);
    if (trial % 2 == 0) {  // sphere: the reduced quantities
      const relpos::SphereQuantities<Rational> sq(ent(em), ent(pm));
      const Rational m = em(0, 0);
      CHECK(q.K == m * m * sq.Kp);
      CHECK(q.Pn == pow_q(m, 4) * sq.Pnp);
      CHECK(q.W == pow_q(m, 6) * sq.Wp);
    }
  }
}

TEST_CASE("scene: the diagonal-A variants equal the general quantities (exact)") {
  const std::uint64_t seed = 0x5CE7E007;
  Rng g(seed);
  CAPTURE(seed);
  auto ent = [](const Matrix4& m) {
    return relpos::SymmetricEntries<Rational>{m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2),
                                              m(1, 2), m(0, 3), m(1, 3), m(2, 3), m(3, 3)};
  };
  for (int trial = 0; trial < 40; ++trial) {
    // An axis-aligned paraboloid (any vertex, any of the three axes): A diagonal.
    Matrix4 pm = paraboloid_matrix(g.positive_rational(4, 3), g.positive_rational(4, 3));
    const Vector3 v{g.rational(-3, 3, 2), g.rational(-3, 3, 2), g.rational(-3, 3, 2)};
    pm = congruence(pm, affine_matrix(identity3(), {-v[0], -v[1], -v[2]}));
    const Matrix4 em = trial % 2 ? random_dyadic_ellipsoid(g).matrix() : sphere_matrix(v, g.positive_rational(4, 3));
    relpos::SymmetricEntries<Rational> adj{
        pm(1, 1) * pm(2, 2), pm(0, 0) * pm(2, 2), pm(0, 0) * pm(1, 1), Q(0), Q(0), Q(0), Q(0), Q(0), Q(0), Q(0)};
    using CQ = relpos::ContainmentQuantities<Rational>;
    const CQ a(ent(em), ent(pm), adj), b(ent(em), ent(pm), adj, CQ::DiagonalA{});
    CHECK(a.D == b.D);
    CHECK(a.K == b.K);
    CHECK(a.Pn == b.Pn);
    CHECK(a.W == b.W);
    CHECK(a.S1 == b.S1);
    CHECK(a.S2 == b.S2);
    if (trial % 2 == 0) {
      using SQ = relpos::SphereQuantities<Rational>;
      const SQ c(ent(em), ent(pm)), d(ent(em), ent(pm), SQ::DiagonalA{});
      CHECK(c.Kp == d.Kp);
      CHECK(c.Pnp == d.Pnp);
      CHECK(c.Wp == d.Wp);
    }
  }
}

TEST_CASE("scene: bodies with known answers, and the early-outs never fire on contact") {
  const std::uint64_t seed = 0x5CE7E002;
  Rng g(seed);
  CAPTURE(seed);
  for (const auto& ab : {std::pair<Rational, Rational>{Q(1), Q(2)}, {Q(6, 5), Q(3, 2)}, {Q(1), Q(1)}}) {
    const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, ab.first, ab.second);
    const Scene scene(p);
    const std::vector<Body> bodies = constructed_bodies(g, ab.first, ab.second, 12);
    for (const Body& b : bodies) {
      const SceneVerdict v = scene.classify(b.e);
      check_against_exact(scene, b, v);
      const auto early = scene.early_out(b.e);
      if (b.known && (b.expected == Position::TI || b.expected == Position::C || b.expected == Position::TE)) {
        INFO(b.name);
        CHECK(!early);
      }
    }
  }
}

TEST_CASE("scene: the early-outs fire on bodies well inside or outside, small or not") {
  const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2));
  // a^2 = 2^100 and 2^-100: the filter rescales the ellipsoid entries by a power of two.
  const Rational big = pow_q(Q(2), 50), tiny = Rational(1) / big;
  const Paraboloid p_huge = Paraboloid::standard({Q(0), Q(0), Q(0)}, big, 2 * big);
  const Paraboloid p_tiny = Paraboloid::standard({Q(0), Q(0), Q(0)}, tiny, 2 * tiny);
  struct Case {
    const char* name;
    const Paraboloid* p;
    Ellipsoid e;
    Position expected;
    Stage stage;
  };
  const Quaternion q{Q(1), Q(1), Q(1), Q(1)};
  const std::vector<Case> cases = {
      {"sphere deep inside", &p, sphere_at(V(Q(0), Q(0), Q(2)), Q(1, 8)), Position::I, Stage::InsideCertificate},
      {"sphere off-axis inside", &p, sphere_at(V(Q(1, 2), Q(1, 2), Q(1)), Q(1, 8)), Position::I,
       Stage::InsideCertificate},
      {"rotated ellipsoid inside", &p, axes(V(Q(0), Q(1, 4), Q(2)), Q(1, 4), Q(1, 8), Q(1, 16), q), Position::I,
       Stage::InsideCertificate},
      {"non-dyadic sphere inside", &p, sphere_at(V(Q(1, 3), Q(1, 7), Q(5, 3)), Q(1, 10)), Position::I,
       Stage::InsideCertificate},
      {"sphere below", &p, sphere_at(V(Q(0), Q(0), Q(-1)), Q(1, 4)), Position::E, Stage::OutsideCertificate},
      {"sphere beside the rim", &p, sphere_at(V(Q(3), Q(0), Q(1)), Q(1, 2)), Position::E, Stage::OutsideCertificate},
      {"rotated ellipsoid outside", &p, axes(V(Q(2), Q(0), Q(1)), Q(1, 4), Q(1, 8), Q(1, 16), q), Position::E,
       Stage::OutsideCertificate},
      {"huge sphere far below (not small)", &p, sphere_at(V(Q(0), Q(0), Q(-100)), Q(10)), Position::E,
       Stage::OutsideCertificate},
      {"2^100 scale, inside", &p_huge, sphere_at(V(Q(0), Q(0), 2 * big * big), big * big / 16), Position::I,
       Stage::InsideCertificate},
      {"2^100 scale, outside", &p_huge, sphere_at(V(Q(0), Q(0), -2 * big * big), big * big / 16), Position::E,
       Stage::OutsideCertificate},
      {"2^-100 scale, inside", &p_tiny, sphere_at(V(Q(0), Q(0), 2 * tiny * tiny), tiny * tiny / 16), Position::I,
       Stage::InsideCertificate},
      {"2^-100 scale, ellipsoid inside", &p_tiny,
       axes(V(Q(0), Q(0), 2 * tiny * tiny), tiny * tiny / 16, tiny * tiny / 32, tiny * tiny / 64, q), Position::I,
       Stage::InsideCertificate},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const Scene scene(*c.p);
    const auto v = scene.early_out(c.e);
    REQUIRE(v);
    CHECK(v->position == c.expected);
    CHECK(v->stage == c.stage);
    check_against_exact(scene, {c.name, c.e, true, c.expected}, *v);
  }
  // Interior bodies that are not small: the inside certificate holds, but the core names their rule
  // (math.md §8), so the early-out leaves them to it; Scene::classify still answers I.
  const std::vector<Case> not_small = {
      // mixed.jsonl I-flat-ellipsoid-inside: inside but rho > 1.
      {"flat ellipsoid inside, not small", &p, axes(V(Q(0), Q(0), Q(3)), Q(1), Q(2), Q(1, 10)), Position::I,
       Stage::InsideCertificate},
      // distance^2 from (0,0,8) to the cup: a^2 z - a^4/4 = 31/4 > r^2 = 4.
      {"big sphere inside, not small", &p, sphere_at(V(Q(0), Q(0), Q(8)), Q(2)), Position::I, Stage::InsideCertificate},
  };
  for (const Case& c : not_small) {
    INFO(c.name);
    const Scene scene(*c.p);
    CHECK_FALSE(scene.early_out(c.e).has_value());
    const SceneVerdict v = scene.classify(c.e);
    CHECK(v.position == c.expected);
    CHECK(v.position == secular_position(c.e, *c.p));
    check_against_exact(scene, {c.name, c.e, true, c.expected}, v);
  }
}

TEST_CASE("scene: a few thousand mixed bodies equal classify_exact; 1, 2, 3 threads agree") {
  const std::uint64_t seed = 0x5CE7E003;
  Rng g(seed);
  CAPTURE(seed);
  struct Setup {
    const char* name;
    Paraboloid p;
    std::vector<Body> bodies;
  };
  std::vector<Setup> setups;
  {  // the demo container (dyadic, mostly exact doubles), plus constructed bodies
    Setup s{"demo container a=1 b=2", Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2)), {}};
    for (const auto& d : relpos::demo_container_scene(2500, seed, Q(1), Q(2)))
      s.bodies.push_back({"demo", d.ellipsoid()});
    for (auto& b : constructed_bodies(g, Q(1), Q(2), 6)) s.bodies.push_back(std::move(b));
    setups.push_back(std::move(s));
  }
  {  // a rotated, translated, non-dyadic paraboloid with generic random ellipsoids
    const Matrix4 pm = transform(Matrix4{}, paraboloid_matrix(Q(1), Q(3, 2)), g, true).p;
    Setup s{"rigidly moved paraboloid, random ellipsoids", Paraboloid::from_matrix(pm), {}};
    for (int i = 0; i < 600; ++i) s.bodies.push_back({"random dyadic ellipsoid", random_dyadic_ellipsoid(g)});
    setups.push_back(std::move(s));
  }
  for (const Setup& s : setups) {
    INFO(s.name);
    const Scene scene(s.p);
    std::vector<Ellipsoid> es;
    for (const Body& b : s.bodies) es.push_back(b.e);
    relpos::SceneOptions o;
    o.threads = 1;
    o.chunk = 64;
    const relpos::SceneResult one = scene.classify(es, o);
    REQUIRE(one.verdicts.size() == es.size());
    for (std::size_t i = 0; i < es.size(); ++i) check_against_exact(scene, s.bodies[i], one.verdicts[i]);
    // Counts are the tallies of the verdicts.
    relpos::SceneCounts recount;
    for (const auto& v : one.verdicts) recount.add(v);
    CHECK(one.counts.bodies == es.size());
    CHECK(one.counts.positions == recount.positions);
    CHECK(one.counts.stages == recount.stages);
    std::size_t sp = 0, ss = 0;
    for (auto n : one.counts.positions) sp += n;
    for (auto n : one.counts.stages) ss += n;
    CHECK(sp == es.size());
    CHECK(ss == es.size());
    // The early-outs did something on these scenes.
    CHECK(one.counts.count(Stage::InsideCertificate) + one.counts.count(Stage::OutsideCertificate) > 0);
    for (unsigned threads : {2u, 3u}) {
      o.threads = threads;
      const relpos::SceneResult many = scene.classify(es, o);
      CHECK(many.threads == threads);
      bool same = many.verdicts.size() == one.verdicts.size();
      for (std::size_t i = 0; same && i < es.size(); ++i)
        same = many.verdicts[i].position == one.verdicts[i].position &&
               many.verdicts[i].stage == one.verdicts[i].stage && many.verdicts[i].rule == one.verdicts[i].rule;
      CHECK(same);
      CHECK(many.counts.positions == one.counts.positions);
      CHECK(many.counts.stages == one.counts.stages);
    }
    // Without early-outs: the same positions, every body through decide_position.
    o.early_outs = false;
    o.threads = 2;
    const relpos::SceneResult plain = scene.classify(es, o);
    CHECK(plain.counts.positions == one.counts.positions);
    CHECK(plain.counts.count(Stage::InsideCertificate) == 0);
    CHECK(plain.counts.count(Stage::OutsideCertificate) == 0);
  }
}

namespace {

/// |value - exact| <= error_bound, and a certain sign is the exact sign.
void check_bound(const relpos::RunningBound& x, const Rational& exact, const std::string& what) {
  INFO(what << ": value " << x.value() << ", bound " << x.error_bound() << ", exact ~ " << CGAL::to_double(exact));
  const Rational err = rabs(relpos::exact_rational(x.value()) - exact);
  CHECK(err <= relpos::exact_rational(x.error_bound()));
  if (x.sign() != 0) CHECK(x.sign() == sgn(exact));
}

/// A random double: mantissa of `bits` bits, exponent in [lo, hi], either sign.
double random_double_bits(Rng& g, int bits, int lo, int hi) {
  const double m = static_cast<double>(g.uniform(1, (1L << bits) - 1)) / static_cast<double>(1L << bits);
  return (g.chance(50) ? -1 : 1) * std::ldexp(m, static_cast<int>(g.uniform(lo, hi)));
}

}  // namespace

TEST_CASE("scene: RunningBound bounds the rounding error of the certificate programs (exact cross-check)") {
  const std::uint64_t seed = 0x5CE7E005;
  Rng g(seed);
  CAPTURE(seed);
  using RB = relpos::RunningBound;
  // Cancellation and underflow on purpose: x*y - z with z = fl(x*y) +- a few ulps; products of
  // 2^-600-sized numbers (the exact product underflows); sums of terms of very different size.
  for (int i = 0; i < 2000; ++i) {
    const double x = random_double_bits(g, 53, -30, 30), y = random_double_bits(g, 53, -30, 30);
    const double z = std::nextafter(x * y, g.chance(50) ? 1e300 : -1e300);
    check_bound(RB(x) * RB(y) - RB(z),
                relpos::exact_rational(x) * relpos::exact_rational(y) - relpos::exact_rational(z), "x y - z");
    const double u = random_double_bits(g, 30, -620, -560), v = random_double_bits(g, 30, -620, -560);
    const double w = random_double_bits(g, 30, -1100, -1030);
    check_bound(RB(u) * RB(v) + RB(w) - RB(u) * RB(-v),
                2 * relpos::exact_rational(u) * relpos::exact_rational(v) + relpos::exact_rational(w), "underflow");
    check_bound((RB(x) + RB(u)) * (RB(y) - RB(u)) - RB(x) * RB(y),
                (relpos::exact_rational(x) + relpos::exact_rational(u)) *
                        (relpos::exact_rational(y) - relpos::exact_rational(u)) -
                    relpos::exact_rational(x) * relpos::exact_rational(y),
                "tiny difference");
  }
  // The certificate programs themselves, on random entries of random magnitudes (the scene filter
  // scales E to at most 2^40; here up to 2^60 and down to 2^-60), against the exact values.
  for (int i = 0; i < 300; ++i) {
    const int e_lo = static_cast<int>(g.uniform(-60, 0)), e_hi = e_lo + static_cast<int>(g.uniform(0, 60));
    auto rd = [&] {
      return g.chance(15) ? 0.0 : random_double_bits(g, static_cast<int>(g.uniform(1, 53)), e_lo, e_hi);
    };
    double ev[10], pv[10], av[10];
    for (double& v : ev) v = rd();
    for (double& v : pv) v = random_double_bits(g, 20, -8, 0);
    for (double& v : av) v = random_double_bits(g, 20, -8, 0);
    auto as_rb = [](const double* v) {
      return relpos::SymmetricEntries<RB>{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9]};
    };
    auto as_q = [](const double* v) {
      auto q = [](double d) { return relpos::exact_rational(d); };
      return relpos::SymmetricEntries<Rational>{q(v[0]), q(v[1]), q(v[2]), q(v[3]), q(v[4]),
                                                q(v[5]), q(v[6]), q(v[7]), q(v[8]), q(v[9])};
    };
    const relpos::ContainmentQuantities<RB> fq(as_rb(ev), as_rb(pv), as_rb(av));
    const relpos::ContainmentQuantities<Rational> eq(as_q(ev), as_q(pv), as_q(av));
    check_bound(fq.Pn, eq.Pn, "Pn");
    check_bound(fq.K, eq.K, "K");
    check_bound(fq.outside_gap(), eq.outside_gap(), "outside gap");
    check_bound(fq.inside_t(), eq.inside_t(), "inside t");
    check_bound(fq.inside_gap(), eq.inside_gap(), "inside gap");
    const relpos::SphereQuantities<RB> fs(as_rb(ev), as_rb(pv));
    const relpos::SphereQuantities<Rational> es(as_q(ev), as_q(pv));
    check_bound(fs.outside_gap(), es.outside_gap(), "sphere outside gap");
    check_bound(fs.inside_gap(RB(pv[0])), es.inside_gap(relpos::exact_rational(pv[0])), "sphere inside gap");
  }
  // An enclosure: the true value anywhere in [lo, hi].
  for (int i = 0; i < 200; ++i) {
    const double lo = random_double_bits(g, 53, -20, 20), hi = std::nextafter(std::nextafter(lo, 1e300), 1e300);
    const RB x = RB::enclosing(lo, hi) * RB(3) - RB(lo) * RB(3);
    for (const double t : {lo, hi})
      check_bound(x, relpos::exact_rational(t) * 3 - relpos::exact_rational(lo) * 3, "enclosure");
  }
  CHECK(RB::enclosing(1, 0).sign() == 0);
  CHECK(RB::enclosing(0, std::numeric_limits<double>::infinity()).sign() == 0);
}

TEST_CASE("scene: transformed configurations (general path, non-dyadic inputs) keep their answers") {
  // Q -> k H^T Q H with the same random affine H for both surfaces preserves the position
  // (math.md §1); a non-rigid H turns every sphere into a general ellipsoid with rational,
  // non-dyadic entries, so this exercises the general certificates and the rational loader.
  const std::uint64_t seed = 0x5CE7E006;
  Rng g(seed);
  CAPTURE(seed);
  int fired = 0, total = 0;
  for (const auto& ab : {std::pair<Rational, Rational>{Q(1), Q(2)}, {Q(6, 5), Q(3, 2)}}) {
    std::vector<Config> configs;
    for (int f = 0; f < 6; ++f) {
      auto [s, t] = random_st(g, false);
      const TangentPoint tp = tangent_point(ab.first, ab.second, s, t);
      for (const Config& k : tangency_family(tp, random_tangent_radius(g, ab.first, ab.second), g.uniform(1, 7)))
        configs.push_back(k);
    }
    configs.push_back({"deep inside", ab.first, ab.second, V(Q(0), Q(0), Q(3)), Q(1, 8), Position::I});
    configs.push_back({"far outside", ab.first, ab.second, V(Q(3), Q(0), Q(0)), Q(1, 4), Position::E});
    for (const Config& k : configs) {
      const Transformed t = transform(k.e(), k.p(), g);
      const Scene scene(Paraboloid::from_matrix(t.p));
      const Body b{describe(k) + " (transformed)", Ellipsoid::from_matrix(t.e), true, k.expected};
      const SceneVerdict v = scene.classify(b.e);
      check_against_exact(scene, b, v);
      ++total;
      fired += v.stage == Stage::InsideCertificate || v.stage == Stage::OutsideCertificate;
    }
  }
  INFO(fired << " of " << total << " settled by an early-out");
  CHECK(fired > 0);
}

TEST_CASE("scene: empty scenes, more threads than chunks, progress counter") {
  const Scene scene(Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(1)));
  const relpos::SceneResult empty = scene.classify(std::vector<Ellipsoid>{});
  CHECK(empty.verdicts.empty());
  CHECK(empty.counts.bodies == 0);
  std::vector<Ellipsoid> es{sphere_at(V(Q(0), Q(0), Q(1)), Q(1, 8)), sphere_at(V(Q(0), Q(0), Q(-1)), Q(1, 8)),
                            sphere_at(V(Q(0), Q(0), Q(1, 8)), Q(1, 8))};
  std::atomic<std::size_t> progress{0};
  relpos::SceneOptions o;
  o.threads = 8;
  o.chunk = 1;
  o.progress = &progress;
  const relpos::SceneResult r = scene.classify(es, o);
  CHECK(r.threads == 3);
  CHECK(progress.load() == 3);
  REQUIRE(r.verdicts.size() == 3);
  CHECK(r.verdicts[0].position == Position::I);
  CHECK(r.verdicts[1].position == Position::E);
  CHECK(r.verdicts[2].position == Position::TI);
  CHECK((r.verdicts[2].stage == Stage::MultipleRootWitness || r.verdicts[2].stage == Stage::ExactRoots));
  // Called from inside a CGAL interval block (rounding upward): the same answers, and the caller's
  // rounding mode is restored.
  {
    CGAL::Protect_FPU_rounding<true> upward;
    const relpos::SceneResult u = scene.classify(es, o);
    for (std::size_t i = 0; i < es.size(); ++i) {
      CHECK(u.verdicts[i].position == r.verdicts[i].position);
      CHECK(u.verdicts[i].stage == r.verdicts[i].stage);
      CHECK(scene.classify(es[i]).position == r.verdicts[i].position);
      CHECK(scene.early_out(es[i]).has_value() == (i < 2));
    }
    CHECK(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
  }
  CHECK(CGAL::FPU_get_cw() == CGAL_FE_TONEAREST);
}

TEST_CASE("scene: classified on a pool the caller keeps, the same verdicts and counts as Scene::classify") {
  const std::uint64_t seed = 0x5CE7E0F1;
  CAPTURE(seed);
  const Scene scene(Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2)));
  std::vector<Ellipsoid> es;
  for (const auto& d : relpos::demo_container_scene(700, seed, Q(1), Q(2))) es.push_back(d.ellipsoid());
  relpos::SceneOptions o;
  o.threads = 1;
  o.chunk = 64;
  const relpos::SceneResult alone = scene.classify(es, o);  // its own pool, one thread
  // One pool kept across calls, as `relpos scene` keeps its pool from block to block.
  relpos::detail::WorkerPool pool(3);
  for (int round = 0; round < 2; ++round) {
    std::atomic<std::size_t> progress{0};
    o.progress = &progress;
    const relpos::SceneResult r = relpos::detail::SceneAccess::classify(scene, es.data(), es.size(), o, pool);
    REQUIRE(r.verdicts.size() == es.size());
    for (std::size_t i = 0; i < es.size(); ++i) {
      CHECK(r.verdicts[i].position == alone.verdicts[i].position);
      CHECK(r.verdicts[i].stage == alone.verdicts[i].stage);
    }
    CHECK(r.counts.positions == alone.counts.positions);
    CHECK(r.counts.stages == alone.counts.stages);
    CHECK(r.threads == pool.threads());  // 11 chunks: every thread of the pool has bodies to take
    CHECK(progress.load() == es.size());
  }
  // Fewer chunks than threads: the threads that had bodies to take.
  o.chunk = 1024;
  o.progress = nullptr;
  CHECK(relpos::detail::SceneAccess::classify(scene, es.data(), es.size(), o, pool).threads == 1);
}
