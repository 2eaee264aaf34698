#include "relpos/contact.hpp"

#include <cfenv>
#include <cmath>
#include <stdexcept>

#include "algebra/filtered.hpp"
#include "algebra/rounding.hpp"
#include "algebra/smallness.hpp"
#include "contact/discriminant_case.hpp"
#include "decide/decision.hpp"
#include "decide/stages.hpp"
#include "filters/running_bound.hpp"
#include "filters/semi_static_filter.hpp"
#include "filters/static_filter.hpp"
#include "relpos/error.hpp"
#include "relpos/scene.hpp"
#include "scene/certificates.hpp"

namespace relpos {

std::string to_string(DiscriminantCase c) {
  switch (c) {
    case DiscriminantCase::Undecided:
      return "undecided";
    case DiscriminantCase::NonRealPair:
      return "non-real-pair";
    case DiscriminantCase::TwoPositive:
      return "two-positive";
    case DiscriminantCase::AllNegative:
      return "all-negative";
  }
  return "?";
}

std::string decided_by(Stage s) { return detail::stage_row(s).decided_by; }

namespace {

std::optional<Verdict> verdict_of_case(DiscriminantCase c, int rho_vs_one) {
  // The case's root facts through classify's own table.
  std::optional<Verdict> v = detail::decide_from_root_facts(root_facts_of(c), rho_vs_one);
  if (v) v->stage = Stage::DiscriminantFilter;
  return v;
}

/// The 3 decided cases x 3 outcomes of rho, generated once from classify's table (verdict_of_case):
/// the hot path is a lookup, nothing is decided twice.
struct CaseTable {
  std::optional<Verdict> v[4][3];  // nullopt: not small, all negative (the gap test decides, math.md §8)
  CaseTable() {
    for (int c = 1; c < 4; ++c)
      for (int r = -1; r <= 1; ++r) v[c][r + 1] = verdict_of_case(static_cast<DiscriminantCase>(c), r);
  }
};

}  // namespace

std::optional<Verdict> verdict_from_discriminant_case(DiscriminantCase c, std::optional<int> rho_vs_one) {
  static const CaseTable table;
  if (c == DiscriminantCase::Undecided) return std::nullopt;
  if (discriminant_case_needs_rho(c) && !rho_vs_one) return std::nullopt;
  // TwoPositive is E before the table looks at smallness (any size), so any rho gives the same.
  return table.v[static_cast<int>(c)][(rho_vs_one ? *rho_vs_one : 1) + 1];
}

namespace {

using detail::rounding_to_nearest;

/// Plugged into the static filter: compute the smallness signs only when the case needs them.
bool needs_smallness(const QuarticSigns& q) { return discriminant_case_needs_rho(discriminant_case(q)); }

/// The contact-only answer of a verdict.
ContactAnswer finish(const Verdict& v) { return {contact_of(v.position), v.position, v.rule, v.stage}; }

}  // namespace

detail::DiscriminantVerdict detail::decide_by_discriminant(const Ellipsoid& e, const Paraboloid& p,
                                                           const SizeLimit& limit) {
  return detail::filtered<detail::Rounding::Nearest>(
      [&]() -> std::optional<DiscriminantVerdict> {
        if (!storage_of(e).filter_doubles() || !storage_of(p).filter_doubles()) return std::nullopt;
        const DecisionSigns d = static_filter_discriminant_signs_normalized(
            *storage_of(p).filter_doubles(), *storage_of(e).filter_doubles(), &needs_smallness);
        const DiscriminantCase c = discriminant_case(d.quartic);
        std::optional<int> rho;
        if (discriminant_case_needs_rho(c)) rho = compare_rho_with_one(d.vertex, d.graeffe);
        if (auto v = verdict_from_discriminant_case(c, rho))
          return DiscriminantVerdict{*v, c != DiscriminantCase::TwoPositive};
        return std::nullopt;
      },
      [&] {
        return DiscriminantVerdict{decide_position(e, p, limit), true};
      });
}

ContactAnswer contact(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit) {
  return finish(detail::decide_by_discriminant(e, p, limit).verdict);
}

ContactChecker::ContactChecker(const Paraboloid& p) : scene_(std::make_unique<Scene>(p)) {}
ContactChecker::~ContactChecker() = default;
ContactChecker::ContactChecker(ContactChecker&&) noexcept = default;
ContactChecker& ContactChecker::operator=(ContactChecker&&) noexcept = default;
const Paraboloid& ContactChecker::paraboloid() const { return scene_->paraboloid(); }

ContactAnswer ContactChecker::contact(const Ellipsoid& e) const {
  if (const auto s = scene_->early_out(e)) {
    // Inside (I) or outside (E): no common point in either case.
    return ContactAnswer{Contact::None, s->position, s->rule, s->stage};
  }
  return finish(detail::decide_by_discriminant(e, scene_->paraboloid()).verdict);
}

// ------------------------------------------------------------------------------------------------
// ExteriorTracker
// ------------------------------------------------------------------------------------------------

namespace {

/// Relative slack of the smallness shortcut: the reference's rho must satisfy
/// rho (1 + kSlack) < 1 (small) or rho (1 - kSlack) > 1 (not small), checked exactly once; a frame
/// then only needs -det E certified within a factor (1 +- kSlack / 2) of the reference's.
constexpr double kSlack = 0x1p-20;

/// Indices of the 3x3 block M in a row-major 4x4 matrix (upper triangle).
constexpr std::size_t kBlock[6] = {0, 1, 2, 5, 6, 10};

/// -det E = e^T adj(M) e - e0 det M for a symmetric matrix given as 10 entries.
template <class NT>
NT minus_det(const SymmetricEntries<NT>& x) {
  const NT a00 = x.q11 * x.q22 - x.q12 * x.q12, a11 = x.q00 * x.q22 - x.q02 * x.q02,
           a22 = x.q00 * x.q11 - x.q01 * x.q01;
  const NT a01 = x.q02 * x.q12 - x.q01 * x.q22, a02 = x.q01 * x.q12 - x.q02 * x.q11,
           a12 = x.q01 * x.q02 - x.q00 * x.q12;
  const NT d = x.q00 * a00 + x.q01 * a01 + x.q02 * a02;
  const NT y0 = a00 * x.q0 + a01 * x.q1 + a02 * x.q2, y1 = a01 * x.q0 + a11 * x.q1 + a12 * x.q2,
           y2 = a02 * x.q0 + a12 * x.q1 + a22 * x.q2;
  return x.q0 * y0 + x.q1 * y1 + x.q2 * y2 - x.q33 * d;
}

}  // namespace

ExteriorTracker::ExteriorTracker(const Paraboloid& p, const Ellipsoid& body) : p_(p), body_(body) {
  m_ref_ = body.matrix();
  m_ref_doubles_ = body.doubles();
  // Smallness of the body, exactly, once (translation invariant: it depends on M, A, det P and
  // det E = -det M * k only).
  const Classification c = classify_exact(body, p, Evidence::Full);
  rho_vs_one_ = c.verdict.rho_vs_one;
  // The shortcut for later frames: rho is proportional to -det E when M is fixed (s and det P are
  // fixed), so a frame with the same M whose -det E is within a factor 1 +- kSlack of the
  // reference's is on the same side of 1 as long as rho_ref (1 +- kSlack) is. Checked exactly.
  if (rho_vs_one_ != 0) {
    Quartic<Rational> f = c.f;
    f[0] *= Rational(1) + Rational(rho_vs_one_ < 0 ? kSlack : -kSlack);
    const auto shifted = compare_rho_with_one<Rational>(f, c.s);
    ratio_ok_ = shifted && *shifted == rho_vs_one_;
  }
  const auto k = CGAL::to_interval(Rational(-c.f[0]));  // -det E > 0
  det_lo_ = k.first;
  det_hi_ = k.second;
}

std::optional<int> ExteriorTracker::frame_rho(const Ellipsoid& placed) {
  if (!ratio_ok_ || !rounding_to_nearest()) return std::nullopt;
  // Same shape block M (exactly)? Otherwise s, and with it rho's relation to det E, changed.
  const std::optional<DoubleMatrix4> d = placed.doubles();
  SymmetricEntries<RunningBound> x;
  if (d && m_ref_doubles_) {
    for (std::size_t i : kBlock)
      if ((*d)[i] != (*m_ref_doubles_)[i]) return std::nullopt;
    x = entries<RunningBound>([&](int i, int j) { return RunningBound((*d)[static_cast<std::size_t>(4 * i + j)]); });
  } else {
    for (std::size_t i : kBlock)
      if (placed.matrix().a[i] != m_ref_.a[i]) return std::nullopt;
    x = entries<RunningBound>([&](int i, int j) {
      const auto iv = CGAL::to_interval(placed.matrix()(i, j));
      return RunningBound::enclosing(iv.first, iv.second);
    });
  }
  const RunningBound k = minus_det(x);
  const double v = k.value(), b = k.error_bound();
  // The comparisons below are rounded, but the slack kSlack/2 dwarfs those few ulps.
  if (rho_vs_one_ < 0 && v + b <= det_lo_ * (1 + kSlack / 2)) return rho_vs_one_;  // -det E' <= (1+s) K_ref
  if (rho_vs_one_ > 0 && v - b >= det_hi_ * (1 - kSlack / 2)) return rho_vs_one_;  // -det E' >= (1-s) K_ref
  return std::nullopt;
}

ExteriorTracker::FrameVerdict ExteriorTracker::update(const Ellipsoid& placed) {
  ++counts_.frames;
  std::optional<Verdict> v;
  bool filter_tried = false;
  if (storage_of(placed).filter_doubles() && storage_of(p_).filter_doubles() && rounding_to_nearest()) {
    // f and Disc(f) only: smallness comes from the reference (frame_rho), never from the filter.
    const DecisionSigns d = static_filter_discriminant_signs_normalized(*storage_of(p_).filter_doubles(),
                                                                        *storage_of(placed).filter_doubles());
    const DiscriminantCase c = discriminant_case(d.quartic);
    filter_tried = c != DiscriminantCase::Undecided;
    std::optional<int> rho;
    if (discriminant_case_needs_rho(c)) {
      rho = frame_rho(placed);
      if (!rho) ++counts_.rho_recomputed;
    }
    v = verdict_from_discriminant_case(c, rho);
  }
  if (!v) {
    // The case was decided but rho was not: the one-shot path computes smallness in the filter.
    v = filter_tried ? detail::decide_by_discriminant(placed, p_).verdict : decide_position(placed, p_);
  }
  return finish(*v);
}

ExteriorTracker::FrameVerdict ExteriorTracker::finish(const Verdict& v) {
  ++(v.stage == Stage::DiscriminantFilter ? counts_.by_filter : counts_.by_fallback);
  FrameVerdict out;
  out.position = v.position;
  out.rule = v.rule;
  out.stage = v.stage;
  out.changed = last_ && *last_ != out.position;
  last_ = out.position;
  return out;
}

ExteriorTracker::FrameVerdict ExteriorTracker::update(const std::array<double, 3>& translation) {
  for (double x : translation)
    if (!std::isfinite(x)) throw InputError("tracker translation: not finite");
  return detail::filtered<detail::Rounding::Nearest>(
      [&]() -> std::optional<FrameVerdict> {
        // Every decision sign of the moved body, certified without forming it (exact-double bodies on
        // the SSE fast path, others on double enclosures); the discriminant case reads f and Disc(f),
        // and rho is the reference's exactly (same M, same det E).
        const DecisionSigns d =
            storage_of(body_).filter_doubles() && storage_of(p_).filter_doubles()
                ? semi_static_filter_signs_translated(*storage_of(p_).filter_doubles(),
                                                      *storage_of(body_).filter_doubles(), translation)
                : semi_static_filter_signs_translated(p_.matrix(), body_.matrix(), translation);
        const DiscriminantCase c = discriminant_case(d.quartic);
        const std::optional<Verdict> v = verdict_from_discriminant_case(c, rho_vs_one_);
        if (!v) return std::nullopt;
        ++counts_.frames;
        return finish(*v);
      },
      [&] {
        const Vector3 t{exact_rational(translation[0]), exact_rational(translation[1]), exact_rational(translation[2])};
        return update(body_.translated(t));
      });
}

}  // namespace relpos
