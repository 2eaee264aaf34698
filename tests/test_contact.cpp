// contact.hpp: the discriminant-only decision, contact(), ContactChecker and ExteriorTracker
// (doc/contact.md). Every answer is compared with classify / decide_position, the exact expectations
// come from constructions (support/construct.hpp), and the fast path is required to decide most
// generic pairs, so a silent "always fall back" fails the suite.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>
#include <random>
#include <relpos/contact.hpp>
#include <relpos/scene.hpp>
#include <vector>

#include "algebra/smallness.hpp"
#include "contact/discriminant_case.hpp"
#include "decide/stages.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"
#include "support/random_pairs.hpp"
#include "support/secular.hpp"

using namespace rt;
using relpos::Classification;
using relpos::Contact;
using relpos::ContactAnswer;
using relpos::DiscriminantCase;
using relpos::Ellipsoid;
using relpos::Evidence;
using relpos::Paraboloid;
using relpos::Rule;
using relpos::Stage;
using relpos::Verdict;
using relpos::testing::secular_position;

namespace {

/// The discriminant case from exact signs of f and Disc(f).
DiscriminantCase exact_case(const Quartic<Rational>& f) {
  const relpos::SturmHabicht<Rational> sh(f);
  return relpos::discriminant_case(relpos::signs_of(f, sh));
}

/// What the contact answer must be, given classify's verdict (when classify decides contact).
void check_contact_consistent(const ContactAnswer& a, const Verdict& v) {
  INFO("contact " << relpos::to_string(a.contact) << ", classify " << relpos::to_string(v.position) << " rule "
                  << relpos::describe(v.rule));
  CHECK(a.position == v.position);
  CHECK(a.rule == v.rule);
  switch (v.position) {
    case Position::I:
    case Position::E:
      CHECK(a.contact == Contact::None);
      break;
    case Position::TI:
    case Position::TE:
      CHECK(a.contact == Contact::Touching);
      break;
    case Position::C:
      CHECK(a.contact == Contact::Crossing);
      break;
  }
}

void check_same(const Verdict& a, const Verdict& b) {
  CHECK(a.position == b.position);
  CHECK(a.rule == b.rule);
}

/// Random ellipsoid / paraboloid pairs with exact-double entries (the benchmark's family).
struct DoublePairs {
  std::mt19937_64 rng;
  explicit DoublePairs(std::uint64_t seed) : rng(seed) {}
  std::pair<Matrix4, Matrix4> next() {
    const Matrix4 E = random_double_ellipsoid_matrix(rng, 0.01);  // drawn before the paraboloid
    return {E, random_double_paraboloid_matrix(rng)};
  }
};

/// The paper's tracker (section 2): Disc < 0 -> C, Disc > 0 -> E, Disc = 0 -> TE.
Position paper_tracker(const Quartic<Rational>& f) {
  const Rational d = quartic_discriminant(f);
  return d < 0 ? Position::C : (d > 0 ? Position::E : Position::TE);
}

}  // namespace

TEST_CASE("the discriminant case on exact signs reproduces classify_exact", "[contact][math]") {
  // Validates the mathematics (>= 2 negative roots, Descartes exact) independently of any filter.
  Rng g(20250101);
  int decided = 0, disc_zero = 0;
  for (int n = 0; n < 400; ++n) {
    // A sphere in the standard frame, then a random congruence (exact rationals).
    const Rational a = g.positive_rational(6, 3), b = g.positive_rational(6, 3);
    const Vector3 c{g.rational(-6, 6, 4), g.rational(-6, 6, 4), g.rational(-4, 12, 4)};
    const Rational r = g.positive_rational(8, 5);
    const Transformed t = transform(sphere_matrix(c, r), paraboloid_matrix(a, b), g);
    const Ellipsoid e = Ellipsoid::from_matrix(t.e);
    const Paraboloid p = Paraboloid::from_matrix(t.p);
    const Classification x = relpos::classify_exact(e, p, Evidence::Full);
    const DiscriminantCase dc = exact_case(x.f);
    INFO("case " << relpos::to_string(dc) << ", classify " << relpos::to_string(x.verdict.position));
    if (x.verdict.sign_disc_f == 0) {
      ++disc_zero;
      CHECK(dc == DiscriminantCase::Undecided);
      continue;
    }
    REQUIRE(dc != DiscriminantCase::Undecided);
    ++decided;
    const auto v = relpos::verdict_from_discriminant_case(dc, x.verdict.rho_vs_one);
    // The case alone may decline a pair that is not small with four real roots (I or C by math.md
    // §8 needs the roots' location relative to lambda_s); whatever it answers is classify's.
    if (!v) {
      CHECK(x.verdict.rho_vs_one > 0);
      CHECK(dc == DiscriminantCase::AllNegative);
      continue;
    }
    CHECK(v->position == x.verdict.position);
    CHECK(v->rule == x.verdict.rule);
    CHECK(int(v->real_roots) == x.verdict.real_roots);
    CHECK(int(v->positive_roots) == x.verdict.positive_roots);
    CHECK(int(v->negative_roots) == x.verdict.negative_roots);
    CHECK(int(v->nonreal_roots) == x.verdict.nonreal_roots);
    CHECK(int(v->sign_disc_f) == x.verdict.sign_disc_f);
    // E does not depend on rho.
    if (dc == DiscriminantCase::TwoPositive) {
      CHECK(x.verdict.position == Position::E);
      CHECK(relpos::verdict_from_discriminant_case(dc, -1)->position == Position::E);
      CHECK(relpos::verdict_from_discriminant_case(dc, std::nullopt)->position == Position::E);
    }
  }
  CHECK(decided > 300);
  (void)disc_zero;
}

TEST_CASE("Descartes cases on hand-made quartics", "[contact][math]") {
  using relpos::USign;
  auto signs = [](const Quartic<Rational>& f) { return exact_case(f); };
  // Roots -1, -2, -3, -4 (lead -1): all negative, Disc > 0.
  CHECK(signs(quartic_from_roots(Q(-1), {Q(-1), Q(-2), Q(-3), Q(-4)})) == DiscriminantCase::AllNegative);
  // Roots -1, -2, 3, 5: two positive.
  CHECK(signs(quartic_from_roots(Q(-1), {Q(-1), Q(-2), Q(3), Q(5)})) == DiscriminantCase::TwoPositive);
  // A double negative root: Disc = 0, undecided.
  CHECK(signs(quartic_from_roots(Q(-1), {Q(-1), Q(-1), Q(3), Q(5)})) == DiscriminantCase::Undecided);
  // (l^2 + 1)(l + 1)(l + 2), lead -1: non-real pair.
  const Quartic<Rational> nr{Q(-2), Q(-3), Q(-3), Q(-3), Q(-1)};
  CHECK(signs(nr) == DiscriminantCase::NonRealPair);
  // Uncertain signs: a certain positive f3 suffices for V = 2 (V <= 2 always); otherwise undecided.
  relpos::QuarticSigns q;
  q.f[4] = USign(CGAL::NEGATIVE);
  q.f[0] = USign(CGAL::NEGATIVE);
  q.g0 = USign(CGAL::POSITIVE);
  CHECK(relpos::discriminant_case(q) == DiscriminantCase::Undecided);
  q.f[3] = USign(CGAL::POSITIVE);
  CHECK(relpos::discriminant_case(q) == DiscriminantCase::TwoPositive);
  q.f[3] = USign(CGAL::NEGATIVE);
  q.f[2] = USign(CGAL::NEGATIVE);
  CHECK(relpos::discriminant_case(q) == DiscriminantCase::Undecided);  // f1 unknown
  q.f[1] = USign(CGAL::ZERO);
  CHECK(relpos::discriminant_case(q) == DiscriminantCase::AllNegative);  // zeros are skipped
  // V = 4 contradicts the theorem (>= 2 negative roots): never trusted.
  q.f[3] = USign(CGAL::POSITIVE), q.f[2] = USign(CGAL::NEGATIVE), q.f[1] = USign(CGAL::POSITIVE);
  CHECK(relpos::discriminant_case(q) == DiscriminantCase::Undecided);
  // f0 >= 0 or f4 >= 0 cannot happen for a valid pair: undecided.
  q.f[0] = USign(CGAL::POSITIVE);
  CHECK(relpos::discriminant_case(q) == DiscriminantCase::Undecided);
}

TEST_CASE("the paper's discriminant tracker is wrong twice; relpos is not", "[contact][paper]") {
  const Rational a(1), b(2), r(1, 4);
  const Paraboloid p = Paraboloid::from_matrix(paraboloid_matrix(a, b));
  struct Case {
    const char* name;
    Vector3 c;
    Position expected;
    Contact contact;
  };
  const std::vector<Case> cases = {
      // -b^2 = -4 is a double root of f that is not a tangency (math.md §3).
      {"C with Disc = 0", V(Q(1), Q(0), Q(131, 192)), Position::C, Contact::Crossing},
      {"E with Disc = 0", V(Q(6, 5), Q(0), Q(857, 1600)), Position::E, Contact::None},
      // A body that crossed all the way in: Disc > 0, like E.
      {"I with Disc > 0", V(Q(0), Q(0), Q(1)), Position::I, Contact::None},
      {"I with Disc > 0, dyadic", V(Q(1, 4), Q(1, 8), Q(3, 2)), Position::I, Contact::None},
  };
  for (const auto& k : cases) {
    INFO(k.name);
    const Ellipsoid e = Ellipsoid::from_matrix(sphere_matrix(k.c, r));
    const Classification x = relpos::classify_exact(e, p, Evidence::Full);
    REQUIRE(x.verdict.position == k.expected);
    const Position paper = paper_tracker(x.f);
    CHECK(paper != k.expected);  // the paper's tracker says TE, TE, E, E
    if (k.expected == Position::I) {
      CHECK(x.verdict.sign_disc_f > 0);
      CHECK(paper == Position::E);
    } else {
      CHECK(x.verdict.sign_disc_f == 0);
      CHECK(paper == Position::TE);
      CHECK(exact_case(x.f) == DiscriminantCase::Undecided);  // the discriminant cannot decide
    }
    const auto d = relpos::detail::decide_by_discriminant(e, p);
    CHECK(d.verdict.position == k.expected);
    const ContactAnswer c = relpos::contact(e, p);
    CHECK(c.contact == k.contact);
    CHECK(relpos::ContactChecker(p).contact(e).contact == k.contact);
    relpos::ExteriorTracker tr(p, e);
    CHECK(tr.update(e).position == k.expected);
  }
}

TEST_CASE("contact on constructed tangencies and their neighbours", "[contact][constructed]") {
  Rng g(77);
  int n = 0;
  for (int rep = 0; rep < 6; ++rep) {
    const Rational a = g.positive_rational(4, 2), b = g.positive_rational(4, 2);
    const auto st = random_st(g, rep % 2 == 0);
    const TangentPoint tp = tangent_point(a, b, st.first, st.second);
    const Rational r = random_tangent_radius(g, a, b);
    for (const Config& k : tangency_family(tp, r, g.uniform(1, 7))) {
      INFO(describe(k));
      const Ellipsoid e = Ellipsoid::from_matrix(k.e());
      const Paraboloid p = Paraboloid::from_matrix(k.p());
      const ContactAnswer c = relpos::contact(e, p);
      CHECK(c.position == k.expected);
      const Contact want = (k.expected == Position::TI || k.expected == Position::TE) ? Contact::Touching
                           : k.expected == Position::C                                ? Contact::Crossing
                                                                                      : Contact::None;
      CHECK(c.contact == want);
      CHECK(relpos::ContactChecker(p).contact(e).contact == want);
      ++n;
    }
  }
  // Spheres on the axis of z = x^2 + y^2/4 with dyadic data (exact doubles: the filter path).
  const Paraboloid p = Paraboloid::from_matrix(paraboloid_matrix(Q(1), Q(2)));
  const Rational r(1, 4);
  for (long k = -24; k <= 24; ++k) {
    const Rational z = Q(k, 32);
    const Ellipsoid e = Ellipsoid::from_matrix(sphere_matrix(V(Q(0), Q(0), z), r));
    const Position expected = axis_position(z, r);
    const ContactAnswer c = relpos::contact(e, p);
    INFO("z = " << relpos::to_string(z));
    CHECK(c.position == expected);
    check_contact_consistent(c, relpos::decide_position(e, p));
    ++n;
  }
  CHECK(n > 60);
}

TEST_CASE("contact beyond smallness", "[contact][large]") {
  const Paraboloid p = Paraboloid::from_matrix(paraboloid_matrix(Q(1), Q(1)));
  // rho = 4 r^2 / a^4 = 16 > 1 for r = 2.
  const Rational r(2);
  {  // Deep inside: I for any size (math.md §8), and the containment certificate agrees.
    const Ellipsoid e = Ellipsoid::from_matrix(sphere_matrix(V(Q(0), Q(0), Q(100)), r));
    const Verdict v = relpos::decide_position(e, p);
    CHECK(v.position == Position::I);
    CHECK(v.position == secular_position(e, p));
    const ContactAnswer c = relpos::contact(e, p);
    CHECK(c.contact == Contact::None);
    // Not small with four negative roots: the gap test of math.md §8 runs in the classifier (the
    // discriminant-only path declines), so the full classifier decides.
    CHECK(c.stage == v.stage);
    const ContactAnswer s = relpos::ContactChecker(p).contact(e);
    CHECK(s.contact == Contact::None);
    CHECK(s.stage == v.stage);  // no early-out either
    check_contact_consistent(c, v);
  }
  {  // Across the vertex: non-real roots, crossing for any size.
    const Ellipsoid e = Ellipsoid::from_matrix(sphere_matrix(V(Q(0), Q(0), Q(0)), r));
    const Verdict v = relpos::decide_position(e, p);
    CHECK(v.position == Position::C);
    CHECK(v.position == secular_position(e, p));
    const ContactAnswer c = relpos::contact(e, p);
    CHECK(c.contact == Contact::Crossing);
    check_contact_consistent(c, v);
  }
  {  // Far outside: E for any size.
    const Ellipsoid e = Ellipsoid::from_matrix(sphere_matrix(V(Q(0), Q(0), Q(-10)), r));
    CHECK(relpos::contact(e, p).contact == Contact::None);
    CHECK(relpos::contact(e, p).position == Position::E);
  }
  {  // TE with a large sphere (any size).
    const Ellipsoid e = Ellipsoid::from_matrix(sphere_matrix(V(Q(0), Q(0), Q(-2)), r));
    CHECK(relpos::contact(e, p).contact == Contact::Touching);
  }
}

TEST_CASE("smallness and the level are translation invariant (exact)", "[contact][tracker]") {
  Rng g(4242);
  for (int n = 0; n < 40; ++n) {
    const Transformed t =
        transform(sphere_matrix(V(Q(0), Q(0), Q(1)), g.positive_rational(3, 4)), paraboloid_matrix(Q(1), Q(2)), g);
    const Ellipsoid e0 = Ellipsoid::from_matrix(t.e);
    const Paraboloid p = Paraboloid::from_matrix(t.p);
    const Matrix4& E = e0.matrix();
    // det E = det M (e0 - e^T M^-1 e).
    Matrix3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = E(i, j);
    const Rational dm = det3(m);
    Matrix3 adj;  // adj(M) by cofactors
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        adj(i, j) = m(r0, c0) * m(r1, c1) - m(r0, c1) * m(r1, c0);
      }
    Rational ete(0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) ete += E(i, 3) * adj(i, j) * E(j, 3);
    CHECK(det4(E) == dm * (E(3, 3) - ete / dm));
    const Rational level = ete / dm - E(3, 3);
    // Translate by a random rational vector: E' = T^-T E T^-1, T^-1 = [[I, -v], [0, 1]].
    const Vector3 v{g.rational(-5, 5, 3), g.rational(-5, 5, 3), g.rational(-5, 5, 3)};
    const Matrix4 Et = congruence(E, affine_matrix(identity3(), V(-v[0], -v[1], -v[2])));
    const Ellipsoid e1 = Ellipsoid::from_matrix(Et);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(Et(i, j) == E(i, j));
    CHECK(det4(Et) == det4(E));
    Rational ete1(0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) ete1 += Et(i, 3) * adj(i, j) * Et(j, 3);
    CHECK(ete1 / dm - Et(3, 3) == level);
    const Classification x0 = relpos::classify_exact(e0, p, Evidence::Full);
    const Classification x1 = relpos::classify_exact(e1, p, Evidence::Full);
    CHECK(x0.verdict.rho_vs_one == x1.verdict.rho_vs_one);
    CHECK(x0.s == x1.s);
    CHECK(x0.f[0] == x1.f[0]);
    CHECK(x0.f[4] == x1.f[4]);
    if (x0.rho && x1.rho) CHECK(*x0.rho == *x1.rho);
  }
}

TEST_CASE("tracker equals decide_position at every frame of translated paths", "[contact][tracker]") {
  const Paraboloid p = Paraboloid::from_matrix(paraboloid_matrix(Q(1), Q(2)));
  std::size_t frames = 0, by_filter = 0, changes = 0;
  auto run = [&](const Ellipsoid& ref, auto placed_at, long steps, bool dyadic) {
    relpos::ExteriorTracker tr(p, ref);
    std::optional<Position> last;
    for (long k = 0; k <= steps; ++k) {
      const Ellipsoid e = placed_at(k);
      const auto fr = tr.update(e);
      const Verdict v = relpos::decide_position(e, p);
      INFO("frame " << k);
      check_same(Verdict{fr.position, {}, fr.rule}, v);
      CHECK(fr.changed == (last && *last != fr.position));
      if (fr.changed) ++changes;
      last = fr.position;
    }
    INFO("filter " << tr.counts().by_filter << " of " << tr.counts().frames);
    if (dyadic) {  // exact doubles: most frames by the discriminant alone (frames of a body that is
      // not small with four negative roots need math.md §8's gap test: the full classifier)
      frames += tr.counts().frames;
      by_filter += tr.counts().by_filter;
      CHECK(tr.counts().by_filter * 10 > tr.counts().frames * 6);
    }
    CHECK(tr.counts().frames == tr.counts().by_filter + tr.counts().by_fallback);
  };
  // A dyadic sphere (exact doubles) falling into the cup along a slanted line: E -> TE? -> C -> I.
  const Rational r(1, 4);
  auto sphere_at = [&](const Vector3& c0, const Vector3& d, long den) {
    return [=](long k) {
      const Rational t = Q(k, den);
      return Ellipsoid::sphere(V(c0[0] + t * d[0], c0[1] + t * d[1], c0[2] + t * d[2]), r);
    };
  };
  run(Ellipsoid::sphere(V(Q(0), Q(0), Q(0)), r), sphere_at(V(Q(3), Q(-1), Q(0)), V(Q(-3), Q(1), Q(2)), 256), 256, true);
  // Along x = 1, y = 0 through the special double root at z = 131/192 (rational times, fallback there).
  run(Ellipsoid::sphere(V(Q(0), Q(0), Q(0)), r), sphere_at(V(Q(1), Q(0), Q(-1)), V(Q(0), Q(0), Q(1)), 192), 384, false);
  // Straight down the axis: exact TE and TI frames (Disc = 0, fallback) between E, C and I.
  run(Ellipsoid::sphere(V(Q(0), Q(0), Q(0)), r), sphere_at(V(Q(0), Q(0), Q(-1)), V(Q(0), Q(0), Q(2)), 64), 64, true);
  // A general ellipsoid (dyadic axes, rotated by a rational quaternion) along a dyadic path.
  const Vector3 axes{Q(1, 4), Q(1, 8), Q(1, 16)};  // dyadic: M and the path are exact doubles
  const relpos::Quaternion q{Q(1), Q(0), Q(0), Q(0)};
  auto ell_at = [&](long k) {
    const Rational t = Q(k, 128);
    return Ellipsoid::from_axes(V(Q(2) - 2 * t, Q(1, 2) - t / 2, Q(-1, 2) + 2 * t), axes, q);
  };
  run(ell_at(0), ell_at, 128, true);
  CHECK(frames > 400);
  CHECK(changes >= 6);
  CHECK(by_filter * 10 > frames * 8);
}

TEST_CASE("tracker: frames that are not translates still get the right answer", "[contact][tracker]") {
  const Paraboloid p = Paraboloid::from_matrix(paraboloid_matrix(Q(1), Q(2)));
  relpos::ExteriorTracker tr(p, Ellipsoid::sphere(V(Q(0), Q(0), Q(3)), Q(1, 4)));
  CHECK(tr.rho_vs_one() < 0);
  // A larger sphere (rho > 1) deep inside: the reference's smallness must not be reused. (At depth
  // 8 the filter certifies Disc(f) > 0; much deeper the roots spread and the filter leaves it.)
  const Ellipsoid big = Ellipsoid::sphere(V(Q(0), Q(0), Q(8)), Q(2));
  const auto fr = tr.update(big);
  const Verdict vb = relpos::decide_position(big, p);
  CHECK(fr.position == vb.position);
  CHECK(fr.position == Position::I);  // not small, yet decided (math.md §8)
  CHECK(fr.stage == vb.stage);        // the gap test of math.md §8 is the classifier's
  CHECK(tr.counts().rho_recomputed == 1);
  // A different shape block (ellipsoid) crossing the wall.
  const Ellipsoid ell = Ellipsoid::from_axes(V(Q(1), Q(0), Q(1)), V(Q(1, 4), Q(1, 8), Q(1, 8)),
                                             relpos::Quaternion{Q(1), Q(0), Q(0), Q(0)});
  CHECK(tr.update(ell).position == relpos::decide_position(ell, p).position);
}

TEST_CASE("decided_by: the part of the contact-only path each stage belongs to", "[contact]") {
  for (const Stage s : relpos::kAllStages) {
    INFO(relpos::to_string(s));
    const bool early_out = s == Stage::InsideCertificate || s == Stage::OutsideCertificate;
    const bool classifier =
        std::find(relpos::detail::kClassifierStages.begin(), relpos::detail::kClassifierStages.end(), s) !=
        relpos::detail::kClassifierStages.end();
    CHECK(relpos::decided_by(s) == (early_out                        ? "scene-certificate"
                                    : s == Stage::DiscriminantFilter ? "discriminant-filter"
                                                                     : "full-classifier"));
    CHECK(early_out + classifier + (s == Stage::DiscriminantFilter) == 1);  // the three parts partition the stages
  }
}

TEST_CASE("random agreement with classify; the discriminant path decides most pairs", "[contact][random]") {
  DoublePairs gen(987654321);
  Rng g(5);
  std::size_t n = 0, by_disc = 0, exact_checked = 0, tracker_filter = 0;
  std::array<std::size_t, relpos::kAllStages.size()> checker_by{};
  const int total = 3000;
  for (int i = 0; i < total; ++i) {
    auto [E, P] = gen.next();
    std::optional<Ellipsoid> e;
    std::optional<Paraboloid> p;
    try {
      e.emplace(Ellipsoid::from_matrix(E));
      p.emplace(Paraboloid::from_matrix(P));
    } catch (const std::exception&) {
      continue;
    }
    ++n;
    INFO("pair " << i);
    const Verdict v = relpos::decide_position(*e, *p);
    const auto d = relpos::detail::decide_by_discriminant(*e, *p);
    check_same(d.verdict, v);
    if (d.verdict.stage == Stage::DiscriminantFilter) {
      ++by_disc;
      CHECK(int(d.verdict.real_roots) == int(v.real_roots));
      CHECK(int(d.verdict.positive_roots) == int(v.positive_roots));
      CHECK(int(d.verdict.sign_disc_f) == int(v.sign_disc_f));
      if (d.rho_known) CHECK(int(d.verdict.rho_vs_one) == int(v.rho_vs_one));
    }
    const ContactAnswer c = relpos::contact(*e, *p);
    check_contact_consistent(c, v);
    const relpos::ContactChecker checker(*p);
    const ContactAnswer cs = checker.contact(*e);
    ++checker_by[static_cast<std::size_t>(cs.stage)];
    // What settled an answer is the discriminant test, a scene early-out (the checker) or decide_position.
    CHECK((c.stage == Stage::DiscriminantFilter || c.stage == v.stage));
    CHECK((cs.stage == Stage::DiscriminantFilter || cs.stage == Stage::InsideCertificate ||
           cs.stage == Stage::OutsideCertificate || cs.stage == v.stage));
    check_contact_consistent(cs, v);
    CHECK(cs.contact == c.contact);
    relpos::ExteriorTracker tr(*p, *e);
    const auto fr = tr.update(*e);
    CHECK(fr.position == v.position);
    if (fr.stage == Stage::DiscriminantFilter) ++tracker_filter;
    if (i % 25 == 0) {  // the reference path, without any filter
      const Classification x = relpos::classify_exact(*e, *p, Evidence::Minimal);
      CHECK(x.verdict.position == v.position);
      CHECK(c.contact == relpos::contact_of(v.position));
      ++exact_checked;
    }
  }
  INFO("pairs " << n << ", discriminant filter decided " << by_disc << ", tracker " << tracker_filter);
  REQUIRE(n > 2000);
  CHECK(by_disc * 100 > n * 90);
  CHECK(tracker_filter * 100 > n * 90);
  CHECK(exact_checked > 80);
  CHECK(checker_by[static_cast<std::size_t>(Stage::InsideCertificate)] +
            checker_by[static_cast<std::size_t>(Stage::OutsideCertificate)] >
        0);
}

TEST_CASE("random near-tangent and exactly tangent dyadic spheres", "[contact][random]") {
  // Spheres touching z = x^2 + y^2/4 at its vertex from either side (exact TE / TI, Disc = 0),
  // and shifted by 2^-k along the axis and sideways: every answer equals decide_position.
  const Paraboloid p = Paraboloid::from_matrix(paraboloid_matrix(Q(1), Q(2)));
  std::mt19937_64 rng(31337);
  std::size_t n = 0, tangent = 0;
  for (int i = 0; i < 600; ++i) {
    const Rational r = Q(static_cast<long>(rng() % 8) + 1, 32);  // <= 1/4: small
    const int side = (rng() & 1) ? 1 : -1;
    const int k = static_cast<int>(rng() % 50);
    Rational dz(0), dx(0);
    if (i % 3 != 0) dz = Rational(std::ldexp((rng() & 1) ? 1.0 : -1.0, -k - 1));
    if (i % 5 == 0) dx = Rational(std::ldexp(1.0, -static_cast<int>(rng() % 30) - 1));
    const Ellipsoid e = Ellipsoid::sphere(V(dx, Q(0), side * r + dz), r);
    const Verdict v = relpos::decide_position(e, p);
    if (v.position == Position::TI || v.position == Position::TE) ++tangent;
    const auto d = relpos::detail::decide_by_discriminant(e, p);
    check_same(d.verdict, v);
    check_contact_consistent(relpos::contact(e, p), v);
    relpos::ExteriorTracker tr(p, e);
    CHECK(tr.update(e).position == v.position);
    ++n;
  }
  CHECK(n == 600);
  CHECK(tangent > 50);
}

TEST_CASE("Ellipsoid::translated is the exact translate", "[contact][tracker]") {
  Rng g(2026);
  for (int n = 0; n < 200; ++n) {
    const Vector3 c{g.rational(-8, 8, 16), g.rational(-8, 8, 16), g.rational(-8, 8, 16)};
    const Vector3 d{g.rational(-40, 40, 7), g.rational(-40, 40, 9), g.rational(-40, 40, 5)};
    const Rational r = g.positive_rational(9, 16);
    // A sphere moved is the sphere about the moved centre.
    const Ellipsoid s = Ellipsoid::sphere(c, r).translated(d);
    CHECK(s.matrix().a == Ellipsoid::sphere(V(c[0] + d[0], c[1] + d[1], c[2] + d[2]), r).matrix().a);
    // A rotated ellipsoid moved is the one built about the moved centre; and it validates.
    const relpos::Quaternion q{Q(g.uniform(-3, 3)), Q(g.uniform(-3, 3)), Q(g.uniform(-3, 3)), Q(1 + g.uniform(0, 2))};
    const Vector3 axes{g.positive_rational(5, 4), g.positive_rational(5, 4), g.positive_rational(5, 4)};
    const Ellipsoid e = Ellipsoid::from_axes(c, axes, q).translated(d);
    CHECK(e.matrix().a == Ellipsoid::from_axes(V(c[0] + d[0], c[1] + d[1], c[2] + d[2]), axes, q).matrix().a);
    CHECK_NOTHROW(Ellipsoid::from_matrix(e.matrix()));
  }
}

TEST_CASE("tracker update(translation) equals decide_position on the moved body", "[contact][tracker]") {
  // Dyadic reference bodies moved by dyadic and by arbitrary double translations, including paths
  // through exact tangencies (Disc(f) = 0: the exact fallback) and generic frames (the filter on the
  // moved entries, without forming the moved ellipsoid).
  const Paraboloid p = Paraboloid::from_matrix(paraboloid_matrix(Q(1), Q(2)));
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t frames = 0, by_filter = 0, tangent_frames = 0;
  const Vector3 axes{Q(1, 4), Q(1, 8), Q(1, 16)};
  const Ellipsoid refs[3] = {
      Ellipsoid::sphere(V(Q(0), Q(0), Q(0)), Q(1, 4)),
      Ellipsoid::from_axes(V(Q(0), Q(0), Q(0)), axes, relpos::Quaternion{Q(1), Q(0), Q(0), Q(0)}),
      Ellipsoid::from_axes(V(Q(1, 2), Q(-1, 4), Q(3)), axes, relpos::Quaternion{Q(2), Q(1), Q(-1), Q(1)})};
  for (const Ellipsoid& ref : refs) {
    relpos::ExteriorTracker tr(p, ref);
    for (int k = 0; k <= 400; ++k) {
      std::array<double, 3> d;
      if (k % 4 == 0) {  // dyadic path down the axis: exact TE / TI frames for the sphere at z = -+1/4
        d = {0.0, 0.0, -1.0 + (k / 4) / 40.0};
      } else {
        d = {2 * u(rng), 2 * u(rng), 4 * u(rng) + 1};  // arbitrary doubles
      }
      const Vector3 t{relpos::exact_rational(d[0]), relpos::exact_rational(d[1]), relpos::exact_rational(d[2])};
      const Ellipsoid moved = ref.translated(t);
      const auto fr = tr.update(d);
      const Verdict v = relpos::decide_position(moved, p);
      INFO("frame " << k << " d = (" << d[0] << ", " << d[1] << ", " << d[2] << ")");
      CHECK(fr.position == v.position);
      CHECK(fr.rule == v.rule);
      if (v.position == Position::TI || v.position == Position::TE) ++tangent_frames;
      if (k % 50 == 0) CHECK(relpos::classify_exact(moved, p, Evidence::Minimal).verdict.position == fr.position);
    }
    frames += tr.counts().frames;
    by_filter += tr.counts().by_filter;
    std::cout << "[tracker-translation] filter " << tr.counts().by_filter << " of " << tr.counts().frames << "\n";
    CHECK(tr.counts().frames == 401);
  }
  INFO("by filter " << by_filter << " of " << frames);
  CHECK(tangent_frames >= 2);           // the sphere's path hits TE and TI exactly
  CHECK(by_filter * 10 >= frames * 8);  // the translated filter decides the generic frames (not the
                                        // not-small interior ones: math.md §8's gap test)
}
