// The fast reader of batch lines (src/io/fast_quadric.hpp) against the general reader: a quadric it
// takes has enclosures that contain the exact entries, the same exact matrix and the same position;
// a text it does not take (not JSON, another form, long numbers) is left to the general reader. The
// full evidence from its integer forms, and from forms whose scales' rests lie in either matrix.
#include <gmp.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algebra/decimal_recipe.hpp"
#include "algebra/forms.hpp"
#include "algebra/pair_size.hpp"
#include "algebra/pencil.hpp"
#include "io/batch.hpp"
#include "io/fast_quadric.hpp"
#include "io/general_io.hpp"
#include "io/json_tree.hpp"
#include "io/quadric_json.hpp"
#include "relpos/classify.hpp"
#include "relpos/general_classify.hpp"
#include "relpos/io.hpp"

namespace {

using relpos::Ellipsoid;
using relpos::Matrix4;
using relpos::Paraboloid;
using relpos::detail::io::fast_ellipsoid;
using relpos::detail::io::fast_paraboloid;

relpos::detail::io::Json general_json(const std::string& text, bool doubles) {
  relpos::detail::io::JsonReadOptions read;
  read.doubles = doubles;
  read.max_elements = 16;
  read.start_depth = 1;
  return relpos::detail::io::parse_json(text, read);
}

/// Every exact entry inside its enclosure (or equal to the double, when the quadric has doubles).
template <class Q>
void check_storage(const Q& q) {
  const Matrix4& m = q.matrix();
  const auto& enc = storage_of(q).enclosure();
  REQUIRE((q.doubles().has_value() || enc != nullptr));
  for (std::size_t k = 0; k < 16; ++k) {
    if (q.doubles()) {
      REQUIRE(relpos::Rational((*q.doubles())[k]) == m.a[k]);
    } else {
      REQUIRE(relpos::Rational(enc->lo[k]) <= m.a[k]);
      REQUIRE(m.a[k] <= relpos::Rational(enc->hi[k]));
    }
  }
}

/// The integer form and split scale the quadric's recipe writes from its numbers
/// (forms::integer_form_of) are those of its exact matrix, factor for factor; for a standard
/// paraboloid off the axis the factors a coprime base of the same rest (what divided_by_powers
/// reads), perhaps coarser than split_scale's (recipe_integer_form.cpp).
template <class Q>
void check_integer_form(const Q& q) {
  using relpos::Integer;
  relpos::detail::forms::MatrixOf<Integer> m;
  Integer l, l2;
  relpos::detail::forms::SplitScale s;
  relpos::detail::forms::integer_form_of(storage_of(q), {relpos::detail::forms::entries(m), l, s});
  const relpos::detail::forms::MatrixOf<Integer> m2 = relpos::detail::forms::integer_form(q.matrix(), l2);
  const relpos::detail::forms::SplitScale s2 = relpos::detail::forms::split_scale(l2, q.matrix());
  REQUIRE(l == l2);
  for (std::size_t k = 0; k < 16; ++k) REQUIRE(m.a[k] == m2.a[k]);
  REQUIRE(s.twos == s2.twos);
  REQUIRE(s.fives == s2.fives);
  REQUIRE(s.rest == s2.rest);
  REQUIRE(s.rest_power.size() == s2.rest_power.size());
  for (std::size_t k = 0; k < s.rest_power.size(); ++k) REQUIRE(s.rest_power[k] == s2.rest_power[k]);
  const relpos::detail::DecimalRecipe* recipe = storage_of(q).recipe();
  if (recipe && recipe->form == relpos::detail::DecimalRecipe::Form::Standard &&
      (recipe->n[0].m != 0 || recipe->n[1].m != 0)) {
    Integer product(1);
    for (std::size_t k = 0; k < s.factors.size(); ++k) {
      for (unsigned long i = 0; i < s.factors[k].power; ++i) product *= s.factors[k].base;
      for (std::size_t j = 0; j < k; ++j) {
        Integer g;  // fresh: written through mpz()
        mpz_gcd(g.mpz(), s.factors[k].base.mpz(), s.factors[j].base.mpz());
        REQUIRE(g == 1);
      }
    }
    REQUIRE((s.factors.empty() ? s.rest == 1 : product == s.rest));
    return;
  }
  REQUIRE(s.factors.size() == s2.factors.size());
  for (std::size_t k = 0; k < s.factors.size(); ++k) {
    REQUIRE(s.factors[k].base == s2.factors[k].base);
    REQUIRE(s.factors[k].power == s2.factors[k].power);
  }
}

/// The truncated doubles the quadric's recipe writes without its matrix (the certificate's curve
/// search reads them) are those of the exact matrix, entry by entry; every recipe of decimal numbers
/// writes them, a recipe of doubles leaves them to the matrix.
template <class Q>
void check_truncated_doubles(const Q& q) {
  const relpos::detail::DecimalRecipe* recipe = storage_of(q).recipe();
  if (!recipe) return;
  relpos::DoubleMatrix4 d;
  const bool written = relpos::detail::truncated_doubles(*recipe, d);
  REQUIRE(written == !recipe->doubles);
  if (!written) return;
  for (std::size_t k = 0; k < 16; ++k) REQUIRE(d[k] == relpos::detail::forms::truncated_double(q.matrix().a[k]));
}

/// The full evidence of a pair read by the fast reader (integer forms from the numbers read, reduced
/// along their split scales) against rational arithmetic on the general reader's matrices: f and s
/// coefficient by coefficient, rho = (f0 / f4) (s2 / s0) / lambda_s^2 with lambda_s the root of s
/// nearest 0 when that is rational (always for a sphere and a standard paraboloid: s factors), the
/// roots and the certificate, and the whole report but the deciding stage as the general reader's
/// quadrics give it.
void check_full_evidence(const Ellipsoid& fe, const Paraboloid& fp, const Ellipsoid& ge, const Paraboloid& gp) {
  using relpos::Rational;
  const relpos::Classification c = relpos::classify(fe, fp, relpos::Evidence::Full);
  const auto f = relpos::characteristic_polynomial<Rational>(gp.matrix(), ge.matrix());
  const auto s = relpos::special_polynomial<Rational>(gp.matrix(), ge.matrix());
  for (std::size_t k = 0; k < 5; ++k) REQUIRE(c.f[k] == f[k]);
  for (std::size_t k = 0; k < 3; ++k) REQUIRE(c.s[k] == s[k]);
  const Rational disc = s[1] * s[1] - 4 * s[2] * s[0];
  Rational root;  // sqrt(disc) when disc is a square (in lowest terms: numerator and denominator are)
  mpz_sqrt(mpq_numref(root.mpq()), mpq_numref(disc.mpq()));
  mpz_sqrt(mpq_denref(root.mpq()), mpq_denref(disc.mpq()));
  REQUIRE(c.rho.has_value() == (root * root == disc));
  if (c.rho) {
    const Rational lambda_s = (root - s[1]) / (2 * s[2]);
    REQUIRE(*c.rho == f[0] * s[2] / (f[4] * s[0] * lambda_s * lambda_s));
  }
  // The roots, isolated on the common-lcm integer form S^4 f (S from the split scales), are f's: an
  // exact one is a root, a simple one changes f's sign across its interval; the certificate holds.
  auto at = [&](const Rational& x) { return (((f[4] * x + f[3]) * x + f[2]) * x + f[1]) * x + f[0]; };
  for (const relpos::RealRoot& r : c.roots) {
    if (r.exact) REQUIRE(at(*r.exact) == 0);
    if (!r.exact && r.multiplicity_f == 1) REQUIRE(CGAL::sign(at(r.lower)) * CGAL::sign(at(r.upper)) < 0);
  }
  REQUIRE_FALSE(relpos::verify_certificate(ge, gp, c.verdict.position, c.certificate));
  relpos::Classification g = relpos::classify(ge, gp, relpos::Evidence::Full);
  g.verdict.stage = c.verdict.stage;  // the stage that decided depends on the reader (enclosures or exact)
  REQUIRE(relpos::io::classification_json_text(c) == relpos::io::classification_json_text(g));
}

/// Both texts taken by the fast reader, with the general reader's exact matrices inside the stored
/// enclosures, and the same position as classify_exact on the general reader's quadrics.
void check_pair(const std::string& e_text, const std::string& p_text, bool doubles) {
  INFO(e_text << "  " << p_text << (doubles ? "  (--numbers double)" : ""));
  const auto fe = fast_ellipsoid(e_text, doubles);
  const auto fp = fast_paraboloid(p_text, doubles);
  REQUIRE(fe);
  REQUIRE(fp);
  const Ellipsoid ge = relpos::detail::io::ellipsoid_from_tree(general_json(e_text, doubles), "ellipsoid");
  const Paraboloid gp = relpos::detail::io::paraboloid_from_tree(general_json(p_text, doubles), "paraboloid");
  check_integer_form(*fe);
  check_integer_form(*fp);
  check_truncated_doubles(*fe);
  check_truncated_doubles(*fp);
  check_storage(*fe);
  check_storage(*fp);
  REQUIRE(fe->matrix() == ge.matrix());
  REQUIRE(fp->matrix() == gp.matrix());
  REQUIRE(relpos::decide_position(*fe, *fp).position == relpos::classify_exact(ge, gp).verdict.position);
}

/// check_pair with the full evidence (check_full_evidence).
void check_pair_evidence(const std::string& e_text, const std::string& p_text, bool doubles) {
  check_pair(e_text, p_text, doubles);
  INFO(e_text << "  " << p_text << (doubles ? "  (--numbers double)" : ""));
  check_full_evidence(*fast_ellipsoid(e_text, doubles), *fast_paraboloid(p_text, doubles),
                      relpos::detail::io::ellipsoid_from_tree(general_json(e_text, doubles), "ellipsoid"),
                      relpos::detail::io::paraboloid_from_tree(general_json(p_text, doubles), "paraboloid"));
}

/// The decimal d 10^exponent, d of `digits` random significant digits, in one of the spellings JSON
/// allows (exponent, fraction, plain, trailing zeros), sometimes negative.
std::string decimal(std::mt19937_64& rng, int digits, int exponent, bool negative) {
  std::string d;
  for (int i = 0; i < digits; ++i) d += static_cast<char>('0' + (i == 0 ? 1 + rng() % 9 : rng() % 10));
  const std::string s = negative ? "-" : "";
  const auto n = static_cast<std::size_t>(digits);
  switch (rng() % 4) {
    case 0:
      return s + d + "e" + std::to_string(exponent);
    case 1: {  // d[0].d[1..] E (exponent + digits - 1)
      const int x = exponent + digits - 1;
      return s + d.substr(0, 1) + "." + (digits > 1 ? d.substr(1) : "0") + (x >= 0 ? "E+" : "E") + std::to_string(x);
    }
    case 2:  // a fraction or an integer, no exponent
      if (exponent >= 0) return s + d + std::string(static_cast<std::size_t>(exponent), '0');
      if (static_cast<std::size_t>(-exponent) >= n)
        return s + "0." + std::string(static_cast<std::size_t>(-exponent) - n, '0') + d;
      return s + d.substr(0, n - static_cast<std::size_t>(-exponent)) + "." +
             d.substr(n - static_cast<std::size_t>(-exponent));
    default:
      return s + d + "000e" + std::to_string(exponent - 3);
  }
}

std::string vec3(const std::string& a, const std::string& b, const std::string& c) {
  return "[" + a + "," + b + "," + c + "]";
}

}  // namespace

TEST_CASE("fast reader: spheres and standard paraboloids agree with the general reader", "[io][fast]") {
  std::mt19937_64 rng(7);
  int taken = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const bool doubles = trial % 5 == 4;
    auto num = [&](bool positive) {
      const int digits = 1 + static_cast<int>(rng() % 19);
      return decimal(rng, digits, -static_cast<int>(rng() % 4) - digits + 1, !positive && rng() % 2 == 0);
    };
    const std::string e_text = "{\"sphere\":{\"" + std::string(trial % 2 ? "center" : "centre") +
                               "\":" + vec3(num(false), num(false), num(false)) + ",\"radius\":" + num(true) + "}}";
    const std::string p_text =
        "{\"vertex\":" + vec3(num(false), num(false), num(false)) + ",\"a\":" + num(true) + ",\"b\":" + num(true) + "}";
    check_pair_evidence(e_text, p_text, doubles);
    ++taken;
  }
  REQUIRE(taken == 400);
}

TEST_CASE("fast reader: matrices agree with the general reader, either orientation", "[io][fast]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 0.3), pos(0.8, 2.0), rad(0.01, 0.2);
  auto f = [](double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return std::string(b);
  };
  auto matrix = [&](const double(&m)[16], double sign) {
    std::string s = "[";
    for (int i = 0; i < 4; ++i) {
      s += i ? ",[" : "[";
      for (int j = 0; j < 4; ++j) s += (j ? "," : "") + f(sign * m[4 * i + j]);
      s += "]";
    }
    return s + "]";
  };
  for (int trial = 0; trial < 300; ++trial) {
    const double x = u(rng), y = u(rng), a = pos(rng), b = pos(rng), r = rad(rng);
    const double z = x * x / a / a + y * y / b / b + u(rng);
    const double em[16] = {1, 0, 0, -x, 0, 1, 0, -y, 0, 0, 1, -z, -x, -y, -z, x * x + y * y + z * z - r * r};
    const double pm[16] = {1 / a / a, 0, 0, 0, 0, 1 / b / b, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0};
    const double sign = trial % 3 == 2 ? -1 : 1;
    const bool doubles = trial % 4 == 3;
    const std::string e_text = trial % 2 ? matrix(em, sign) : "{\"matrix\":" + matrix(em, sign) + "}";
    const std::string p_text = trial % 2 ? "{\"matrix\":" + matrix(pm, sign) + "}" : matrix(pm, sign);
    check_pair(e_text, p_text, doubles);
  }
}

TEST_CASE("fast reader: exact doubles stay doubles; decimals that are not get enclosures", "[io][fast]") {
  const auto e = fast_ellipsoid(R"({"sphere":{"center":[0.5,-0.25,1],"radius":0.75}})", false);
  REQUIRE(e);
  REQUIRE(e->doubles());  // every entry (0.25 + 0.0625 + 1 - 0.5625 included) is a double
  const auto d = fast_ellipsoid(R"({"sphere":{"center":[0.1,0,0],"radius":1}})", false);
  REQUIRE(d);
  REQUIRE_FALSE(d->doubles());
  REQUIRE(storage_of(*d).enclosure());
  REQUIRE(d->matrix()(0, 3) == relpos::Rational(-1, 10));  // built exactly from the text on demand
  // --numbers double: 0.1 is the nearest double, exactly.
  const auto n = fast_ellipsoid(R"({"sphere":{"center":[0.1,0,0],"radius":1}})", true);
  REQUIRE(n);
  REQUIRE(n->matrix()(0, 3) == -relpos::Rational(0.1));
}

TEST_CASE("fast reader: texts it leaves to the general reader", "[io][fast]") {
  // Not JSON, or not plainly: the general reader gives the error or reads the escapes.
  for (const char* text : {"",
                           "[",
                           "{}",
                           "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1],]",
                           "01",
                           "1.",
                           ".5",
                           "-",
                           "1e",
                           "+1",
                           "NaN",
                           R"({"sphere":{"center":[0,0,0],"radius":1}})"
                           "x",
                           R"({"sph\u0065re":{"center":[0,0,0],"radius":1}})",
                           R"({"sphere":{"center":[0,0,0],"radius":1,"radius":2}})",
                           R"({"sphere":{"center":[0,0,0],"centre":[0,0,0],"radius":1}})",
                           R"({"sphere":{"center":[0,0,0],"radius":0}})",
                           R"({"sphere":{"center":[0,0,0],"radius":-1}})",
                           R"({"sphere":{"center":[0,0,0],"radius":12345678901234567891}})",
                           R"({"sphere":{"center":[0,0,0],"radius":1e31}})",
                           R"({"sphere":{"center":[0,0],"radius":1}})",
                           R"({"axes":[1,2,3],"center":[0,0,0]})",
                           "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]",     // imaginary: the general error
                           "[[1,0,0,0.5],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]",  // not symmetric
                           "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1],[0,0,0,0]]"})
    REQUIRE_FALSE(fast_ellipsoid(text, false));
  for (const char* text : {R"({"vertex":[0,0,0],"a":1,"b":1,"rotation":[1,0,0,0]})", R"({"vertex":[0,0,0],"a":1})",
                           R"({"vertex":[0,0,0],"a":0,"b":1})", R"({"vertex":[0,0,0],"a":1,"b":-1})",
                           "[[1,0,0,0],[0,1,0,0],[0,0,1,-0.5],[0,0,-0.5,0]]"})  // an ellipsoid
    REQUIRE_FALSE(fast_paraboloid(text, false));
  // A valid paraboloid whose det Q3 = 0 (Q3 = A^T A, A = [[1,1,1],[1,2,3]]) is not shown by zero
  // entries: the general reader takes it.
  const char* tilted = "[[2,3,4,-0.5],[3,5,7,1],[4,7,10,-0.5],[-0.5,1,-0.5,0]]";
  REQUIRE_FALSE(fast_paraboloid(tilted, false));
  REQUIRE_NOTHROW(relpos::detail::io::paraboloid_from_tree(general_json(tilted, false), "paraboloid"));
  // det Q3 = 0 by zeros, although rotated about the axis: taken.
  REQUIRE(fast_paraboloid("[[1,0.5,0,0],[0.5,1,0,0],[0,0,0,-0.5],[0,0,-0.5,0]]", false));
  // Exactly symmetric although spelled differently: taken.
  REQUIRE(fast_ellipsoid("[[1,0,0,0.5],[0,1,0,0],[0,0,1,0],[5e-1,0,0,-1]]", false));
  REQUIRE(fast_ellipsoid("[[-1,0,0,0],[0,-1,0,0],[0,0,-1,0],[0,0,0,1]]", false)->matrix()(0, 0) == 1);
}

TEST_CASE("fast reader: its numbers keep the normalized size far below the limit", "[io][fast]") {
  // The extremes of the reader's numbers (19 digits, decimal exponent +-30) in the forms whose
  // entries have the highest degree.
  const std::string big = "9999999999999999999e11", tiny = "-1234567890123456789e-30", odd = "7777777777777777777e-30";
  const auto e = fast_ellipsoid("{\"sphere\":{\"center\":" + vec3(big, tiny, odd) + ",\"radius\":" + odd + "}}", false);
  const auto p =
      fast_paraboloid("{\"vertex\":" + vec3(tiny, big, odd) + ",\"a\":" + odd + ",\"b\":" + big + "}", false);
  REQUIRE(e);
  REQUIRE(p);
  REQUIRE(relpos::detail::normalized_bits(e->matrix()) <= 1500);
  REQUIRE(relpos::detail::normalized_bits(p->matrix()) <= 1500);
  relpos::detail::check_normalized_pair_size(*e, *p);  // does not build the matrices, does not throw
}

TEST_CASE("full evidence with scales whose rests lie in either matrix or in both", "[io][fast]") {
  // S = lcm(lp, le) from the split scales: the rest (the scale without its 2s and 5s) in P only (a
  // standard paraboloid with decimal a and b beside a decimal sphere), in E only, in both, in neither.
  using relpos::Rational;
  relpos::Matrix3 axes;  // E: the image of the unit ball under diag(3/2, 7/4, 1): M = diag(4/9, 16/49, 1)
  axes(0, 0) = Rational(3, 2);
  axes(1, 1) = Rational(7, 4);
  axes(2, 2) = Rational(1);
  // Crossing the paraboloid, and below it (separated: f has two positive roots, isolated on S^4 f).
  const relpos::Vector3 crossing{Rational(1, 10), Rational(-1, 5), Rational(3, 10)};
  const relpos::Vector3 below{Rational(1, 10), Rational(-1, 5), Rational(-5)};
  std::vector<Ellipsoid> es;
  for (const relpos::Vector3& centre : {crossing, below}) {
    es.push_back(Ellipsoid::from_map(centre, axes));
    es.push_back(Ellipsoid::sphere(centre, Rational(1, 2)));
  }
  const relpos::Vector3 vertex{Rational(0), Rational(0), Rational(-1, 2)};
  for (const Ellipsoid& e : es)
    for (const auto& ab :
         {std::make_pair(Rational(1, 2), Rational(2)), std::make_pair(Rational(3, 10), Rational(7, 10)),
          std::make_pair(Rational(3, 2), Rational(7, 4))}) {
      const Paraboloid p = Paraboloid::standard(vertex, ab.first, ab.second);
      check_full_evidence(e, p, e, p);
    }
}

TEST_CASE("fast reader: long digit runs, at most 19 significant digits, zeros", "[io][fast]") {
  // Runs of eight digits and more are read eight at a time: around that and the 19-digit bound, the
  // numbers taken are the general reader's, and more significant digits go to the general reader.
  const std::string ok[] = {"0.1234567890123456789",     "1234567890123456789",           "1234567890123456789000000",
                            "1234567890123456789.000",   "0.000000001234567890123456789", "12345678.12345678",
                            "1000000000000000001",       "10000000000000000010e-12",      "99999999.9999999990000e-5",
                            "-0.0000000000012345678E+3", "7.00000000000000000000000000"};
  for (const std::string& x : ok) {
    const std::string abs = x.substr(x[0] == '-' ? 1 : 0);
    check_pair("{\"sphere\":{\"center\":" + vec3(x, "-" + abs, "0.5") + ",\"radius\":" + abs + "}}",
               "{\"vertex\":" + vec3(x, "0", x) + ",\"a\":1.5,\"b\":" + abs + "}", false);
  }
  for (const char* x : {"12345678901234567891", "0.12345678901234567891", "1234567890123456789.1",
                        "10000000000000000001", "100000000000000000010e-12", "1.2345678901234567891e5"})
    REQUIRE_FALSE(fast_ellipsoid("{\"sphere\":{\"center\":[0,0,0],\"radius\":" + std::string(x) + "}}", false));
}

TEST_CASE("fast reader: a value at the start of a longer text, with its end", "[io][fast]") {
  using relpos::detail::io::fast_ellipsoid_at;
  using relpos::detail::io::fast_paraboloid_at;
  const std::string sphere = R"({"sphere":{"center":[0.1,0,12345678.123456789],"radius":1}})";
  const std::string cup = "[[1,0,0,0],[0,2.5,0,0],[0,0,0,-0.5],[0,0,-0.5,0]]";
  std::optional<Ellipsoid> e;
  std::optional<Paraboloid> p;
  for (const std::string tail : {"", "}", ",\"id\":1}", " ]", "x"}) {
    std::size_t end = 0;
    REQUIRE(fast_ellipsoid_at(sphere + tail, false, end, e));
    REQUIRE(e);
    REQUIRE(end == sphere.size());
    REQUIRE(e->matrix() == fast_ellipsoid(sphere, false)->matrix());
    REQUIRE(fast_paraboloid_at(cup + tail, false, end, p));
    REQUIRE(p);
    REQUIRE(end == cup.size());
  }
  // Scanned but not taken (an ellipsoid's text as a paraboloid): the end is still known, and the
  // quadric left empty.
  std::size_t end = 0;
  REQUIRE_FALSE(fast_paraboloid_at(sphere + ",", false, end, p));
  REQUIRE_FALSE(p);
  REQUIRE(end == sphere.size());
  // Not scanned (an escape in a key, a string value): no end.
  for (const char* text : {R"({"sph\u0065re":{"center":[0,0,0],"radius":1}},)", R"("x",)", "[1,2,", "-"}) {
    REQUIRE_FALSE(fast_ellipsoid_at(text, false, end, e));
    REQUIRE_FALSE(e);
    REQUIRE(end == std::string::npos);
  }
}

TEST_CASE("fast reader: spheres and paraboloids on the axis over the whole exponent range", "[io][fast]") {
  // The exact matrices of these forms are written from the decimals' digits and powers of 2 and 5
  // (fast_quadric.cpp): they must be the constructors' rationals, for mantissas with factors 2 or 5,
  // exponents of either sign and sums that cancel.
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 400; ++trial) {
    auto num = [&](bool positive) {
      const int digits = 1 + static_cast<int>(rng() % 19);
      const int exponent = static_cast<int>(rng() % 41) - 30 - (digits - 1) / 2;
      std::string x = decimal(rng, digits, std::max(-30, std::min(exponent, 30 - digits)), false);
      if (trial % 7 == 0)
        x = std::to_string((1 + rng() % 9) * (rng() % 2 ? 25 : 16)) + "e-" + std::to_string(rng() % 9);
      return !positive && rng() % 2 ? "-" + x : x;
    };
    const std::string c = num(false), r = trial % 5 == 0 ? c.substr(c[0] == '-' ? 1 : 0) : num(true);
    const std::string e_text =
        "{\"sphere\":{\"center\":" + vec3(c, trial % 3 ? num(false) : "0", num(false)) + ",\"radius\":" + r + "}}";
    const std::string p_text = "{\"vertex\":" + vec3("0", "0", trial % 4 ? num(false) : "0") + ",\"a\":" + num(true) +
                               ",\"b\":" + num(true) + "}";
    check_pair_evidence(e_text, p_text, false);
  }
  // a and b whose mantissas share factors (3, 3^2 7), are equal, or are powers of 2 and 5.
  for (const char* ab : {R"("a":0.33,"b":2.1)", R"("a":6.3,"b":0.441)", R"("a":1.7,"b":1.7)", R"("a":0.8,"b":1.25)",
                         R"("a":3,"b":9e-1)", R"("a":1.5,"b":1.5e1)"})
    check_pair_evidence(R"({"sphere":{"center":[0.1,-0.25,0.125],"radius":1e-2}})",
                        std::string(R"({"vertex":[0,0,-0.5],)") + ab + "}", false);
  // A sum that cancels: the constant entry is exactly zero.
  check_pair_evidence(R"({"sphere":{"center":[0,-0.3,0],"radius":3e-1}})",
                      R"({"vertex":[0,0,-2.5e-3],"a":0.5,"b":125})", false);
  REQUIRE(fast_ellipsoid(R"({"sphere":{"center":[0,-0.3,0],"radius":3e-1}})", false)->matrix()(3, 3) == 0);
}

TEST_CASE("fast reader: only a decimal sphere and a paraboloid on the axis get closed forms", "[io][fast]") {
  // Other forms keep the general path: a vertex off the axis, a matrix, --numbers double.
  for (const auto& [body, doubles] : {std::make_pair(R"({"vertex":[0.1,0,0],"a":1.3,"b":0.7})", false),
                                      std::make_pair(R"({"vertex":[0,0,0.1],"a":1.3,"b":0.7})", true)}) {
    const auto q = fast_paraboloid(body, doubles);
    REQUIRE(q);
    const relpos::detail::DecimalRecipe* recipe = storage_of(*q).recipe();
    CHECK((!recipe || !relpos::detail::has_closed_form(*recipe)));
  }
  const auto m = fast_ellipsoid("[[1,0,0,0.1],[0,1,0,0],[0,0,1,0],[0.1,0,0,-0.3]]", false);
  REQUIRE(m);
  REQUIRE(storage_of(*m).recipe());
  CHECK_FALSE(relpos::detail::has_closed_form(*storage_of(*m).recipe()));
  const auto sphere = fast_ellipsoid(R"({"sphere":{"center":[0.1,0,0],"radius":0.3}})", false);
  REQUIRE(sphere);
  REQUIRE(storage_of(*sphere).recipe());
  CHECK(relpos::detail::has_closed_form(*storage_of(*sphere).recipe()));
}

TEST_CASE("fast reader: closed forms end to end, with mantissas that share primes", "[io][fast]") {
  // The radius, the centre and vz multiples of a's or b's mantissa, and a's of b's: the closed forms'
  // reductions (tests/test_decimal_recipe.cpp) meet common factors beyond 2 and 5; the whole report
  // is the general path's (check_pair_evidence).
  std::mt19937_64 rng(43);
  const std::uint64_t primes[] = {2, 3, 5, 7, 11, 13, 9, 343, 1000003};
  auto mantissa = [&] {
    std::uint64_t m = 1 + rng() % 9;
    for (int k = static_cast<int>(rng() % 7); k > 0; --k) {
      const std::uint64_t p = primes[rng() % 9];
      if (m > 100000000000000000ULL / p) break;
      m *= p;
    }
    return m;
  };
  auto text = [&](std::uint64_t m, bool negative) {
    return (negative ? "-" : "") + std::to_string(m) + "e" + std::to_string(-static_cast<int>(rng() % 12));
  };
  for (int trial = 0; trial < 100; ++trial) {
    const std::uint64_t ma = mantissa(), mb = trial % 3 == 0 ? ma * (1 + rng() % 12) : mantissa();
    auto related = [&](bool negative) {
      const std::uint64_t pick = rng() % 4;
      return pick == 0   ? text(ma * (1 + rng() % 50), negative)
             : pick == 1 ? text(mb * (1 + rng() % 50), negative)
             : pick == 2 ? "0"
                         : text(mantissa(), negative);
    };
    const std::string z = related(rng() % 2 == 0);
    const std::string e_text = "{\"sphere\":{\"center\":" + vec3(related(true), related(false), z) +
                               ",\"radius\":" + (rng() % 3 == 0 ? text(ma, false) : text(mantissa(), false)) + "}}";
    // Every other vertex off the axis (the closed forms take it, math.md §2).
    const bool off = trial % 2 == 1;
    const std::string p_text = "{\"vertex\":" +
                               vec3(off ? related(rng() % 2 == 0) : "0", off ? related(false) : "0",
                                    trial % 7 == 0 ? z : related(rng() % 2 == 0)) +
                               ",\"a\":" + text(ma, false) + ",\"b\":" + text(mb, false) + "}";
    check_pair_evidence(e_text, p_text, false);
  }
}

TEST_CASE("fast reader: a decimal written as a string is the same number, the same stages", "[io][fast]") {
  // The general reader reads "0.18" as 0.18: the fast reader takes both spellings, so the quadric
  // gets one storage and the ladder the same stages (two regime pairs whose stage differed:
  // interval for numbers, semi-static-double for strings).
  const auto quoted = [](const std::string& line) {
    std::string out;
    bool in_number = false;
    const std::size_t from = line.find("\"ellipsoid\"");  // the id stays as it is
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      const bool digit = (c >= '0' && c <= '9') || c == '-';
      const bool part = digit || c == '.' || c == 'e' || c == 'E' || c == '+';
      const bool starts = !in_number && digit && i > from;
      if (starts) out += '"', in_number = true;
      if (in_number && !part) out += '"', in_number = false;
      out += c;
    }
    return out;
  };
  for (
      const std::string line :
      {R"({"id":2356,"ellipsoid":{"sphere":{"center":[-0.045171798541083441,-0.17801139965519919,0.0093831117817997564],"radius":0.18281975318707119}},"paraboloid":{"vertex":[0,0,0],"a":1.2365757725442075,"b":0.88088035061183523}})",
       R"({"id":2396,"ellipsoid":{"sphere":{"center":[-0.17480196320404073,-0.031704277866592023,-0.03390694111879778],"radius":0.17990845020637647}},"paraboloid":{"vertex":[0,0,0],"a":1.6504348510329787,"b":1.8065380509967925}})",
       R"({"id":1,"ellipsoid":[[2,0,0,0.1],[0,3,0,0.2],[0,0,1,-0.3],[0.1,0.2,-0.3,-0.7]],"paraboloid":[[1.5,0,0,0],[0,0.25,0,0],[0,0,0,-0.5],[0,0,-0.5,0]]})"}) {
    const std::string strings = quoted(line);
    INFO(strings);
    REQUIRE(std::count(strings.begin(), strings.end(), '"') >= std::count(line.begin(), line.end(), '"') + 16);
    for (const relpos::Evidence evidence : {relpos::Evidence::Minimal, relpos::Evidence::Full}) {
      relpos::detail::io::BatchOptions options;
      options.evidence = evidence;
      const std::string a = relpos::detail::io::answer_batch_line(line, 1, options);
      CHECK(a.find("\"error\"") == std::string::npos);
      CHECK(a == relpos::detail::io::answer_batch_line(strings, 1, options));
    }
    // And the quadrics themselves: the fast reader takes the strings.
    const std::size_t e = strings.find("\"ellipsoid\":") + 12, p = strings.find(",\"paraboloid\":");
    CHECK(fast_ellipsoid(std::string_view(strings).substr(e, p - e), false).has_value());
  }
}

namespace {

/// A matrix as text, each entry v spelled with 17 significant digits and its decimal exponent
/// moved by `shift`: the numbers of v 10^shift, exactly (the same mantissas).
std::string shifted_matrix(const double (&m)[16], int shift) {
  std::string s = "[";
  for (int i = 0; i < 4; ++i) {
    s += i ? ",[" : "[";
    for (int j = 0; j < 4; ++j) {
      const double v = m[4 * i + j];
      char b[48];
      std::snprintf(b, sizeof b, "%.16e", v);
      std::string t = b;
      const std::size_t e = t.find('e');
      if (v != 0) t = t.substr(0, e + 1) + std::to_string(std::stoi(t.substr(e + 1)) + shift);
      s += (j ? "," : "") + (v == 0 ? std::string("0") : t);
    }
    s += "]";
  }
  return s + "]";
}

}  // namespace

TEST_CASE("fast reader: a matrix scaled by a power of ten is read as the unscaled one", "[io][fast]") {
  // Known by construction: a positive factor changes neither the quadric nor the position. The
  // scaled texts are taken by the fast reader (not only the short ones), with the general reader's
  // exact matrices inside their enclosures, the same integer forms and the unscaled pair's position.
  std::mt19937_64 rng(300);
  std::uniform_real_distribution<double> u(-0.3, 0.3), pos(0.8, 2.0), rad(0.01, 0.4);
  for (int trial = 0; trial < 24; ++trial) {
    const double x = u(rng), y = u(rng), a = pos(rng), b = pos(rng), r = rad(rng);
    const double z = x * x / a / a + y * y / b / b + u(rng);
    // A = [[1, 1/4, 0], [1/4, 1, 0], [0, 0, 1]] about the centre (x, y, z), radius r: b = -A c.
    const double bx = -(x + 0.25 * y), by = -(0.25 * x + y), c0 = x * x + y * y + 0.5 * x * y + z * z - r * r;
    const double em[16] = {1, 0.25, 0, bx, 0.25, 1, 0, by, 0, 0, 1, -z, bx, by, -z, c0};
    const double pm[16] = {1 / a / a, 0, 0, -x, 0, 1 / b / b, 0, 0, 0, 0, 0, -0.5, -x, 0, -0.5, 3 * x};
    const int shifts[][2] = {{300, -300}, {-300, 300}, {100, 250}, {-280, -31}};
    const int* s = shifts[trial % 4];
    const std::string e0 = shifted_matrix(em, 0), p0 = shifted_matrix(pm, 0);
    const std::string es = shifted_matrix(em, s[0]), ps = shifted_matrix(pm, s[1]);
    check_pair(es, ps, false);
    if (trial < 2) check_pair_evidence(es, ps, false);
    REQUIRE(relpos::decide_position(*fast_ellipsoid(es, false), *fast_paraboloid(ps, false)).position ==
            relpos::decide_position(*fast_ellipsoid(e0, false), *fast_paraboloid(p0, false)).position);
  }
}

TEST_CASE("fast reader: scaled numbers it leaves to the general reader", "[io][fast]") {
  for (const char* text : {
           // exponents spanning more than 60 in one matrix (the size bound of fast_quadric.hpp)
           "[[1e300,0,0,0],[0,1e300,0,0],[0,0,1e300,0],[0,0,0,-1e239]]",
           // beyond 2^1020 (the filters' range), or beyond the double range
           "[[9e307,0,0,0],[0,9e307,0,0],[0,0,9e307,0],[0,0,0,-9e307]]",
           "[[1e341,0,0,0],[0,1e341,0,0],[0,0,1e341,0],[0,0,0,-1e341]]",
           "[[1e-341,0,0,0],[0,1e-341,0,0],[0,0,1e-341,0],[0,0,0,-1e-341]]",
           // 10^|e| beyond the double range, |e| up to the widest exponent read (its enclosure in
           // two steps of the table of powers: the sanitizer build checks every index)
           "[[1e-309,0,0,0],[0,1e-309,0,0],[0,0,1e-309,0],[0,0,0,-1e-309]]",
           "[[1e-335,0,0,0],[0,1e-335,0,0],[0,0,1e-335,0],[0,0,0,-1e-335]]",
           "[[1e-340,0,0,0],[0,1e-340,0,0],[0,0,1e-340,0],[0,0,0,-1e-340]]",
           "[[1e340,0,0,0],[0,1e340,0,0],[0,0,1e340,0],[0,0,0,-1e340]]",
           // a sphere's numbers stay short (its constant entry squares them)
           R"({"sphere":{"center":[1e40,0,0],"radius":1e40}})",
       }) {
    INFO(text);
    REQUIRE_FALSE(fast_ellipsoid(text, false));
  }
  REQUIRE_FALSE(fast_paraboloid(R"({"vertex":[0,0,1e-31],"a":1,"b":1})", false));
  // Within the bounds: taken, the exact matrix that of the text.
  const auto e = fast_ellipsoid("[[1e300,0,0,0],[0,1e300,0,0],[0,0,1e300,0],[0,0,0,-1e240]]", false);
  REQUIRE(e);
  auto pow10 = [](int n) {
    relpos::Rational p(1);
    for (int k = 0; k < n; ++k) p *= 10;
    return p;
  };
  REQUIRE(e->matrix()(0, 0) == pow10(300));
  REQUIRE(e->matrix()(3, 3) == -pow10(240));
}

TEST_CASE("fast reader: a sphere's and a standard paraboloid's size bound, number by number", "[io][fast]") {
  // Whether a value holds a wide number (|e| > 30 once trailing zeros are removed) is known after
  // its numbers are read: in each place of the form, a number at the bound is taken (and read as the
  // general reader reads it), one past it left to the general reader, however it is spelled.
  const std::string at[] = {"1e30", "-1e-30", "0.1e-29", "1000e27", "\"2.5e-29\"", "-1234567890123456789e-30"};
  const std::string past[] = {"1e31", "-1e-31", "0.1e-30", "10e30", "\"2.5e-30\"", "-1234567890123456789e-31"};
  for (std::size_t place = 0; place < 5; ++place)
    for (std::size_t k = 0; k < 6; ++k) {
      for (const bool wide : {false, true}) {
        std::string x = wide ? past[k] : at[k];
        if (place >= 3 && x[0] == '-') x = x.substr(1);  // a radius, a and b: positive
        std::string n[5] = {"0.5", "-0.25", "2", "1.5", "3"};
        n[place] = x;
        const std::string sphere =
            "{\"sphere\":{\"center\":" + vec3(n[0], n[1], n[2]) + ",\"radius\":" + (place == 4 ? n[4] : n[3]) + "}}";
        const std::string cup = "{\"vertex\":" + vec3(n[0], n[1], n[2]) + ",\"a\":" + n[3] + ",\"b\":" + n[4] + "}";
        INFO(sphere << "  " << cup);
        if (wide) {
          REQUIRE_FALSE(fast_ellipsoid(sphere, false));
          REQUIRE_FALSE(fast_paraboloid(cup, false));
        } else {
          check_pair(sphere, cup, false);
        }
      }
    }
  // A zero is never wide, whatever its exponent; with --numbers double no number is.
  check_pair(R"({"sphere":{"center":[0e400,0,-0.0e-9999],"radius":1}})", R"({"vertex":[0,0e999,0],"a":1,"b":2})",
             false);
  check_pair(R"({"sphere":{"center":[1e20,0,0],"radius":1e-20}})", R"({"vertex":[0,0,1e20],"a":1e-20,"b":2})", true);
}

TEST_CASE("fast reader: a general quadric that is an ellipsoid's or an elliptic paraboloid's matrix", "[io][fast]") {
  // The quadric the general reader makes of the same text: the same exact matrix (its orientation
  // included) and type; any other type or form is left to it.
  using relpos::Quadric;
  using relpos::QuadricType;
  const std::string ball = "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]";
  const std::string texts[] = {
      ball,
      "{\"matrix\":[[-2,0,0,0.1],[0,-3,0,0],[0,0,-4,0],[0.1,0,0,50]]}",         // negated
      "[[1e300,0,0,0],[0,2e300,0,0],[0,0,3e300,-1e300],[0,0,-1e300,-4e300]]",   // scaled
      "[[1,0,0,0],[0,2.5,0,0],[0,0,0,-0.5],[0,0,-0.5,0.25]]",                   // a paraboloid
      "[[-1e-300,0,0,0],[0,-1e-300,0,0],[0,0,0,5e-301],[0,0,5e-301,-2e-300]]",  // negated, scaled
  };
  const QuadricType types[] = {QuadricType::Ellipsoid, QuadricType::Ellipsoid, QuadricType::Ellipsoid,
                               QuadricType::EllipticParaboloid, QuadricType::EllipticParaboloid};
  const Ellipsoid probe = *fast_ellipsoid("{\"sphere\":{\"center\":[0.5,0.25,2],\"radius\":1.5}}", false);
  for (std::size_t k = 0; k < 5; ++k) {
    INFO(texts[k]);
    for (const bool doubles : {false, true}) {
      std::optional<Quadric> q;
      std::size_t end = 0;
      const std::string text = texts[k] + ",\"id\":1}";
      if (doubles && k >= 2 && k != 3) {  // beyond 2^100: the general reader's, as for an ellipsoid
        REQUIRE_FALSE(relpos::detail::io::fast_quadric_at(text, doubles, end, q));
        continue;
      }
      REQUIRE(relpos::detail::io::fast_quadric_at(text, doubles, end, q));
      REQUIRE(end == texts[k].size());
      const Quadric g = relpos::detail::io::quadric_from_json(general_json(texts[k], doubles));
      REQUIRE(q->type() == types[k]);
      REQUIRE(g.type() == types[k]);
      REQUIRE(q->matrix() == g.matrix());
      REQUIRE(relpos::decide_position(probe, *q).position == relpos::decide_position_exact(probe, g).position);
    }
  }
  // Left to the general reader: other types, the geometric forms, an ellipsoid's own forms.
  for (const char* text : {"[[1,0,0,0],[0,1,0,0],[0,0,-1,0],[0,0,0,-1]]",  // a hyperboloid of one sheet
                           "[[1,0,0,0],[0,1,0,0],[0,0,0,0],[0,0,0,-1]]",   // an elliptic cylinder
                           R"({"type":"sphere","center":[0,0,0],"radius":1})",
                           R"({"sphere":{"center":[0,0,0],"radius":1}})", R"({"vertex":[0,0,0],"a":1,"b":1})"}) {
    INFO(text);
    std::optional<Quadric> q;
    std::size_t end = 0;
    REQUIRE_FALSE(relpos::detail::io::fast_quadric_at(text, false, end, q));
    REQUIRE_FALSE(q);
  }
}
