// A motion's positions over [t0, t1] (math.md §7): the first contact and the timeline. The moving
// pencil gives the event polynomials (moving_pencil.hpp), their real zeros the candidate instants
// (candidates.hpp); each open interval between two is classified at a rational sample, each instant
// exactly (classify at a rational one; the definiteness test of instant_position.hpp, or the
// neighbours' position when f is square-free there, at an irrational one), and every instant is
// cross-checked with its neighbours.
#include "relpos/motion.hpp"

#include <stdexcept>
#include <utility>

#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "base/interrupt.hpp"
#include "decide/unchecked.hpp"
#include "motion/candidates.hpp"
#include "motion/instant_position.hpp"
#include "motion/moving_pencil.hpp"
#include "motion/polynomial_motion.hpp"
#include "motion/subresultant_position.hpp"
#include "relpos/error.hpp"

namespace relpos {
namespace {

using detail::add_zeros;
using detail::AK;
using detail::Alg;
using detail::Candidate;
using detail::instant_of;
using detail::make_candidate;
using detail::MovingPencil;
using detail::PolyZ;
using detail::rational_between;
using detail::sign_at;

int total_degree(const std::vector<std::pair<PolyZ, unsigned>>& polys) {
  int d = 0;
  for (const auto& [p, cause] : polys)
    if (!CGAL::is_zero(p) && p.degree() > 0) d += p.degree();
  return d;
}

/// The position at an instant t* where f(., t*) has a multiple root, for any size (instant_position.hpp);
/// nullopt when f(., t*) is square-free there. `interrupt` is checked before every sign.
std::optional<detail::InstantDecision> decide_at(const MovingPencil& mp, const AK& ak, const Candidate& a,
                                                 const Interrupt* interrupt) {
  // A zero of the discriminant polynomial (its minimal polynomial divides Disc f) needs no test.
  const bool known_multiple = mp.disc_zero || ((a.causes & kCauseDiscriminant) && !a.exact);
  return detail::decide_at_instant(
      *mp.instant,
      [&](const PolyZ& q) {
        detail::check(interrupt);
        return sign_at(ak, q, a);
      },
      known_multiple);
}

/// rho(t*) <= 1 at an instant (the two smallness quantities' signs; reported, never needed).
bool small_at(const MovingPencil& mp, const AK& ak, const Candidate& a) {
  return *compare_rho_with_one(USign(static_cast<CGAL::Sign>(sign_at(ak, mp.vertex, a))),
                               USign(static_cast<CGAL::Sign>(sign_at(ak, mp.graeffe, a)))) <= 0;
}

/// Positions that a limit of configurations in position p can have (the contact set is closed,
/// E, I and C are open conditions; an ellipsoid cannot lie both inside-or-on and outside-or-on).
unsigned closure(Position p) {
  auto bit = [](Position q) { return 1u << static_cast<unsigned>(q); };
  switch (p) {
    case Position::E:
      return bit(Position::E) | bit(Position::TE);
    case Position::I:
      return bit(Position::I) | bit(Position::TI);
    case Position::C:
      return bit(Position::C) | bit(Position::TI) | bit(Position::TE);
    case Position::TE:
      return bit(Position::TE);
    case Position::TI:
      return bit(Position::TI);
  }
  return 0;
}

/// The cross-check of an instant with its neighbouring intervals (`closure`): a violation is a
/// defect, never an answer.
void check_closure(Position at, const std::optional<Position>& before, const std::optional<Position>& after,
                   const AlgebraicReal& t) {
  const unsigned bit = 1u << static_cast<unsigned>(at);
  for (const auto& n : {before, after})
    if (n && !(closure(*n) & bit))
      throw std::logic_error("internal error: motion: position " + to_string(at) + " at t = " + t.decimals(20) +
                             " is not a limit of the neighbouring position " + to_string(*n));
}

Classification classify_at(const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p, const Rational& t) {
  return detail::classify_unchecked(detail::placed_ellipsoid(e0, m, t), p, Evidence::Minimal);
}

std::string classify_how(const Classification& c) {
  return "classified exactly at the rational instant (" + to_string(c.verdict.stage) + ")";
}

/// The candidate instants in [t0, t1], with t0 and t1 themselves, increasing.
std::vector<Candidate> candidate_instants(const MovingPencil& mp, const AK& ak, const Rational& t0, const Rational& t1,
                                          const Interrupt* interrupt) {
  std::vector<Candidate> cands{make_candidate(Alg(t0), kCauseStart, t0, {-t0.numerator(), t0.denominator()})};
  if (t1 > t0)
    cands.push_back(make_candidate(Alg(t1), kCauseEnd, t1, {-t1.numerator(), t1.denominator()}));
  else
    cands.front().causes |= kCauseEnd;
  for (const auto& [poly, cause] : mp.events) add_zeros(ak, poly, cause, t0, t1, cands, interrupt);
  return cands;
}

/// The position at one candidate instant: classified at a rational one; at an irrational one
/// (interior, t0 and t1 being rational: `before` is the interval on its left) the definiteness test
/// of instant_position.hpp for any size, or, f square-free at t* (no tangency: that needs a
/// multiple root), the open position (E, I or C) of the neighbouring intervals.
MotionInstant instant_at(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const MovingPencil& mp,
                         const AK& ak, const Candidate& z, const std::optional<Position>& before,
                         const Interrupt* interrupt) {
  MotionInstant inst{instant_of(z), Position::C, false, z.causes, ""};
  if (inst.time.is_rational()) {
    const Classification c = classify_at(e0, motion, p, *inst.time.exact());
    inst.position = c.verdict.position;
    inst.small = c.verdict.small;
    inst.how = classify_how(c);
    return inst;
  }
  if (const auto d = decide_at(mp, ak, z, interrupt)) {
    inst.position = d->position;
    inst.how = "at the algebraic instant: " + d->how;
  } else {
    inst.position = *before;
    inst.how =
        "at the algebraic instant: f is square-free (no root merges), the position of the neighbouring "
        "intervals";
  }
  detail::check(interrupt);
  inst.small = small_at(mp, ak, z);
  return inst;
}

}  // namespace

std::vector<std::string> detail::cause_names(unsigned causes) {
  std::vector<std::string> out;
  if (causes & kCauseStart) out.emplace_back("start");
  if (causes & kCauseEnd) out.emplace_back("end");
  if (causes & kCauseDiscriminant) out.emplace_back("discriminant");
  if (causes & kCauseSpecialRoot) out.emplace_back("special-root");
  if (causes & kCauseSmallness) out.emplace_back("smallness");
  return out;
}

std::string to_string(FirstContact::Kind kind) {
  switch (kind) {
    case FirstContact::Kind::NotExteriorAtStart:
      return "not-exterior-at-start";
    case FirstContact::Kind::Contact:
      return "contact";
    case FirstContact::Kind::None:
      return "none";
  }
  throw std::logic_error("internal error: to_string: not a FirstContact::Kind");
}

FirstContact first_contact(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                           const Rational& t1, const Interrupt* interrupt) {
  detail::validate_motion(motion, t0, t1);
  detail::check(interrupt);
  FirstContact out;
  const Classification c0 = classify_at(e0, motion, p, t0);
  out.start_position = c0.verdict.position;
  if (c0.verdict.position != Position::E) {
    out.kind = FirstContact::Kind::NotExteriorAtStart;
    out.time = AlgebraicReal::rational(t0);
    out.position = c0.verdict.position;
    out.how = classify_how(c0);
    return out;
  }
  // Separation (two distinct positive roots) is open and is decided for any size; it can only end
  // where two roots of f meet, i.e. at a real zero of `merge` (math.md §7).
  const MovingPencil mp(e0, motion, p, interrupt);
  AK ak;
  std::vector<Candidate> zeros;
  add_zeros(ak, mp.merge, kCauseDiscriminant, t0, t1, zeros, interrupt);
  const auto cmp = ak.compare_1_object();
  const Alg a0(t0);
  for (const Candidate& z : zeros) {
    if (cmp(z.t, a0) == CGAL::EQUAL) continue;  // t0 itself: classified above
    detail::check(interrupt);
    Position pos;
    std::string how;
    if (z.exact) {
      const Classification c = classify_at(e0, motion, p, *z.exact);
      pos = c.verdict.position;
      how = classify_how(c);
    } else {
      // The left neighbour is E; E is open, so a square-free f (no root merges) keeps it.
      const auto d = decide_at(mp, ak, z, interrupt);
      if (!d) continue;
      pos = d->position;
      how = "at the algebraic instant: " + d->how;
      check_closure(pos, Position::E, std::nullopt, instant_of(z));
    }
    if (pos != Position::E) {
      out.kind = FirstContact::Kind::Contact;
      out.time = instant_of(z);
      out.position = pos;
      out.how = how;
      return out;
    }
  }
  out.kind = FirstContact::Kind::None;
  return out;
}

Timeline timeline(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p, const Rational& t0,
                  const Rational& t1, const Interrupt* interrupt) {
  detail::validate_motion(motion, t0, t1);
  Timeline out;
  out.t0 = t0;
  out.t1 = t1;
  const MovingPencil mp(e0, motion, p, interrupt);
  out.discriminant_identically_zero = mp.disc_zero;
  out.event_degree = total_degree(mp.events);
  AK ak;
  const std::vector<Candidate> cands = candidate_instants(mp, ak, t0, t1, interrupt);
  // Open intervals: classified exactly at a rational sample strictly inside.
  for (std::size_t i = 0; i + 1 < cands.size(); ++i) {
    detail::check(interrupt);
    MotionInterval iv;
    iv.sample = rational_between(cands[i].t, cands[i + 1].t);
    const Classification c = classify_at(e0, motion, p, iv.sample);
    iv.position = c.verdict.position;
    iv.small = c.verdict.small;
    out.intervals.push_back(std::move(iv));
  }
  for (std::size_t i = 0; i < cands.size(); ++i) {
    detail::check(interrupt);
    const std::optional<Position> before =
        i > 0 ? std::optional<Position>(out.intervals[i - 1].position) : std::nullopt;
    MotionInstant inst = instant_at(e0, motion, p, mp, ak, cands[i], before, interrupt);
    // Cross-check with the neighbours: E|C forces TE, I|C forces TI, E|I is impossible, ...
    check_closure(inst.position, before,
                  i + 1 < cands.size() ? std::optional<Position>(out.intervals[i].position) : std::nullopt, inst.time);
    out.instants.push_back(std::move(inst));
  }
  return out;
}

std::optional<Position> position_by_subresultants(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p,
                                                  const Rational& t) {
  const MovingPencil mp(e0, motion, p, nullptr);
  AK ak;
  const auto d = decide_at(mp, ak, make_candidate(Alg(t), 0, t, {-t.numerator(), t.denominator()}), nullptr);
  if (!d) return std::nullopt;
  return d->position;
}

std::vector<PositionChange> Timeline::changes() const {
  std::vector<PositionChange> out;
  for (std::size_t i = 0; i < instants.size(); ++i) {
    PositionChange c{instants[i].time, std::nullopt, instants[i].position, std::nullopt};
    if (i > 0) c.before = intervals[i - 1].position;
    if (i < intervals.size()) c.after = intervals[i].position;
    const bool changed = (c.before && *c.before != c.at) || (c.after && *c.after != c.at);
    if (changed) out.push_back(std::move(c));
  }
  return out;
}

std::vector<PositionSpan> Timeline::spans() const {
  std::vector<PositionSpan> out;
  auto extend = [&](const AlgebraicReal& from, bool from_closed, const AlgebraicReal& to, bool to_closed,
                    Position pos) {
    if (!out.empty() && out.back().position == pos) {
      out.back().to = to;
      out.back().to_closed = to_closed;
    } else {
      out.push_back(PositionSpan{from, to, from_closed, to_closed, pos});
    }
  };
  for (std::size_t i = 0; i < instants.size(); ++i) {
    extend(instants[i].time, true, instants[i].time, true, instants[i].position);
    if (i < intervals.size()) extend(instants[i].time, false, instants[i + 1].time, false, intervals[i].position);
  }
  return out;
}

Position Timeline::position_at(const Rational& t) const {
  if (instants.empty() || intervals.size() + 1 != instants.size())
    throw InputError("Timeline::position_at: an empty or inconsistent timeline (build it with relpos::timeline)");
  if (t < t0 || t > t1) throw InputError("time " + to_string(t) + " is outside [t0, t1]");
  for (std::size_t i = 0; i < instants.size(); ++i) {
    const int c = instants[i].time.compare(t);
    if (c == 0) return instants[i].position;
    if (c > 0) return intervals[i - 1].position;  // i > 0 because instants[0] = t0 <= t
  }
  return instants.back().position;
}

}  // namespace relpos
