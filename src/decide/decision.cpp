#include "decide/decision.hpp"

#include "anysize/exact.hpp"

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

std::optional<Verdict> detail::decide_from_root_facts(const RootFacts& facts, int rho_vs_one) {
  Verdict v;
  detail::decide_from_facts(facts, rho_vs_one, v);
  if (!detail::decided(v)) return std::nullopt;
  return v;
}

namespace detail {

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

namespace {

/// decide_from_signs without the table: every case, the table's source.
bool decide_from_signs_slow(const DecisionSigns& d, Verdict& v) {
  auto disc = certain(d.quartic.g0);
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
  Verdict v[256][3];              // [sign bits][rho_vs_one + 1]
  [[gnu::flatten]] SignTable() {  // flatten: the one written decision inlined into its 768 runs
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

}  // namespace

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

CaseTable::CaseTable() {
  for (int c = 1; c < 4; ++c)
    for (int rho = -1; rho <= 1; ++rho)
      decide_from_facts(root_facts_of(static_cast<DiscriminantCase>(c)), rho, v[c][rho + 1]);
}

}  // namespace detail
}  // namespace relpos
