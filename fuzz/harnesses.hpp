// The bodies of the libFuzzer harnesses (fuzz/fuzz_*.cpp), header-only so that the regression test
// (tests/test_fuzz_regressions.cpp, built with g++ in the ordinary build) replays every saved input
// through exactly the same checks. Each check_* function either returns normally or throws
// relpos_fuzz::Defect naming the violated invariant; any other exception escaping it, a crash, a
// sanitizer report or a hang is a defect as well.
//
//   check_numbers     parse_rational / to_string / to_decimal / exact_rational / rational_from_json
//   check_batch_line  one line of `relpos batch`, through the io.hpp function the CLI uses
//   check_classify    the classifier on pairs built from the bytes, degenerate ones on purpose
#pragma once

#include <gmp.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <relpos/numbers.hpp>
#include <relpos/quadric.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "../src/io/fast_quadric.hpp"
#include "../src/io/json_tree.hpp"
#include "../src/io/json_values.hpp"
#include "../src/io/quadric_json.hpp"
#include "../tests/support/construct.hpp"
#include "../tests/support/oracles.hpp"
#include "../tests/support/secular.hpp"
#include "algebra/number_limits.hpp"
#include "io/batch.hpp"

namespace relpos_fuzz {

/// A violated invariant.
class Defect : public std::logic_error {
 public:
  explicit Defect(const std::string& what) : std::logic_error(what) {}
};

inline void expect(bool ok, const std::string& what) {
  if (!ok) throw Defect(what);
}

using relpos::Rational;
using relpos::detail::io::Json;

// ------------------------------------------------------------------------------------------------
// Numbers

/// The exact decimal expansion of a dyadic rational (every finite double has one): m / 2^k =
/// m 5^k / 10^k.
inline std::string exact_decimal(const Rational& q) {
  relpos::Integer den = q.denominator();
  unsigned long k = 0;
  while (den % 2 == 0) {
    den = den / 2;
    ++k;
  }
  if (den != 1) return relpos::to_string(q);  // not dyadic: the fraction
  relpos::Integer five;
  mpz_ui_pow_ui(five.mpz(), 5, k);  // fresh object (Gmpz is reference-counted)
  relpos::Integer m = q.numerator() * five;
  const bool neg = m < 0;
  std::string digits = relpos::to_string(neg ? -m : m);
  if (k > 0) {
    if (digits.size() <= k) digits = std::string(k - digits.size() + 1, '0') + digits;
    digits.insert(digits.size() - k, ".");
  }
  return (neg ? "-" : "") + digits;
}

inline void check_numbers(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // 1. parse_rational: a value or InputError; the value survives printing and decimal rounding.
  bool parsed = false;
  Rational q;
  try {
    q = relpos::parse_rational(text);
    parsed = true;
  } catch (const relpos::InputError& e) {
    expect(std::strlen(e.what()) > 0, "parse_rational: empty error message");
  }
  if (parsed) {
    // The limits are on text, so another notation of an accepted value can exceed them:
    // 2.2e-10883 is 18 characters, its fraction over 10000 (fuzz/regressions/numbers/README.md).
    const std::string exact = relpos::to_string(q);
    if (exact.size() <= relpos::detail::kMaxNumberChars)
      expect(relpos::parse_rational(exact) == q, "to_string does not round-trip: " + text);
    for (int digits : {1, 12, 40}) {
      const std::string d = relpos::to_decimal(q, digits);
      Rational back;
      try {
        back = relpos::parse_rational(d);
      } catch (const relpos::InputError& e) {
        // The exponent limit of numbers.hpp applies to the printed text too: 10000 digits written in
        // full are about 1e9999, and "7e4001" is beyond it (fuzz/regressions/numbers/README.md).
        const std::size_t epos = d.find('e');
        expect(epos != std::string::npos && std::stol(d.substr(epos + 1)) > relpos::detail::kMaxDecimalExponent &&
                   std::string(e.what()).find("exponent") != std::string::npos,
               "to_decimal(" + std::to_string(digits) + ") = " + d + " does not parse back: " + e.what());
        continue;
      }
      // Rounding to `digits` significant digits: |back - q| <= 1/2 10^(1 - digits) |q|.
      Rational err = back - q;
      if (err < 0) err = -err;
      Rational bound = q < 0 ? -q : q;
      for (int i = 1; i < digits; ++i) err *= 10;
      expect(2 * err <= bound, "to_decimal(" + std::to_string(digits) + ") = " + d + " is off for " + text);
    }
  }
  // 2. The JSON route: a number or string gives the same exact value or InputError.
  try {
    const Json doc = relpos::detail::io::parse_json_exact(text);
    try {
      const Rational j = relpos::detail::io::rational_from_json(doc, "x");
      // A bare JSON number (not a string literal) is the same text for parse_rational.
      if (parsed && text.find('"') == std::string::npos)
        expect(j == q, "JSON number and parse_rational disagree on " + text);
    } catch (const relpos::InputError&) {
    }
  } catch (const relpos::InputError&) {
  }
  // 3. The first 8 bytes as a double: exact_rational is exact, and so is its decimal expansion.
  if (size >= 8) {
    double x;
    std::memcpy(&x, data, sizeof x);
    try {
      const Rational r = relpos::exact_rational(x);
      expect(CGAL::to_double(r) == x, "exact_rational is not exact");
      expect(relpos::parse_rational(exact_decimal(r)) == r, "exact decimal of a double does not parse back");
    } catch (const relpos::InputError&) {
      expect(!(x == x) || x - x != 0, "exact_rational rejected a finite double");
    }
  }
}

// ------------------------------------------------------------------------------------------------
// One batch line

/// The fast reader of batch lines against the general reader on one quadric text: whatever the fast
/// reader takes, the general reader takes too, with the same exact matrix, inside the stored
/// enclosures (or equal to the stored doubles).
template <class Q, class Fast, class FastAt, class General>
void check_fast_quadric(std::string_view text, bool doubles, Fast fast, FastAt fast_at, General general,
                        const char* role) {
  const std::optional<Q> q = fast(text, doubles);
  // The same value at the start of a longer text (a batch line's scan): taken alike, with its end
  // (a text with more after its first value is taken there only up to that value).
  const std::size_t first = text.find_first_not_of(" \t\n\r"), last = text.find_last_not_of(" \t\n\r");
  if (first != std::string_view::npos) {
    const std::string value(text.substr(first, last + 1 - first));
    std::size_t end = 0;
    std::optional<Q> at;
    const bool taken = fast_at(value + ",", doubles, end, at);
    expect(at.has_value() == taken && (taken || !q) && (!taken || end != value.size() || q),
           std::string("fast reader: a value inside a line taken otherwise for the ") + role);
    expect(!q || (taken && end == value.size() && at->matrix() == q->matrix()),
           std::string("fast reader: another end or matrix inside a line for the ") + role);
  }
  if (!q) return;
  relpos::detail::io::JsonReadOptions read;
  read.doubles = doubles;
  read.max_elements = 16;
  read.start_depth = 1;
  std::optional<Q> g;
  try {
    g = general(relpos::detail::io::parse_json(text, read), role);
  } catch (const relpos::InputError& e) {
    expect(false, std::string("fast reader took a ") + role + " the general reader refuses: " + e.what());
  }
  expect(q->matrix() == g->matrix(), std::string("fast reader: another exact matrix for the ") + role);
  const auto& enc = storage_of(*q).enclosure();
  expect(q->doubles().has_value() || enc != nullptr, "fast reader: neither doubles nor enclosures");
  for (std::size_t k = 0; k < 16 && enc; ++k)
    expect(Rational(enc->lo[k]) <= q->matrix().a[k] && q->matrix().a[k] <= Rational(enc->hi[k]),
           std::string("fast reader: an entry outside its enclosure for the ") + role);
}

inline void check_fast_reader(std::string_view text) {
  for (const bool doubles : {false, true}) {
    check_fast_quadric<relpos::Ellipsoid>(text, doubles, relpos::detail::io::fast_ellipsoid,
                                          relpos::detail::io::fast_ellipsoid_at,
                                          relpos::detail::io::ellipsoid_from_tree, "ellipsoid");
    check_fast_quadric<relpos::Paraboloid>(text, doubles, relpos::detail::io::fast_paraboloid,
                                           relpos::detail::io::fast_paraboloid_at,
                                           relpos::detail::io::paraboloid_from_tree, "paraboloid");
  }
}

inline void check_batch_line(const std::uint8_t* data, std::size_t size) {
  // The bytes may hold several lines, split at '\n' as the CLI splits its input; each goes through
  // the library's relpos::detail::io::answer_batch_line, the one function `relpos batch` calls.
  const std::string all(reinterpret_cast<const char*>(data), size);
  std::size_t start = 0;
  long number = 0;
  while (start < all.size()) {
    std::size_t end = all.find('\n', start);
    if (end == std::string::npos) end = all.size();
    const std::string text = relpos::detail::io::answer_batch_line(std::string_view(all).substr(start, end - start),
                                                                   ++number, relpos::detail::io::BatchOptions{});
    expect(text.find('\n') == std::string::npos, "answer spans several lines");
    // The fast reader on the raw line and on the quadric values of a line that is a JSON object
    // (their bytes as written: the members' spans are located in the raw text).
    const std::string_view raw = std::string_view(all).substr(start, end - start);
    check_fast_reader(raw);
    for (const char* key : {"\"ellipsoid\":", "\"paraboloid\":"}) {
      const std::size_t at = raw.find(key);
      if (at == std::string_view::npos) continue;
      const std::string_view rest = raw.substr(at + std::strlen(key));
      for (std::size_t cut = 1; cut <= rest.size(); ++cut)  // every prefix that ends a value
        if (rest[cut - 1] == '}' || rest[cut - 1] == ']') check_fast_reader(rest.substr(0, cut));
    }
    Json answer;
    try {
      answer = relpos::detail::io::parse_json_exact(text);  // ids are echoed as written: 1e400 too
    } catch (const relpos::InputError&) {
      expect(false, "answer is not JSON: " + text.substr(0, 200));
    }
    expect(answer.is_object() && answer.contains("id"), "answer without id");
    expect(answer.contains("error") != answer.contains("position"), "answer is neither an error nor a position");
    if (answer.contains("error")) {
      const std::string message = answer["error"].get<std::string>();
      expect(!message.empty(), "error without a message");
      expect(message.rfind("internal error", 0) != 0, "internal error: " + message);
    }
    start = end + 1;
  }
}

// ------------------------------------------------------------------------------------------------
// The classifier

/// Bytes as a stream of small choices (zeros after the end).
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  unsigned u8() { return pos_ < size_ ? data_[pos_++] : 0u; }
  unsigned below(unsigned n) { return u8() % n; }
  bool flag() { return u8() & 1u; }
  /// Small rationals, exactly degenerate-friendly: integers -8..8 over 1, 2, 4, 3, 8, 5.
  Rational small() {
    static const long den[] = {1, 2, 4, 3, 8, 5};
    const long n = static_cast<long>(below(17)) - 8;
    return rt::Q(n, den[below(6)]);
  }
  Rational positive() {
    static const long den[] = {1, 2, 4, 3, 8, 5};
    return rt::Q(static_cast<long>(below(12)) + 1, den[below(6)]);
  }
  /// A power of two 2^-k, k in 1..64 (near-degenerate perturbations).
  Rational tiny() {
    Rational t(1);
    for (unsigned k = below(64) + 1; k > 0; --k) t /= 2;
    return t;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// A pair of matrices with what its construction says about the answer.
struct Built {
  rt::Matrix4 e, p;
  std::string what;
  bool truth_known = false;
  relpos::Position truth = relpos::Position::C;  ///< meaningful when truth_known
};

/// The position on the axis of the cup for a sphere of any size (test_properties's oracle): below
/// the vertex by z +- r; above it the squared distance to the surface is z^2 for z <= a^2/2, else
/// a^2 z - a^4/4 (a the smaller parameter).
inline relpos::Position axis_truth(const Rational& amin, const Rational& z, const Rational& r) {
  using relpos::Position;
  if (z < r) return rt::axis_position(z, r);
  const Rational a2 = amin * amin;
  const Rational d2 = z <= a2 / 2 ? z * z : a2 * z - a2 * a2 / 4;
  return d2 > r * r ? Position::I : (d2 == r * r ? Position::TI : Position::C);
}

inline bool build_pair(Bytes& in, Built& out) {
  using relpos::Position;
  const unsigned mode = in.below(5);
  if (mode == 0) {  // sphere and standard paraboloid, degenerate on purpose
    rt::Config k;
    k.a = in.positive();
    k.b = in.flag() ? k.a : in.positive();
    k.c = {in.small(), in.small(), in.small()};
    k.r = in.positive();
    switch (in.below(8)) {
      case 0:
        k.c[0] = k.c[1] = 0;  // on the axis
        break;
      case 1:
        k.c[0] = k.c[1] = 0;
        k.c[2] = in.flag() ? k.r : -k.r;  // tangent at the vertex
        break;
      case 2:
        k.c[2] = rt::paraboloid_value(k.a, k.b, {k.c[0], k.c[1], Rational(0)});  // centre on the surface
        break;
      case 3:
        k.r = k.amin() * k.amin() / 2;  // rho = 1
        break;
      case 4: {  // -a^2 or -b^2 double root of f (math.md §3), when a != b
        if (k.a == k.b) break;
        const Rational a2 = k.a * k.a, b2 = k.b * k.b;
        if (in.flag())
          k.c = {Rational(0), k.c[1], k.c[1] * k.c[1] / (b2 - a2) + k.r * k.r / a2 + a2 / 4};
        else
          k.c = {k.c[0], Rational(0), k.c[0] * k.c[0] / (a2 - b2) + k.r * k.r / b2 + b2 / 4};
        break;
      }
      default:
        break;
    }
    out.e = k.e();
    out.p = k.p();
    out.what = rt::describe(k);
    if (k.c[0] == 0 && k.c[1] == 0) {
      out.truth_known = true;
      out.truth = axis_truth(k.amin(), k.c[2], k.r);
    }
    return true;
  }
  if (mode == 1) {  // exact tangency at a point with a rational normal, and its neighbours
    const Rational a = in.positive(), b = in.flag() ? a : in.positive();
    const Rational s = in.small(), t = in.small();
    if (s * s + t * t == 1) return false;
    const rt::TangentPoint tp = rt::tangent_point(a, b, s, t);
    const bool big = in.below(4) == 0;  // not small: only TE and E are claimed
    // Small: r <= min(a, b)^2 / 4 (the family's hypothesis). Big: 2r > min(a, b)^2.
    const Rational amin2 = rt::rmin(a, b) * rt::rmin(a, b);
    const Rational r = big ? amin2 * (in.positive() + 1) : amin2 * rt::Q(static_cast<long>(in.below(4)) + 1, 16);
    const long j = static_cast<long>(in.below(7)) + 1;
    std::vector<rt::Config> family = rt::tangency_family(tp, r, j);
    const unsigned which = in.below(static_cast<unsigned>(family.size()));
    rt::Config k = family[which];
    out.truth_known = !big || k.expected == Position::TE || k.expected == Position::E;
    if (which < 2 && in.flag()) {  // near-tangent: radius times 1 -+ 2^-k
      const bool grow = in.flag();
      k.r = grow ? k.r * (1 + in.tiny()) : k.r * (1 - in.tiny());
      k.name += grow ? ", radius grown by 2^-k" : ", radius shrunk by 2^-k";
      // Shrunk: inside the open tangent ball (I / E). Grown: the ball contains the contact point in
      // its interior (C), and stays small when r was (r' <= 2r <= a^2 / 2).
      k.expected = grow ? Position::C : (which == 0 ? Position::I : Position::E);
      out.truth_known = !big || k.expected == Position::E;
    }
    out.truth = k.expected;
    out.e = k.e();
    out.p = k.p();
    out.what = rt::describe(k);
    return true;
  }
  if (mode == 2) {  // general ellipsoid (axes + quaternion) and rotated paraboloid
    const rt::Vector3 c{in.small(), in.small(), in.small()};
    const rt::Vector3 axes{in.positive(), in.positive(), in.positive()};
    const rt::Quaternion qe{in.small(), in.small(), in.small(), in.small()};
    const rt::Quaternion qp{in.small(), in.small(), in.small(), in.small()};
    try {
      out.e = relpos::Ellipsoid::from_axes(c, axes, qe).matrix();
      out.p =
          relpos::Paraboloid::standard({in.small(), in.small(), in.small()}, in.positive(), in.positive(), qp).matrix();
    } catch (const relpos::InputError&) {
      return false;  // zero quaternion
    }
    out.what = "axes + quaternion";
    return true;
  }
  if (mode == 3) {  // affine maps with small entries (often singular: then InputError)
    rt::Matrix3 l, t;
    for (auto& x : l.a) x = in.small();
    for (auto& x : t.a) x = in.small();
    try {
      out.e = relpos::Ellipsoid::from_map({in.small(), in.small(), in.small()}, l).matrix();
      out.p = relpos::Paraboloid::from_map(t, {in.small(), in.small(), in.small()}).matrix();
    } catch (const relpos::InputError&) {
      return false;
    }
    out.what = "affine maps";
    return true;
  }
  // Raw coefficients: most are not an ellipsoid and a paraboloid (InputError).
  relpos::Coefficients10 ce, cp;
  for (auto& x : ce) x = in.small();
  for (auto& x : cp) x = in.small();
  try {
    out.e = relpos::Ellipsoid::from_coefficients(ce).matrix();
    out.p = relpos::Paraboloid::from_coefficients(cp).matrix();
  } catch (const relpos::InputError&) {
    return false;
  }
  out.what = "raw coefficients";
  return true;
}

/// A signed permutation of the coordinates with a translation: an affine congruence.
inline rt::Matrix4 signed_permutation(Bytes& in) {
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int* perm = perms[in.below(6)];
  rt::Matrix3 l;
  for (int i = 0; i < 3; ++i) l(i, perm[i]) = in.flag() ? Rational(-1) : Rational(1);
  return rt::affine_matrix(l, {in.small(), in.small(), in.small()});
}

inline std::string name(relpos::Position p) { return relpos::to_string(p); }

/// Everything that must agree between two answers for the same pair (up to a congruence).
inline void expect_same(const relpos::Verdict& a, const relpos::Verdict& b, const std::string& what) {
  expect(a.position == b.position, what + ": position " + name(a.position) + " vs " + name(b.position));
  expect(a.small == b.small && a.rho_vs_one == b.rho_vs_one, what + ": smallness differs");
  expect(a.negative_roots == b.negative_roots && a.positive_roots == b.positive_roots &&
             a.nonreal_roots == b.nonreal_roots,
         what + ": root counts differ");
  expect(a.sign_disc_f == b.sign_disc_f && a.sign_disc_ftilde == b.sign_disc_ftilde, what + ": Disc signs differ");
}

inline void check_classify(const std::uint8_t* data, std::size_t size) {
  using relpos::Ellipsoid;
  using relpos::Paraboloid;
  using relpos::Position;
  Bytes in(data, size);
  Built b;
  if (!build_pair(in, b)) return;
  // The constructions above are valid by design; a raw matrix may still be rejected.
  std::optional<Ellipsoid> eo;
  std::optional<Paraboloid> po;
  try {
    eo = Ellipsoid::from_matrix(b.e);
    po = Paraboloid::from_matrix(b.p);
  } catch (const relpos::InputError& err) {
    expect(!b.truth_known, b.what + ": a constructed pair was rejected: " + err.what());
    return;
  }
  const Ellipsoid& e = *eo;
  const Paraboloid& p = *po;
  const std::string what = b.what;

  const relpos::Classification c = relpos::classify(e, p);
  const relpos::Classification x = relpos::classify_exact(e, p, relpos::Evidence::Minimal);
  const relpos::Verdict v = relpos::decide_position(e, p);
  expect(c.verdict.position == x.verdict.position,
         what + ": classify " + name(c.verdict.position) + " vs classify_exact " + name(x.verdict.position));
  expect(v.position == c.verdict.position, what + ": decide_position differs from classify");
  expect(c.verdict.small == x.verdict.small && c.verdict.rho_vs_one == x.verdict.rho_vs_one,
         what + ": smallness differs from classify_exact");
  expect(c.verdict.real_roots == x.verdict.real_roots && c.verdict.negative_roots == x.verdict.negative_roots &&
             c.verdict.positive_roots == x.verdict.positive_roots && c.verdict.nonreal_roots == x.verdict.nonreal_roots,
         what + ": root counts differ from classify_exact");
  expect(c.verdict.sign_disc_f == x.verdict.sign_disc_f && c.verdict.sign_disc_ftilde == x.verdict.sign_disc_ftilde,
         what + ": Disc signs differ from classify_exact");
  expect(relpos::classify(e, p, relpos::Evidence::Minimal).verdict.position == c.verdict.position,
         what + ": Minimal differs");
  // A zero is certified only by an exact stage: GMP roots or the machine-integer multiple-root witness.
  if (c.verdict.sign_disc_f == 0)
    expect(c.verdict.stage == relpos::Stage::ExactRoots || c.verdict.stage == relpos::Stage::MultipleRootWitness,
           what + ": Disc(f) = 0 decided by a filter");
  if (b.truth_known) {
    expect(c.verdict.position == b.truth,
           what + ": position " + name(c.verdict.position) + ", construction says " + name(b.truth));
  } else if (!c.verdict.small) {
    // No construction truth: the independent secular oracle decides (any size).
    Position want = c.verdict.position;
    try {
      want = relpos::testing::secular_position(e, p);
    } catch (const std::logic_error& err) {
      expect(false, what + ": the secular oracle found a structural failure: " + err.what());
    }
    expect(c.verdict.position == want,
           what + ": position " + name(c.verdict.position) + ", secular oracle says " + name(want));
  }
  // The independent tangency test on every rational multiple root (small pairs; math.md §3).
  if (c.verdict.small)
    for (const auto& r : c.roots)
      if (r.multiplicity_f >= 2 && r.exact)
        expect(relpos::detail::oracle::kernel_has_common_point(e, p, *r.exact) == r.tangency(),
               what + ": kernel test disagrees at the root " + relpos::to_string(*r.exact));

  // Invariance: a signed permutation + translation, a random congruence, positive rescaling and sign
  // flips of either matrix change nothing (math.md §1).
  const rt::Matrix4 h = signed_permutation(in);
  const Ellipsoid e1 = Ellipsoid::from_matrix(rt::congruence(b.e, h));
  const Paraboloid p1 = Paraboloid::from_matrix(rt::congruence(b.p, h));
  expect_same(relpos::decide_position(e1, p1), v, what + " (signed permutation)");
  const Rational ke = in.positive(), kp = in.positive();
  const Ellipsoid e2 = Ellipsoid::from_matrix(rt::scaled(b.e, in.flag() ? -ke : ke));
  const Paraboloid p2 = Paraboloid::from_matrix(rt::scaled(b.p, in.flag() ? -kp : kp));
  expect_same(relpos::decide_position(e2, p2), v, what + " (rescaled / sign flipped)");
  rt::Rng g(in.u8() * 256u + in.u8());
  const rt::Transformed t = rt::transform(b.e, b.p, g);
  expect_same(relpos::decide_position(Ellipsoid::from_matrix(t.e), Paraboloid::from_matrix(t.p)), v,
              what + " (random congruence)");
}

}  // namespace relpos_fuzz
