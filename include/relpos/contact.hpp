// Contact-only answers and a discriminant-only tracker (doc/contact.md).
//
// f(l) = det(l P + E) has f(0) = det E < 0 and f4 = det P < 0, and always at least two negative real
// roots (with multiplicity): l P + E has inertia (3, 1) at l = 0 and that of -P, (1, 3), as l -> -inf,
// and an eigenvalue changes sign only where det = 0. So f never has four non-real roots, and
//   Disc(f) < 0  <=>  two distinct (negative) real roots and one non-real pair,
//   Disc(f) > 0  <=>  four distinct real roots,
//   Disc(f) = 0  <=>  a multiple root.
// With all roots real, Descartes' rule is exact: #positive roots = V, the sign variations of
// (f4, f3, f2, f1, f0), and V is 0 or 2 because f4, f0 < 0. Hence, from sign(Disc(f)) and the signs
// of f1, f2, f3 alone -- no Sturm-Habicht sequence:
//   Disc < 0         -> f square-free with a non-real pair: C when small, "the surfaces cross" for any size;
//   Disc > 0, V = 2  -> two distinct positive roots: E for any size;
//   Disc > 0, V = 0  -> four distinct negative roots: I when small (not small: the gap test of math.md §8);
//   Disc = 0         -> undecided here; the full classifier decide_position() answers.
// The table applied is classify's own, so every answer is decide_position's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "relpos/classify.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

class Scene;

// ------------------------------------------------------------------------------------------------
// One-shot discriminant decision with exact fallback.
// ------------------------------------------------------------------------------------------------

/// The "decided_by" text of a contact-only answer (doc/contact.md), by the part of the path its stage
/// belongs to: "scene-certificate" (an early-out of ContactChecker), "discriminant-filter"
/// (Stage::DiscriminantFilter) or "full-classifier" (a stage of decide_position()).
std::string decided_by(Stage s);

// ------------------------------------------------------------------------------------------------
// Contact only: do the two surfaces meet?
// ------------------------------------------------------------------------------------------------

struct ContactAnswer {
  Contact contact = Contact::None;
  Position position = Position::C;  ///< classify's position
  Rule rule = Rule::None;           ///< classify's rule
  /// What settled it: a scene early-out (ContactChecker), Stage::DiscriminantFilter or a stage of decide_position().
  Stage stage = Stage::StaticDouble;
};

/// Contact of the two surfaces: the discriminant test, then decide_position(), then (for an answer
/// that is not decided because the body is not small) the exact inside certificate.
ContactAnswer contact(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit = {});

/// The same with the paraboloid prepared once: Scene::early_out first (the cheapest certificate),
/// then as contact(). Thread-safe (const).
class ContactChecker {
 public:
  explicit ContactChecker(const Paraboloid& p);
  ~ContactChecker();
  ContactChecker(ContactChecker&&) noexcept;
  ContactChecker& operator=(ContactChecker&&) noexcept;
  ContactAnswer contact(const Ellipsoid& e) const;
  const Paraboloid& paraboloid() const;

 private:
  std::unique_ptr<Scene> scene_;
};

// ------------------------------------------------------------------------------------------------
// The paper's tracker, certified: one paraboloid, a body moving by translation.
// ------------------------------------------------------------------------------------------------

/// The paper (section 2) tracks a body coming from the exterior by the sign of Disc(f) alone
/// ("< 0: C, > 0: E, = 0: TE"). That is wrong twice: Disc > 0 also holds for I (a body that has gone
/// all the way in), and Disc = 0 also holds for C and E with a special double root -a^2 or -b^2
/// (math.md §3). This tracker reads sign(Disc(f)) and the signs of f1, f2, f3, takes the
/// smallness of the body from its reference placement (rho depends on M, A, det P and det E, and a
/// translation changes neither M nor det E = -det M * k, k the level), and falls back to
/// decide_position() when Disc(f) = 0 or a sign is uncertain. Every frame's answer is exactly
/// decide_position()'s on that frame.
///
/// The smallness shortcut is checked, not assumed: a frame whose 3x3 block differs from the
/// reference's, or whose det E cannot be certified to keep rho on the reference's side of 1 (a body
/// that changed size), gets its smallness computed afresh. Nothing is claimed between frames: a
/// body can enter and leave between two samples. For certified first contact over continuous time
/// use the motion module (relpos motion, include/relpos/motion.hpp).
class ExteriorTracker {
 public:
  /// body: the moving body in any placement (its shape; smallness is computed here, exactly, once).
  ExteriorTracker(const Paraboloid& p, const Ellipsoid& body);

  struct FrameVerdict {
    Position position = Position::C;
    Rule rule = Rule::None;
    bool changed = false;               ///< position differs from the previous frame's (false on the first)
    Stage stage = Stage::StaticDouble;  ///< Stage::DiscriminantFilter or a stage of decide_position()
  };
  /// The certified position of this frame (decide_position(placed, p)).
  FrameVerdict update(const Ellipsoid& placed);

  /// The reference body moved by `translation` (its centre moves by it; exact doubles): the same
  /// answer as update(body.translated(translation)), without constructing the moved ellipsoid. The
  /// moved entries are evaluated with their error carried along (semi_static_filter.hpp) and rho is
  /// the reference's, exactly (a translate has the same M and det E). Only when a sign is uncertain
  /// or Disc(f) = 0 is the moved ellipsoid built exactly (Ellipsoid::translated) and classified.
  FrameVerdict update(const std::array<double, 3>& translation);

  /// rho compared with 1 for the reference body, exactly.
  int rho_vs_one() const { return rho_vs_one_; }

  struct Counts {
    std::size_t frames = 0, by_filter = 0, by_fallback = 0;
    std::size_t rho_recomputed = 0;  ///< frames whose smallness could not be taken from the reference
  };
  const Counts& counts() const { return counts_; }

 private:
  std::optional<int> frame_rho(const Ellipsoid& placed);
  FrameVerdict finish(const Verdict& v);
  Paraboloid p_;
  Ellipsoid body_;  ///< the reference placement (update(translation) moves it)
  Matrix4 m_ref_;   ///< reference 3x3 block (in a 4x4 for convenience)
  std::optional<DoubleMatrix4> m_ref_doubles_;
  int rho_vs_one_ = 0;
  double det_lo_ = 0, det_hi_ = 0;  ///< enclosure of -det E of the reference (> 0)
  bool ratio_ok_ = false;           ///< rho_ref is farther than the slack from 1
  std::optional<Position> last_;
  Counts counts_;
};

}  // namespace relpos
