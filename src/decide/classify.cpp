#include "relpos/classify.hpp"

#include <CGAL/Interval_nt.h>
#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <cfenv>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "algebra/exact_pencil.hpp"
#include "algebra/forms.hpp"
#include "algebra/rounding.hpp"
#include "algebra/shape_filter.hpp"
#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "anysize/exact.hpp"
#include "anysize/gap.hpp"
#include "certificate/build.hpp"
#include "decide/static_route.hpp"
#include "decide/unchecked.hpp"
#include "filters/fixed_pencil.hpp"
#include "filters/multiple_roots.hpp"
#include "filters/pooled_integer.hpp"
#include "filters/running_bound.hpp"
#include "filters/semi_static_filter.hpp"
#include "filters/static_filter.hpp"

namespace relpos {

std::string describe(Rule r) {
  switch (r) {
    case Rule::None:
      return "";
    case Rule::NonRealPairCrossing:
      return "f has a pair of non-real roots and f~ no multiple root (Disc(f~) < 0): crossing contact";
    case Rule::NegativeMultipleRoot:
      return "f~ has a negative multiple root (Disc(f~) = 0) and all roots of f are real and negative: tangent "
             "from inside";
    case Rule::PositiveMultipleRoot:
      return "f~ has a positive multiple root (lambda3 = lambda4 > 0): tangent from outside";
    case Rule::AllRootsNegative:
      return "f~ is square-free (Disc(f~) > 0) and all roots of f are real and negative: interior";
    case Rule::TwoPositiveRoots:
      return "f has two distinct positive roots (0 < lambda3 < lambda4): separated";
    case Rule::RootsAboveLambdaS:
      return "f is square-free with four real negative roots, two of them in (lambda_s, 0): interior (any size, "
             "math.md section 8)";
    case Rule::NoRootAboveLambdaS:
      return "f is square-free with four real roots, none above lambda_s (the root of s nearest 0) and none "
             "positive: crossing (any size, math.md section 8)";
    case Rule::OddPositiveRoot:
      return "f has a positive root of odd multiplicity: separated (math.md section 8, rule 1)";
    case Rule::EvenPositiveRoot:
      return "f has a positive root, of even multiplicity: tangent from outside (math.md section 8, rule 2)";
    case Rule::OddGapRoot:
      return "f has a root of odd multiplicity in (lambda_s, 0): interior (math.md section 8, rule 3)";
    case Rule::EvenGapRoot:
      return "f~ has a multiple root in (lambda_s, 0): tangent from inside (math.md section 8, rule 4)";
    case Rule::HardCase:
      return "f~ vanishes at lambda_s, the root of s nearest 0: tangent from inside along two points or a conic "
             "(the hard case, math.md section 8, rule 4)";
    case Rule::NoRootInGap:
      return "no positive root and no root of f~ in [lambda_s, 0): crossing (math.md section 8, rule 5)";
  }
  return "";
}

std::string to_string(Stage s) {
  switch (s) {
    case Stage::InsideCertificate:
      return "inside-certificate";
    case Stage::OutsideCertificate:
      return "outside-certificate";
    case Stage::DiscriminantFilter:
      return "discriminant-filter";
    case Stage::StaticDouble:
      return "static-double";
    case Stage::SemiStaticDouble:
      return "semi-static-double";
    case Stage::MultipleRootWitness:
      return "multiple-root-witness";
    case Stage::Interval:
      return "interval";
    case Stage::ExactSigns:
      return "exact-signs";
    case Stage::ExactRoots:
      return "exact-roots";
  }
  return "?";
}

namespace {

/// The classification (math.md §3, §6 and §8), written once for every stage. Reads the root
/// facts of v and its rho comparison; writes position and rule. Leaves rule None (the
/// position undecided) when the facts do not suffice: a pair that is not small with four real
/// negative roots needs roots_above_lambda_s (math.md §8), and a multiple root outside the proven
/// small-pair table needs the exact facts of math.md §8 (decide_any_size).
void decide(Verdict& v) {
  v.small = v.rho_vs_one <= 0;
  const int tangencies = v.tangent_negative + v.tangent_positive;
  auto set = [&](Position pos, Rule rule) {
    v.position = pos;
    v.rule = rule;
  };
  v.rule = Rule::None;  // undecided until a rule is set (the position is then meaningless)
  const bool square_free = tangencies == 0 && v.nonreal_multiple == 0 && v.sign_disc_f != 0;
  if (square_free) {
    // f has >= 2 real roots at or below lambda_s (math.md §8); the other two decide, for any size.
    if (v.nonreal_roots == 2 && v.positive_roots == 0) return set(Position::C, Rule::NonRealPairCrossing);
    if (v.nonreal_roots == 0 && v.positive_roots == 2) return set(Position::E, Rule::TwoPositiveRoots);
    if (v.nonreal_roots == 0 && v.positive_roots == 0) {
      if (v.small) return set(Position::I, Rule::AllRootsNegative);  // math.md §3, proven for small pairs
      if (v.roots_above_lambda_s == 1) return set(Position::I, Rule::RootsAboveLambdaS);
      if (v.roots_above_lambda_s == 0) return set(Position::C, Rule::NoRootAboveLambdaS);
    }
    return;  // undecided: the gap test, or a pattern the theorem excludes (decide_any_size reports it)
  }
  if (v.nonreal_multiple == 0 && v.nonreal_roots == 0) {  // any size (math.md §6, Wang-Wang-Kim)
    if (tangencies == 1 && v.tangent_positive == 1) return set(Position::TE, Rule::PositiveMultipleRoot);
    if (tangencies == 0 && v.positive_roots == 2) return set(Position::E, Rule::TwoPositiveRoots);
  }
  if (!v.small || v.nonreal_multiple > 0) return;  // math.md §8, exactly (decide_any_size)
  // Small pairs with a multiple root: the rest of the table of math.md §3.
  if (tangencies == 0 && v.nonreal_roots == 2 && v.positive_roots == 0)
    return set(Position::C, Rule::NonRealPairCrossing);
  if (tangencies == 1 && v.tangent_negative == 1 && v.nonreal_roots == 0 && v.positive_roots == 0)
    return set(Position::TI, Rule::NegativeMultipleRoot);
  if (tangencies == 0 && v.nonreal_roots == 0 && v.positive_roots == 0) return set(Position::I, Rule::AllRootsNegative);
}

bool decided(const Verdict& v) { return v.rule != Rule::None; }

/// Section 8 from exact facts of f and s (integer coefficients; any common positive scaling of the
/// roots): the five rules in order. Every valid pair gets one of the five positions.
void decide_any_size(const Quartic<Integer>& f, const Quadratic<Integer>& s, Verdict& v) {
  const anysize::AnySizeFacts x = anysize::any_size_facts(anysize::to_poly(f.data(), 5), anysize::to_poly(s.data(), 3));
  auto set = [&](Position pos, Rule rule) {
    v.position = pos;
    v.rule = rule;
  };
  v.roots_above_lambda_s = static_cast<signed char>(x.odd_gap + x.even_gap > 0);
  switch (x.rule) {
    case 1:
      return set(Position::E, Rule::OddPositiveRoot);
    case 2:
      return set(Position::TE, Rule::EvenPositiveRoot);
    case 3:
      return set(Position::I, Rule::OddGapRoot);
    case 4:
      return set(Position::TI, x.hard ? Rule::HardCase : Rule::EvenGapRoot);
    default:
      return set(Position::C, Rule::NoRootInGap);
  }
}

using detail::rounding_to_nearest;
using forms::Interval;
using forms::MatrixOf;
using forms::to_compact_integers;
using forms::to_intervals;

/// The signs of every decision quantity, evaluated in NT (intervals or exact integers).
template <class NT>
DecisionSigns signs_in(const Quartic<NT>& f, const Quadratic<NT>& s) {
  SturmHabicht<NT> sh(f);
  SmallnessQuantities<NT> q(f, s);
  return DecisionSigns{signs_of(f, sh), sign_of(q.vertex), sign_of(q.graeffe)};
}

/// Decision from certified signs when Disc(f) != 0 (then f and f~ are square-free). False when a
/// needed sign is uncertain, Disc(f) = 0 or the Sturm-Habicht sequence is defective.
bool decide_from_signs_slow(const DecisionSigns& d, Verdict& v) {
  auto disc = detail::certain(d.quartic.g0);
  if (!disc || *disc == 0) return false;
  auto counts = count_roots(d.quartic);
  if (!counts) return false;
  auto rho = compare_rho_with_one(d.vertex, d.graeffe);
  if (!rho) return false;
  v.real_roots = static_cast<signed char>(counts->real);
  v.negative_roots = static_cast<signed char>(counts->negative);
  v.positive_roots = static_cast<signed char>(counts->positive);
  v.nonreal_roots = static_cast<signed char>(4 - counts->real);
  v.sign_disc_f = v.sign_disc_ftilde = static_cast<signed char>(*disc);  // Disc(f) = Disc(f~) * positive
  v.rho_vs_one = static_cast<signed char>(*rho);
  decide(v);
  return true;
}

/// The eight signs root counting reads (count_roots): every one certain and non-zero is the common
/// case, and then the whole decision is a function of 8 sign bits and rho's 3 outcomes. This table
/// holds that function, *generated* at start-up by running decide_from_signs_slow() -- the one
/// written decision -- on every combination, so nothing is decided twice; the hot path becomes a
/// few compares and one lookup instead of a chain of data-dependent (hence mispredicted) branches.
struct SignTable {
  Verdict v[256][3];  // [sign bits][rho_vs_one + 1]
  SignTable() {
    auto sg = [](int bit) { return USign(bit ? CGAL::POSITIVE : CGAL::NEGATIVE); };
    for (int bits = 0; bits < 256; ++bits)
      for (int rho = -1; rho <= 1; ++rho) {
        DecisionSigns d;
        QuarticSigns& q = d.quartic;
        q.f[4] = sg(bits & 1), q.g2[0] = sg(bits & 2), q.g1[0] = sg(bits & 4), q.g0 = sg(bits & 8);
        q.f[0] = sg(bits & 16), q.f[1] = sg(bits & 32), q.g2[2] = sg(bits & 64), q.g1[1] = sg(bits & 128);
        // rho < 1: vertex >= 0 and graeffe > 0; rho = 1: graeffe = 0; rho > 1: vertex < 0.
        d.vertex = USign(rho > 0 ? CGAL::NEGATIVE : CGAL::POSITIVE);
        d.graeffe = USign(rho < 0 ? CGAL::POSITIVE : CGAL::ZERO);
        Verdict x;
        decide_from_signs_slow(d, x);  // always decides: every needed sign is certain and non-zero
        v[bits][rho + 1] = x;
      }
  }
};

/// 1 for a certain positive sign, 0 for a certain negative one, -1 otherwise (zero or uncertain).
inline int sign_bit(const USign& s) {
  const int lo = s.inf(), hi = s.sup();
  return (lo == hi && lo != 0) ? (lo > 0) : -1;
}

bool decide_from_signs(const DecisionSigns& d, Verdict& v) {
  static const SignTable table;
  const QuarticSigns& q = d.quartic;
  const int b[8] = {sign_bit(q.f[4]), sign_bit(q.g2[0]), sign_bit(q.g1[0]), sign_bit(q.g0),
                    sign_bit(q.f[0]), sign_bit(q.f[1]),  sign_bit(q.g2[2]), sign_bit(q.g1[1])};
  const auto rho = compare_rho_with_one(d.vertex, d.graeffe);
  if ((b[0] | b[1] | b[2] | b[3] | b[4] | b[5] | b[6] | b[7]) < 0 || !rho)
    return decide_from_signs_slow(d, v);  // a zero or uncertain sign: the general path decides or fails
  int bits = 0;
  for (int i = 0; i < 8; ++i) bits |= b[i] << i;
  const Stage stage = v.stage;
  v = table.v[bits][*rho + 1];
  v.stage = stage;
  return true;
}

/// Keep every sign one filter certified: a sign certain in `more` replaces an uncertain one in `d`
/// (two certified signs of the same quantity never disagree).
void merge_certain(DecisionSigns& d, const DecisionSigns& more) {
  auto take = [](USign& x, const USign& y) {
    if (!CGAL::is_certain(x)) x = y;
  };
  for (int i = 0; i < 5; ++i) take(d.quartic.f[i], more.quartic.f[i]);
  for (int i = 0; i < 3; ++i) take(d.quartic.g2[i], more.quartic.g2[i]);
  for (int i = 0; i < 2; ++i) take(d.quartic.g1[i], more.quartic.g1[i]);
  take(d.quartic.g0, more.quartic.g0);
  take(d.vertex, more.vertex);
  take(d.graeffe, more.graeffe);
  d.disc_hopeless = d.disc_hopeless || more.disc_hopeless;
}

/// Decision from exact root facts (Disc(f) = 0 or a defective sequence) and the rho comparison.
void decide_from_facts(const RootFacts& x, int rho_vs_one, Verdict& v) {
  v.real_roots = static_cast<signed char>(x.real);
  v.negative_roots = static_cast<signed char>(x.negative);
  v.positive_roots = static_cast<signed char>(x.positive);
  v.nonreal_roots = static_cast<signed char>(x.nonreal);
  v.nonreal_multiple = static_cast<signed char>(x.nonreal_multiple);
  v.tangent_negative = static_cast<signed char>(x.tangent_negative);
  v.tangent_positive = static_cast<signed char>(x.tangent_positive);
  v.sign_disc_f = static_cast<signed char>(x.sign_disc_f);
  v.sign_disc_ftilde = static_cast<signed char>(x.sign_disc_ftilde);
  v.rho_vs_one = static_cast<signed char>(rho_vs_one);
  decide(v);
}

/// The 3 cases x 3 outcomes of rho of the fast route, generated once from the one written decision
/// (decide_from_facts).
struct CaseTable {
  Verdict v[4][3];
  CaseTable() {
    for (int c = 1; c < 4; ++c)
      for (int rho = -1; rho <= 1; ++rho)
        decide_from_facts(root_facts_of(static_cast<DiscriminantCase>(c)), rho, v[c][rho + 1]);
  }
};

/// The fast route (math.md §8): with Disc(f) != 0 the signs of f's coefficients and of Disc(f) give
/// every root count (discriminant_case), so the Sturm-Habicht g2 and g1 are not needed; rho is
/// always compared (the answer reports smallness). False when the case or rho is uncertain.
/// Always inlined: on every pair's path, where a call and its frame cost as much as the lookup.
[[gnu::always_inline]] inline bool decide_from_discriminant(DiscriminantCase c, int rho,
                                                            Verdict& v) {  // rho: 2 when uncertain
  static const CaseTable table;
  if (c == DiscriminantCase::Undecided || rho == 2) return false;
  const Stage stage = v.stage;
  v = table.v[static_cast<int>(c)][rho + 1];
  v.stage = stage;
  return true;
}

/// The same from a filter's signs.
bool decide_from_discriminant(const DecisionSigns& d, Verdict& v) {
  return decide_from_discriminant(discriminant_case(d.quartic), compare_rho_with_one(d.vertex, d.graeffe).value_or(2),
                                  v);
}
bool decide_from_discriminant(const DiscriminantSignBits& d, Verdict& v) {
  return decide_from_discriminant(d.discriminant_case(), d.rho_vs_one(), v);
}

/// Stage 1b: the static filter left Disc(f) uncertain on exact-double input. If f has rational
/// multiple roots, exhibit them on machine integers (multiple_roots.hpp): that certifies Disc(f) = 0
/// and gives every root fact without GMP. rho comes from the static signs, or exactly from the same
/// machine integers. False (nothing certified) when there is no such witness or a number overflows.
bool decide_from_witness(const DoubleMatrix4& p, const DoubleMatrix4& e, const DecisionSigns& d, Verdict& v) {
  const auto mp = machine_pencil(p, e);
  if (!mp) return false;
  const auto facts = rational_multiple_root_facts(mp->f, mp->s);
  if (!facts) return false;
  auto rho = compare_rho_with_one(d.vertex, d.graeffe);
  if (!rho) rho = compare_rho_with_one(mp->f, mp->s);  // CheckedInt: uncertain only on overflow
  if (!rho) return false;
  decide_from_facts(*facts, *rho, v);
  return true;
}

/// The entries of a quadric as intervals for stage 2, without building its rationals when it has
/// doubles or stored enclosures (scaled by a power of two; rounding towards +inf).
template <class Q>
MatrixOf<Interval> interval_entries(const Q& q) {
  if (const std::optional<DoubleMatrix4> d = q.doubles()) return to_intervals(*d);
  if (storage_of(q).enclosure()) return to_intervals(*storage_of(q).enclosure());
  return to_intervals(q.matrix());
}

/// The stored enclosures of a quadric read from text, degenerate ones of a matrix of doubles, else
/// certified ones of its rationals (for a pair of which one quadric was read from text).
template <class Q>
detail::EnclosureMatrix4 enclosure_of(const Q& q) {
  if (storage_of(q).enclosure()) return *storage_of(q).enclosure();
  detail::EnclosureMatrix4 out;
  if (const std::optional<DoubleMatrix4> d = q.doubles()) {
    out.lo = out.hi = *d;
    return out;
  }
  const Matrix4& m = q.matrix();
  for (std::size_t i = 0; i < 16; ++i) {
    const std::pair<double, double> b = CGAL::to_interval(m.a[i]);
    out.lo[i] = b.first;
    out.hi[i] = b.second;
  }
  return out;
}

/// Exact data of a pair, computed only when an exact stage runs or full evidence is asked for.
/// f and s in the compact integer form (to_compact_integers): roots scaled by a positive constant,
/// so only sign and multiplicity facts may be read from them. Evaluated on PooledInteger (no heap
/// traffic for the temporaries of the generic formulas); as Integer for the factorisation stage.
struct ExactData {
  Quartic<PooledInteger> f;
  Quadratic<PooledInteger> s;
  ExactData(const Ellipsoid& e, const Paraboloid& p) {
    MatrixOf<PooledInteger> pp, ep;
    std::array<mpz_ptr, 16> pz, ez;
    for (std::size_t i = 0; i < 16; ++i) pz[i] = pp.a[i].mpz(), ez[i] = ep.a[i].mpz();
    to_compact_integers(p.matrix(), e.matrix(), pz, ez);
    f = characteristic_polynomial<PooledInteger>(pp, ep);
    s = special_polynomial<PooledInteger>(pp, ep);
  }
  Quartic<Integer> f_integer() const {
    return {f[0].to_integer(), f[1].to_integer(), f[2].to_integer(), f[3].to_integer(), f[4].to_integer()};
  }
  Quadratic<Integer> s_integer() const { return {s[0].to_integer(), s[1].to_integer(), s[2].to_integer()}; }
};

/// True when a float stage certified every sign the decision reads except Disc(f)'s: the usual state
/// near a tangency, where the exact stage then needs that one sign only.
bool only_disc_uncertain(const DecisionSigns& d) {
  const QuarticSigns& q = d.quartic;
  auto ok = [](const USign& x) { return CGAL::is_certain(x); };
  return !ok(q.g0) && ok(q.f[0]) && ok(q.f[1]) && ok(q.f[2]) && ok(q.f[3]) && ok(q.f[4]) && ok(q.g2[0]) &&
         ok(q.g2[1]) && ok(q.g2[2]) && ok(q.g1[0]) && ok(q.g1[1]) && ok(d.vertex) && ok(d.graeffe);
}

/// A square-free f with four real negative roots and a pair that is not small: the position depends
/// on where two roots lie against lambda_s (anysize/gap.hpp).
bool needs_gap(const Verdict& v) {
  return !decided(v) && !v.small && v.sign_disc_f != 0 && v.tangent_negative + v.tangent_positive == 0 &&
         v.nonreal_roots == 0 && v.positive_roots == 0 && v.roots_above_lambda_s < 0;
}

/// The gap test through its own ladder: semi-static doubles, intervals, exact integers (the last
/// always certain). Records the latest stage used.
void settle_gap(const Ellipsoid& e, const Paraboloid& p, bool use_filter, Verdict& v, std::optional<ExactData>& exact) {
  std::optional<bool> g;
  Stage stage = v.stage;
  if (use_filter) {
    if (rounding_to_nearest() && storage_of(e).filter_doubles() && storage_of(p).filter_doubles()) {
      g = semi_static_roots_above_lambda_s(*storage_of(p).filter_doubles(), *storage_of(e).filter_doubles());
      stage = std::max(stage, Stage::SemiStaticDouble);
    }
    if (!g) {
      CGAL::Protect_FPU_rounding<true> guard;
      const MatrixOf<Interval> pi = interval_entries(p), ei = interval_entries(e);
      g = anysize::roots_above_lambda_s(characteristic_polynomial<Interval>(pi, ei),
                                        special_polynomial<Interval>(pi, ei));
      stage = std::max(stage, Stage::Interval);
    }
  }
  if (!g) {
    if (!exact) exact.emplace(e, p);
    g = anysize::roots_above_lambda_s(exact->f, exact->s);
    stage = std::max(stage, Stage::ExactSigns);
  }
  if (!g) throw std::logic_error("relpos: the exact gap test left a sign uncertain");
  v.roots_above_lambda_s = static_cast<signed char>(*g);
  v.stage = stage;
  decide(v);
}

/// A stage certified the root counts: finish the decision (the gap test when it is needed). False
/// when the exact facts of math.md §8 are needed (multiple roots outside the small-pair table).
bool finish(const Ellipsoid& e, const Paraboloid& p, bool use_filter, Verdict& v, std::optional<ExactData>& exact) {
  if (decided(v)) return true;
  if (!needs_gap(v)) return false;
  settle_gap(e, p, use_filter, v, exact);
  return decided(v);
}

/// The whole filter -> exact policy in one place: each stage certifies what it can, the next one
/// runs only if a needed sign is still uncertain. All stages evaluate the same generic formulas.
/// `determinants_pending` (true on entry): a pair validated but for det E < 0 and det P < 0, which
/// the static filter certifies as f(0) and the leading coefficient (math.md §2); false once it has,
/// and nothing is decided (an empty verdict returned at once) when it has not.
Verdict run_stages(const Ellipsoid& e, const Paraboloid& p, bool use_filter, std::optional<ExactData>& exact,
                   bool* determinants_pending = nullptr) {
  Verdict v;
  DecisionSigns d;  // every sign certified so far, by any stage (uncertain until then)
  if (use_filter) {
    // The double stages assume round-to-nearest; a caller inside an upward-rounding block (CGAL
    // interval code) gets the interval stage instead.
    const bool nearest = rounding_to_nearest();
    if (storage_of(e).has_doubles() && storage_of(p).has_doubles()) {
      v.stage = Stage::StaticDouble;  // stage 1: doubles with static error bounds
      const bool in_range = storage_of(e).filter_doubles() && storage_of(p).filter_doubles() && nearest;
      if (in_range) {
        // The fast route first: f, Disc(f) and smallness only. Anything it leaves open is asked
        // again of the whole sequence, from the start.
        std::optional<bool> gap;  // the gap test from the same f and s, when it is the one open question
        const DiscriminantSignBits fast = static_filter_discriminant_bits_normalized(
            *storage_of(p).filter_doubles(), *storage_of(e).filter_doubles(), &gap);
        if (determinants_pending) {
          const unsigned f0_and_f4 = 1u << 0 | 1u << 4;  // f(0) = det E, leading coefficient det P
          if ((fast.negative & f0_and_f4) != f0_and_f4) return v;
          *determinants_pending = false;
        }
        if (decide_from_discriminant(fast, v)) {
          if (gap && needs_gap(v)) {
            v.roots_above_lambda_s = static_cast<signed char>(*gap);
            decide(v);
          }
          if (decided(v) || finish(e, p, use_filter, v, exact)) return v;  // the common case without a call
        }
        v = Verdict{};
        d = static_filter_signs_normalized(*storage_of(p).filter_doubles(), *storage_of(e).filter_doubles());
      }
      if (determinants_pending && *determinants_pending) return v;  // not in range: nothing certified
      if (decide_from_signs(d, v) && finish(e, p, use_filter, v, exact)) return v;
      if (in_range) {  // stage 1': the same signs with bounds from the actual magnitudes
        v.stage = Stage::SemiStaticDouble;
        merge_certain(
            d, semi_static_filter_signs_normalized(*storage_of(p).filter_doubles(), *storage_of(e).filter_doubles()));
        if (decide_from_signs(d, v) && finish(e, p, use_filter, v, exact)) return v;
      }
      const auto disc = detail::certain(d.quartic.g0);
      if (!disc || *disc == 0) {  // stage 1b: a witness of Disc(f) = 0 on machine integers
        v.stage = Stage::MultipleRootWitness;
        if (decide_from_witness(*p.doubles(), *e.doubles(), d, v) && decided(v)) return v;
      }
    } else if (nearest) {  // stage 1' for other entries: double enclosures (stored, or of the rationals)
      v.stage = Stage::SemiStaticDouble;
      if (storage_of(p).enclosure() || storage_of(e).enclosure()) {
        const detail::EnclosureMatrix4 ep = enclosure_of(p), ee = enclosure_of(e);
        // The discriminant route first, as for doubles; then the whole sequence from the start.
        if (decide_from_discriminant(semi_static_filter_discriminant_signs(ep, ee), v) &&
            finish(e, p, use_filter, v, exact))
          return v;
        v = Verdict{};
        v.stage = Stage::SemiStaticDouble;
        d = semi_static_filter_signs(ep, ee);
      } else {
        d = semi_static_filter_signs(p.matrix(), e.matrix());
      }
      if (decide_from_signs(d, v) && finish(e, p, use_filter, v, exact)) return v;
    }
    // Stage 2 only while Disc(f) is within reach of intervals: near a multiple root its value sits
    // orders of magnitude inside the semi-static bound, and every decision needs its sign.
    if (!d.disc_hopeless) {
      v.stage = Stage::Interval;               // stage 2: interval arithmetic
      CGAL::Protect_FPU_rounding<true> guard;  // Interval_nt<false> needs rounding towards +inf
      const MatrixOf<Interval> pi = interval_entries(p), ei = interval_entries(e);
      merge_certain(d, signs_in(characteristic_polynomial<Interval>(pi, ei), special_polynomial<Interval>(pi, ei)));
      if (decide_from_signs(d, v) && finish(e, p, use_filter, v, exact)) return v;
    }
  }
  if (!exact) exact.emplace(e, p);
  v.stage = Stage::ExactSigns;  // stage 3: exact integer signs of the same polynomials
  PooledInteger disc = discriminant_times_27(exact->f);
  if (use_filter && only_disc_uncertain(d)) {
    d.quartic.g0 = sign_of(disc);
    // Disc(f) = 0 needs the subresultants below (stage 4).
    if (d.quartic.g0 != CGAL::ZERO && decide_from_signs(d, v) && finish(e, p, use_filter, v, exact)) return v;
  }
  mpz_divexact_ui(disc.mpz(), disc.mpz(), 27);  // Disc(f) itself, the sequence's g0: 80 products fewer
  const SturmHabicht<PooledInteger> sh(exact->f, std::move(disc));  // kept: stage 4 reads the subresultants
  {
    const SmallnessQuantities<PooledInteger> sq(exact->f, exact->s);
    if (decide_from_signs(DecisionSigns{signs_of(exact->f, sh), sign_of(sq.vertex), sign_of(sq.graeffe)}, v) &&
        finish(e, p, use_filter, v, exact))
      return v;
  }
  // Stage 4: Disc(f) = 0 or a defective Sturm-Habicht sequence: exact gcd and factorisation.
  v.stage = Stage::ExactRoots;
  RootFacts x;
  const Quartic<Integer> fi = exact->f_integer();
  const Quadratic<Integer> si = exact->s_integer();
  const Integer g2[3] = {sh.g2[0].to_integer(), sh.g2[1].to_integer(), sh.g2[2].to_integer()};
  const Integer g1[2] = {sh.g1[0].to_integer(), sh.g1[1].to_integer()};
  std::optional<RootFacts> facts = subresultant_root_facts(fi, si, g2, g1, sh.g0[0].to_integer());
  if (!facts) facts = exact_root_facts_by_factorisation(fi, si);
  if (facts) {
    x = *facts;  // closed forms on the degree <= 2 square-free factors
  } else {       // square-free f with a defective sequence: isolate the roots
    const RootStructure rs = exact_root_structure(fi, si);  // counts only: the roots are scaled
    x.real = static_cast<int>(rs.real_roots.size());
    x.negative = rs.negative();
    x.positive = rs.positive();
    x.nonreal = rs.nonreal;
    x.nonreal_multiple = rs.nonreal_multiple;
    for (const auto& r : rs.real_roots)
      if (r.tangency()) ++(r.sign < 0 ? x.tangent_negative : x.tangent_positive);
    x.sign_disc_f = rs.sign_disc_f;
    x.sign_disc_ftilde = rs.sign_disc_ftilde;
  }
  decide_from_facts(x, *compare_rho_with_one(exact->f, exact->s), v);  // exact: certain
  if (!decided(v) && needs_gap(v)) settle_gap(e, p, false, v, exact);
  if (!decided(v)) decide_any_size(fi, si, v);  // math.md §8: every pair gets an answer
  return v;
}

/// The double nearest q (ties to even; CGAL's to_double of a Gmpq truncates): rounded once to 53
/// bits by MPFR, which is the double itself unless it is subnormal, then rounded from 40 digits.
double nearest_double(const Rational& q) {
  MPFR_DECL_INIT(x, 53);  // on the stack: no allocation, nothing to clear
  mpfr_set_q(x, q.mpq(), MPFR_RNDN);
  const double d = mpfr_get_d(x, MPFR_RNDN);
  if (d == 0 || std::fabs(d) < DBL_MIN || !std::isfinite(d)) return std::strtod(to_decimal(q, 40).c_str(), nullptr);
  return d;
}

/// f = det(lambda P + E) and s = det(lambda A + M) from the two integer forms Pz = lp P and
/// Ez = le E (forms::integer_form): with g = det(mu Pz + Ez) and h = det(mu Az + Mz),
///   f_i = g_i / (lp^i le^(4-i)),  s_i = h_i / (lp^i le^(3-i))   (reported reduced),
/// and the common-lcm integer forms of the root isolation, S^4 f and S^3 s with S = lcm(lp, le):
///   S^4 f_i = g_i (S/lp)^i (S/le)^(4-i),  S^3 s_i = h_i (S/lp)^i (S/le)^(3-i).
void reported_polynomials(const Quartic<PooledInteger>& g, const Quadratic<PooledInteger>& h,
                          const forms::SplitScale& sp, const forms::SplitScale& se, const Integer& lp,
                          const Integer& le, Classification& out, Quartic<Integer>& fi, Quadratic<Integer>& si) {
  // Every Rational and Integer written here is a fresh default one (its value not shared): written
  // in place, without a temporary handle per coefficient.
  for (unsigned long i = 0; i < 5; ++i) forms::divided_by_powers(g[i].mpz(), {{sp, i}, {se, 4 - i}}, out.f[i].mpq());
  for (unsigned long i = 0; i < 3; ++i) forms::divided_by_powers(h[i].mpz(), {{sp, i}, {se, 3 - i}}, out.s[i].mpq());
  // S/lp and S/le from the splits, without a gcd: S = 2^max 5^max lcm(rest_p, rest_e), and the lcm
  // of the rests is one of them when the other is 1 or they are equal (doubles, decimal text, a
  // standard paraboloid with decimal a and b beside a decimal ellipsoid). Then
  // S/lp = 2^ta 5^fa rest_a with rest_a = rest_e / gcd = rest_e or 1, and the same for S/le.
  const bool p_rest_one = mpz_cmp_ui(sp.rest.mpz(), 1) == 0, e_rest_one = mpz_cmp_ui(se.rest.mpz(), 1) == 0;
  if (p_rest_one || e_rest_one || mpz_cmp(sp.rest.mpz(), se.rest.mpz()) == 0) {
    const unsigned long twos = std::max(sp.twos, se.twos), fives = std::max(sp.fives, se.fives);
    const unsigned long ta = twos - sp.twos, tb = twos - se.twos, fa = fives - sp.fives, fb = fives - se.fives;
    const forms::SplitScale* rest_a = p_rest_one && !e_rest_one ? &se : nullptr;  // its rest_power: rest_a^k
    const forms::SplitScale* rest_b = e_rest_one && !p_rest_one ? &sp : nullptr;
    auto times = [&](const PooledInteger& z, unsigned long i, unsigned long j, Integer& r) {  // z (S/lp)^i (S/le)^j
      const mpz_ptr to = r.mpz();  // a fresh Integer: written in place
      mpz_mul_2exp(to, z.mpz(), ta * i + tb * j);
      if (const unsigned long k = fa * i + fb * j; k > 0) forms::times_power_of_five(to, to, k);
      if (rest_a && i > 0) mpz_mul(to, to, rest_a->rest_power[i].mpz());
      if (rest_b && j > 0) mpz_mul(to, to, rest_b->rest_power[j].mpz());
    };
    for (unsigned long i = 0; i < 5; ++i) times(g[i], i, 4 - i, fi[i]);
    for (unsigned long i = 0; i < 3; ++i) times(h[i], i, 3 - i, si[i]);
    return;
  }
  PooledInteger common, a, b;
  mpz_lcm(common.mpz(), lp.mpz(), le.mpz());
  mpz_divexact(a.mpz(), common.mpz(), lp.mpz());
  mpz_divexact(b.mpz(), common.mpz(), le.mpz());
  PooledInteger pa[5], pb[5];  // powers of S/lp and S/le
  pa[0] = pb[0] = PooledInteger(1);
  for (std::size_t i = 1; i < 5; ++i) pa[i] = pa[i - 1] * a, pb[i] = pb[i - 1] * b;
  auto times = [](const PooledInteger& z, const PooledInteger& x, const PooledInteger& y, Integer& r) {
    mpz_mul(r.mpz(), z.mpz(), x.mpz());
    mpz_mul(r.mpz(), r.mpz(), y.mpz());
  };
  for (std::size_t i = 0; i < 5; ++i) times(g[i], pa[i], pb[4 - i], fi[i]);
  for (std::size_t i = 0; i < 3; ++i) times(h[i], pa[i], pb[3 - i], si[i]);
}

/// The numbers of a sphere or standard paraboloid read from decimal text, or nullptr.
const forms::DecimalShape* decimal_shape_of(const detail::QuadricMatrix& q) {
  const detail::ExactSource* source = q.exact_source();
  return source ? source->decimal_shape() : nullptr;
}

/// The root facts of the full evidence.
void take_roots(RootStructure&& rs, Classification& out) {
  out.has_full_evidence = true;
  out.degree_ftilde = rs.degree_ftilde;
  out.roots = std::move(rs.real_roots);
}

/// A rational rho, with the double nearest it.
void take_rho(const Rational& rho, Classification& out) {
  out.rho = rho;
  out.rho_approx = nearest_double(*out.rho);
}

/// lambda_s, the root of s nearest 0, computed once for rho and for the certificate, from h: with
/// mu = lambda le / lp, s(lambda) = h(mu) / le^3, so Disc(s) = Disc(h) / (lp le^2)^2 (reduced along
/// the split scales), rational iff Disc(h) is a square R^2, and then
/// lambda_s = (lp / le) (R - h1) / (2 h2). `s` is the reduced s.
anysize::LambdaS lambda_s_of_pencil(const Quadratic<PooledInteger>& h, const forms::SplitScale& sp,
                                    const forms::SplitScale& se, const Quadratic<Rational>& s) {
  PooledInteger disc, t;
  mpz_mul(disc.mpz(), h[1].mpz(), h[1].mpz());
  mpz_mul(t.mpz(), h[2].mpz(), h[0].mpz());
  mpz_submul_ui(disc.mpz(), t.mpz(), 4);
  if (h[2].sign() > 0 && mpz_sgn(disc.mpz()) >= 0 && mpz_perfect_square_p(disc.mpz())) {
    // lambda_s = (R - h1) lp / (2 h2 le) = ((R - h1) / (lp le^2)) / (2 s2), as h2 = lp^2 le s2: the
    // first quotient reduced along the split scales, the second one a quotient of short fractions.
    PooledInteger root_minus_h1;
    mpz_sqrt(root_minus_h1.mpz(), disc.mpz());
    mpz_sub(root_minus_h1.mpz(), root_minus_h1.mpz(), h[1].mpz());
    Rational l;  // fresh: written in place
    forms::divided_by_powers(root_minus_h1.mpz(), {{sp, 1}, {se, 2}}, l.mpq());
    mpq_div(l.mpq(), l.mpq(), s[2].mpq());
    mpq_div_2exp(l.mpq(), l.mpq(), 1);
    return anysize::rational_lambda_s(l);
  }
  return anysize::lambda_s_of(anysize::to_poly(s.data(), 3), forms::divided_by_powers(disc.mpz(), {{sp, 2}, {se, 4}}));
}

/// The rest of the reported evidence: the roots, and rho = (f0/f4)(s2/s0) / u1^2 with
/// u1 = -lambda_s, the smallest root of s(-u), rational iff Disc(s) is a square (lambda_s of
/// lambda_s_of_pencil). A rational rho comes from the reduced f, s and lambda_s; an irrational one
/// only as a double, from the reduced f and s.
void fill_full_evidence(RootStructure&& rs, const anysize::LambdaS& ls, Classification& out) {
  take_roots(std::move(rs), out);
  // k = (f0 s2) / (f4 s0)
  if (ls.rational()) {
    // rho = (f0 / f4) (s2 / s0) / lambda_s^2 from the reduced coefficients and lambda_s: GMP's
    // products of fractions in lowest terms take gcds of their short parts only, where reducing
    // 4 g0 h2^3 / (g4 h0 (R - h1)^2) is one gcd of numbers ten times longer (mostly the scales).
    // s2 / f4 first: both are over powers of lp (h2 / (lp^2 le), g4 / lp^4), so their quotient
    // cancels most of both and the later gcds see short numbers (the order sets their sizes).
    Rational rho;  // fresh: written in place
    const mpq_ptr r = rho.mpq();
    mpq_div(r, out.s[2].mpq(), out.f[4].mpq());  // f4 = det P, s0 = det M and lambda_s are not 0
    mpq_mul(r, r, out.f[0].mpq());
    mpq_div(r, r, out.s[0].mpq());
    mpq_mul(r, r, forms::inverse_square(ls.value().a).mpq());
    take_rho(rho, out);
  } else {
    // k only as a double (CGAL::to_double is mpq_get_d: the exact quotient truncated, whatever
    // fraction represents it), so from the unreduced product of the reduced coefficients: no gcd.
    PooledInteger kn_, kd_;
    const mpz_ptr kn = kn_.mpz(), kd = kd_.mpz();
    mpz_mul(kn, mpq_numref(out.f[0].mpq()), mpq_denref(out.f[4].mpq()));
    mpz_mul(kn, kn, mpq_numref(out.s[2].mpq()));
    mpz_mul(kn, kn, mpq_denref(out.s[0].mpq()));
    mpz_mul(kd, mpq_denref(out.f[0].mpq()), mpq_numref(out.f[4].mpq()));
    mpz_mul(kd, kd, mpq_denref(out.s[2].mpq()));
    mpz_mul(kd, kd, mpq_numref(out.s[0].mpq()));
    if (mpz_sgn(kd) < 0) {  // a positive denominator, as mpq_get_d reads it
      mpz_neg(kn, kn);
      mpz_neg(kd, kd);
    }
    const __mpq_struct k{*kn, *kd};  // a read-only view of the fraction
    const double k_double = mpq_get_d(&k);
    const double s2 = forms::truncated_double(out.s[2]), s1 = forms::truncated_double(out.s[1]),
                 s0 = forms::truncated_double(out.s[0]);
    const double u1 = (2 * s0) / (s1 + std::sqrt(s1 * s1 - 4 * s2 * s0));  // stable smaller root
    out.rho_approx = k_double / (u1 * u1);
  }
}

/// The integer forms of the full evidence, one pair per thread: rewritten (all 16 entries each) by
/// every classify_impl and read only within that call (by the certificate too), so their integers
/// are not taken from and given back to the pool 32 times per pair. classify_impl never runs
/// inside itself.
struct PooledForms {
  MatrixOf<PooledInteger> p, e;
};
PooledForms& pooled_forms() {
  thread_local PooledForms forms;
  return forms;
}

/// Makes z safe to write in place: a fresh Integer when another handle shares its value (a copy
/// kept by a callee), else z itself. CGAL's reference count is on Gmpz's private base, which a
/// C-style cast converts to all the same (C++17 [expr.cast]/4).
void make_unshared(Integer& z) {
  if (((const CGAL::Handle_for<CGAL::Gmpz_rep>&)z).is_shared()) z = Integer();  // NOLINT: the private base
}

/// An Integer 0 without a heap allocation, to be assigned (never written in place): a copy of the
/// thread's.
Integer shared_zero() {
  thread_local const Integer zero;
  return zero;
}

/// The split of the scale 1 without a heap allocation: a copy of the thread's (its rest shares the
/// thread's 1; the integer forms' writers assign a whole split, never its rest in place).
forms::SplitScale unit_split() {
  thread_local const forms::SplitScale unit;
  return unit;
}

/// A default Classification without a heap allocation per number: a copy of the thread's default
/// one, its numbers sharing that one's (a Gmpq copy shares its value; each default Gmpq costs two
/// allocations, and a certificate holds some twenty, most never written). Safe because every
/// number of a result is assigned, never written in place, except f and s (made fresh by the
/// caller before their in-place writes).
Classification default_classification() {
  thread_local const Classification prototype;
  return prototype;
}

Classification classify_impl(const Ellipsoid& e, const Paraboloid& p, Evidence evidence, bool use_filter) {
  std::optional<ExactData> exact;
  const Verdict v = run_stages(e, p, use_filter, exact);
  Classification out = default_classification();
  out.verdict = v;
  if (evidence == Evidence::Full) {  // reported exactly as det(lambda P + E), from each matrix's own form
    // Fresh numbers: reported_polynomials writes them in place.
    for (Rational& c : out.f) c = Rational();
    for (Rational& c : out.s) c = Rational();
    // The integer forms, without a rational matrix: as machine words for doubles whose forms fit
    // (below), else written straight into pooled integers (the generic formulas without heap traffic
    // for temporaries), from the doubles or from the quadric's exact source with the scale's split
    // (each scale's rest kept as its denominators' factors: every gcd of the reduction is short); the
    // closed forms of a decimal sphere and standard paraboloid may need no form at all.
    const std::optional<DoubleMatrix4> pd = p.doubles(), ed = e.doubles();  // copies: read once
    // The scales: fresh where an exact source writes them in place; integer_form of doubles assigns
    // its own, so there a copy of the thread's 0 (no allocation) is what it replaces.
    Integer lp = pd ? shared_zero() : Integer(), le = ed ? shared_zero() : Integer();
    MatrixOf<PooledInteger>& pp = pooled_forms().p;  // every entry rewritten below
    MatrixOf<PooledInteger>& ep = pooled_forms().e;
    forms::SplitScale sp = unit_split(), se = unit_split();
    // A sphere and a standard paraboloid read from decimal text: f, s, lambda_s and rho from their
    // closed forms, on short integers (the splits then need no factors).
    const forms::DecimalShape* es = ed ? nullptr : decimal_shape_of(storage_of(e));
    const forms::DecimalShape* ps = pd ? nullptr : decimal_shape_of(storage_of(p));
    const bool closed = es && ps && es->sphere && !ps->sphere;
    // The closed forms read only the scales' exponents, and the multipliers of E and I no integer
    // form: then only those exponents are written (no entries, lcm or rest; nothing for the certificate).
    const bool scales_only = closed && (v.position == Position::E || v.position == Position::I);
    // Doubles whose integer forms fit in machine words (nearly all): those forms with their scales'
    // exponents straight from the doubles, and none in GMP (lp and le are not read: the scales are
    // powers of two; the certificate forms its own from the doubles when it needs one).
    MatrixOf<std::int64_t> pw, ew;
    const bool words =
        pd && ed && forms::small_integer_form(*pd, pw, sp.twos) && forms::small_integer_form(*ed, ew, se.twos);
    // Else in pooled integers (a scale of doubles is a power of two: its split is its exponent).
    if (!words) {
      if (pd) {
        forms::integer_form(*pd, forms::entries(pp), lp);
        sp.twos = mpz_scan1(lp.mpz(), 0);
      } else {
        forms::integer_form_of(storage_of(p), {forms::entries(pp), lp, sp, !closed, !scales_only, !scales_only});
      }
      if (ed) {
        forms::integer_form(*ed, forms::entries(ep), le);
        se.twos = mpz_scan1(le.mpz(), 0);
      } else {
        forms::integer_form_of(storage_of(e), {forms::entries(ep), le, se, !closed, !scales_only, !scales_only});
      }
    }
    // S^4 f and S^3 s: the thread's, written in place (their limbs kept from call to call).
    thread_local Quartic<Integer> f;
    thread_local Quadratic<Integer> s;
    for (Integer& c : f) make_unshared(c);
    for (Integer& c : s) make_unshared(c);
    const anysize::LambdaS ls = [&] {
      if (closed) {
        Rational lambda_s, rho;  // fresh: written in place
        // S = lcm(lp, le): a sphere's scale is 2^a 5^b, a standard paraboloid's 2^c 5^d lcm(R_a^2, R_b^2).
        forms::sphere_standard_evidence(
            *es, *ps, {out.f, out.s, lambda_s, rho, std::max(sp.twos, se.twos), std::max(sp.fives, se.fives), f, s});
        take_roots(exact_root_structure(f, s, v.sign_disc_f), out);
        take_rho(rho, out);
        return anysize::rational_lambda_s(lambda_s);
      }
      // g and h in fixed-size integers when the entries are short, else with GMP.
      Quartic<PooledInteger> g;
      Quadratic<PooledInteger> h;
      if (words) {
        small_pencil_polynomials(pw, ew, g, h);
      } else if (!small_pencil_polynomials(pp, ep, g, h)) {
        g = exact_characteristic_polynomial<PooledInteger>(pp, ep);
        h = exact_special_polynomial<PooledInteger>(pp, ep);
      }
      reported_polynomials(g, h, sp, se, lp, le, out, f, s);
      // The verdict's sign of Disc(f) is certified (a positive rescaling of f keeps it).
      RootStructure rs = exact_root_structure(f, s, v.sign_disc_f);
      anysize::LambdaS from_pencil = lambda_s_of_pencil(h, sp, se, out.s);
      fill_full_evidence(std::move(rs), from_pencil, out);
      return from_pencil;
    }();
    // The certificate reuses f, s, lambda_s, the isolation, the integer forms and S^4 f. The forms
    // with their scales only where it reads them (the points of C, TE and TI, not the multipliers
    // of E and I) and cannot take them from the doubles: copied from the pooled ones on first use.
    certificate::Known known{&out.f, &out.s, &out.roots, &ls, nullptr, &f};
    if (!words && !scales_only) {
      known.ez_pooled = &ep;
      known.pz_pooled = &pp;
    }
    if (!(pd && ed) && v.position != Position::E && v.position != Position::I) {
      known.le_pooled = &le;
      known.lp_pooled = &lp;
    }
    certificate::build(e, p, v.position, known, out.certificate);
  }
  return out;
}

}  // namespace

void detail::static_route_table(Verdict (&table)[4][3]) {
  for (int c = 0; c < 4; ++c)
    for (int rho = -1; rho <= 1; ++rho) {
      Verdict& v = table[c][rho + 1];
      v = Verdict{};  // stage StaticDouble
      if (!decide_from_discriminant(static_cast<DiscriminantCase>(c), rho, v)) v = Verdict{};
    }
}

bool detail::static_route_gap(Verdict& v, bool gap) {
  if (!needs_gap(v)) return false;
  v.roots_above_lambda_s = static_cast<signed char>(gap);
  decide(v);
  return decided(v);
}

std::optional<Verdict> decide_from_root_facts(const RootFacts& facts, int rho_vs_one) {
  Verdict v;
  decide_from_facts(facts, rho_vs_one, v);
  if (!decided(v)) return std::nullopt;
  return v;
}

Verdict decide_position(const Ellipsoid& e, const Paraboloid& p) {
  // Doubles and the fast reader's numbers are within the size limit: the check's own two flag
  // tests, without the call.
  if (!storage_of(e).within_size_limit() || !storage_of(p).within_size_limit()) check_normalized_pair_size(e, p);
  std::optional<ExactData> exact;
  return run_stages(e, p, true, exact);
}

Verdict decide_position(const DoubleMatrix4& e, const DoubleMatrix4& p) {
  // The objects from_doubles builds (normalized in place, the same orientation), with every shape
  // sign but the determinants certified; run_stages certifies those from the pencil or gives up.
  // Matrices of doubles are within the size limit (check_normalized_pair_size): no check. The
  // ellipsoid's signs assume round to nearest: run_stages certifies the determinants (clears
  // `pending`) only in that mode; in any other the two steps below decide.
  Ellipsoid ell(e);
  Paraboloid par(p);
  const int oe = shape_filter::ellipsoid_before_det_if_nearest(ell.m_.filter_doubles());
  const int op = oe != 0 ? shape_filter::paraboloid_before_det(p, par.m_.filter_doubles()) : 0;
  if (op != 0) {
    if (oe < 0) ell.m_.negate_doubles();
    if (op < 0) par.m_.negate_doubles();
    bool pending = true;
    std::optional<ExactData> exact;
    const Verdict v = run_stages(ell, par, true, exact, &pending);
    if (!pending) return v;
  }
  // Anything uncertain, and every invalid input: the two steps themselves (their errors, the
  // ellipsoid's first: two statements, as the order of a call's arguments is unspecified).
  const Ellipsoid first = Ellipsoid::from_doubles(e);
  return decide_position(first, Paraboloid::from_doubles(p));
}

Classification classify(const Ellipsoid& e, const Paraboloid& p, Evidence evidence) {
  check_normalized_pair_size(e, p);
  return classify_impl(e, p, evidence, true);
}

Classification classify_exact(const Ellipsoid& e, const Paraboloid& p, Evidence evidence) {
  check_normalized_pair_size(e, p);
  return classify_impl(e, p, evidence, false);
}

Classification detail::classify_unchecked(const Ellipsoid& e, const Paraboloid& p, Evidence evidence) {
  return classify_impl(e, p, evidence, true);
}

}  // namespace relpos
