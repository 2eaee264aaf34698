// The certificate of C (math.md §8): two rational points of the solid ellipsoid, one with p < 0
// and one with p > 0. Candidates come from the double search along the curve of stationary points
// (double_search.cpp), in the body's own frame when doubles cannot resolve it, and otherwise from the
// exact search (secular_search.cpp); each is checked exactly, its signs filtered by intervals first
// (algebra/filtered.hpp).
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "algebra/centre.hpp"
#include "algebra/filtered.hpp"
#include "algebra/forms.hpp"
#include "certificate/double_search.hpp"
#include "certificate/kinds.hpp"
#include "certificate/rational_search.hpp"
#include "certificate/secular_search.hpp"

namespace relpos::detail::certificate {
namespace {

using detail::EnclosureMatrix4;
using detail::PointForm;

/// Whether the body is below 2^-20 of its distance to the origin (or its size is not a finite
/// double): then doubles around its centre cannot resolve it, and the search runs in its frame.
bool small_for_doubles(const DoubleMatrix4& em, const double c[3]) {
  auto e = [&](int i, int j) { return em[static_cast<std::size_t>(4 * i + j)]; };
  double least = HUGE_VAL, far = 0, r2 = e(3, 3);
  for (int i = 0; i < 3; ++i) {
    r2 += 2 * e(i, 3) * c[i];
    for (int j = 0; j < 3; ++j) r2 += c[i] * e(i, j) * c[j];
    least = std::min(least, e(i, i));
    far = std::max(far, std::fabs(c[i]));
  }
  const double size = std::sqrt(-r2 / least);  // -e(c) = r2 up to rounding
  return !(std::isfinite(size) && size > 0x1p-20 * far);
}

/// Q in the frame x = c + s u: H^T Q H for H = [[s I, c], [0, 1]], as doubles (CGAL::to_double).
DoubleMatrix4 in_frame(const Matrix4& q, const V3& c, const Rational& s) {
  Matrix4 out;
  std::array<Rational, 3> g;  // Q's block times c plus its last column: half the gradient at c
  for (int i = 0; i < 3; ++i) {
    g[i] = q(i, 3);
    for (int j = 0; j < 3; ++j) g[i] += q(i, j) * c[j];
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out(i, j) = s * s * q(i, j);
    out(i, 3) = out(3, i) = s * g[i];
  }
  out(3, 3) = form(q, c);
  DoubleMatrix4 d;
  for (std::size_t i = 0; i < 16; ++i) d[i] = forms::truncated_double(out.a[i]);
  return d;
}

/// A power of two near the body's largest semi-axis, sqrt(-e(c) / min_i M_ii) (bit lengths only).
Rational body_scale(const Matrix4& e, const Rational& e_at_centre) {
  long least = 0;
  for (int i = 0; i < 3; ++i) least = i == 0 ? log2_of(e(0, 0)) : std::min(least, log2_of(e(i, i)));
  return power_of_two((log2_of(-e_at_centre) - least) / 2);
}

/// sign(X^T Q X), X = (x, 1), for every matrix Q within the entries' enclosures (exact doubles:
/// lo = hi) and x in the point's, when interval arithmetic decides it; empty when it does not (an
/// enclosure containing 0, overflow or NaN). Rounding towards +inf (filtered.hpp sets it).
std::optional<int> interval_sign(const EnclosureMatrix4& q, const Enclosure3& x) {
  using I = CGAL::Interval_nt<false>;
  auto entry = [&q](std::size_t k) { return I(q.lo[k], q.hi[k]); };
  I acc = entry(15);
  for (std::size_t i = 0; i < 3; ++i) {
    I row = entry(4 * i + 3) * 2;  // off-diagonal entries appear twice
    for (std::size_t j = 0; j < 3; ++j) row += entry(4 * i + j) * I(x[j]);
    acc += row * I(x[i]);
  }
  if (acc.inf() > 0) return 1;
  if (acc.sup() < 0) return -1;
  return std::nullopt;
}

/// The entries a quadric's interval signs read: its exact doubles, else the enclosures the reader
/// of decimal text stored; nullopt for other entries (then every sign is exact).
std::optional<EnclosureMatrix4> entries_of(const std::optional<DoubleMatrix4>& own, const EnclosureMatrix4* stored) {
  if (own) return EnclosureMatrix4{*own, *own};
  return stored ? std::optional<EnclosureMatrix4>(*stored) : std::nullopt;
}

/// The two points being searched, and the exact check of each candidate.
class Crossing {
 public:
  explicit Crossing(const PairContext& pr)
      : pr_(pr),
        e_entries_(entries_of(pr.ellipsoid().doubles(), pr.e_storage().enclosure())),
        p_entries_(entries_of(pr.paraboloid().doubles(), pr.p_storage().enclosure())) {}

  /// A candidate: kept as `inside` (p < 0) or `outside` (p > 0) when it is in the solid ellipsoid
  /// and the slot is empty. `known`: the point's enclosure when the caller has it, else null.
  void consider_at(const V3& x, const std::optional<Enclosure3>* known) {
    const std::optional<Enclosure3> at = !(e_entries_ && p_entries_) ? std::nullopt : known ? *known : enclosure(x);
    std::optional<PointForm::Point> xz;  // the exact point, built once for whichever sign needs it
    auto exact = [&](const PointForm& form) {
      if (!xz) xz.emplace(x);
      return form.sign(*xz);
    };
    if (sign(e_entries_, at, [&] { return exact(pr_.e_point_form()); }) > 0) return;
    const int sp = sign(p_entries_, at, [&] { return exact(pr_.p_point_form()); });
    if (sp < 0 && !inside) inside = x;
    if (sp > 0 && !outside) outside = x;
  }
  void consider(const V3& x) { consider_at(x, nullptr); }

  /// The double search from a dyadic centre, or in the body's frame.
  void search_in_doubles();
  /// What the double search missed, from the exact optimisers (they always exist in a crossing).
  void search_exactly();

  std::optional<V3> inside, outside;

 private:
  /// The sign of a form at a candidate: intervals on the entries first, else exact.
  template <class Exact>
  static int sign(const std::optional<EnclosureMatrix4>& q, const std::optional<Enclosure3>& at, const Exact& exact) {
    if (!q || !at) return exact();
    return detail::filtered<detail::Rounding::Upward>([&] { return interval_sign(*q, *at); }, exact);
  }
  const PairContext& pr_;
  const std::optional<EnclosureMatrix4> e_entries_, p_entries_;
  DoubleBracket brackets_[2];
};

// Candidates are pulled towards a dyadic centre (short exact arithmetic): the centre solved in
// doubles, taken exactly, when it is strictly inside the solid (almost always); else the exact
// centre (Cramer's rule on integers, several times dearer).
void Crossing::search_in_doubles() {
  const Consider consider_here = [this](const V3& x, const std::optional<Enclosure3>* known) { consider_at(x, known); };
  const DoubleMatrix4 ed = pr_.e_search_doubles();
  double pull_doubles[3];
  const std::optional<V3> pull = approximate_centre(ed, pull_doubles);
  const std::optional<Enclosure3> pull_at = pull ? std::optional<Enclosure3>(enclosure(pull_doubles)) : std::nullopt;
  auto pull_e_sign = [&] {
    return sign(e_entries_, pull_at, [&] { return pr_.e_point_form().sign(PointForm::Point(*pull)); });
  };
  if (pull && pull_e_sign() < 0 && !small_for_doubles(ed, pull_doubles)) {
    consider_at(*pull, &pull_at);
    double_curve_search(ed, pr_.p_search_doubles(), pr_.lambda_s(), *pull, inside, outside, consider_here, brackets_);
  } else if (const std::optional<V3> ctr = detail::centre_of(pr_.ellipsoid().matrix())) {
    // A body too small or too far for doubles: the same search in the body's frame x = c + 2^k u
    // (an exact congruence; lambda and lambda_s unchanged), the body of unit size at the origin;
    // the points found are mapped back exactly.
    const V3& at = *ctr;
    consider(at);
    const Rational scale = body_scale(pr_.ellipsoid().matrix(), e_at(pr_, at));
    const Consider mapped = [&](const V3& u, const std::optional<Enclosure3>*) {  // u's enclosure is not x's
      V3 x;
      for (int i = 0; i < 3; ++i) x[i] = at[i] + scale * u[i];
      consider(x);
    };
    double_curve_search(in_frame(pr_.ellipsoid().matrix(), at, scale), in_frame(pr_.paraboloid().matrix(), at, scale),
                        pr_.lambda_s(), V3{}, inside, outside, mapped, brackets_);
  }
}

void Crossing::search_exactly() {
  if (inside && outside) return;
  const Secular sec(pr_);
  const ConsiderExact consider_fn = [this](const V3& x) { consider(x); };
  if (!inside && !refine_from_doubles(pr_, sec, brackets_[0], -1, inside, consider_fn))
    min_side_point(pr_, sec, inside, consider_fn);
  if (!outside && !refine_from_doubles(pr_, sec, brackets_[1], 1, outside, consider_fn))
    max_side_point(pr_, sec, outside, consider_fn);
}

}  // namespace

void crossing_points(const PairContext& pr, Certificate& c) {
  Crossing search(pr);
  search.search_in_doubles();
  search.search_exactly();
  if (!search.inside || !search.outside)
    throw internal_error(std::string("no point of the solid ellipsoid with p ") + (search.inside ? "> 0" : "< 0") +
                         " for a pair classified C");
  c.kind = Certificate::Kind::Crossing;
  c.inside = *search.inside;
  c.outside = *search.outside;
}

}  // namespace relpos::detail::certificate
