// The fast reader of fast_quadric.hpp: the value read into a bounded tree of decimals and their
// enclosures (fast_value.hpp), the entries of the form in interval arithmetic (one rounding-mode
// switch per quadric), the shape certified by the interval filter, and the numbers kept as the
// quadric's recipe (algebra/decimal_recipe.hpp), from which the exact matrix is built on demand.
//
// Written by hand rather than with simdjson: the forms need the number *text* (exactness, exact
// symmetry), the nodes are few and the general reader stays the reference for every error; a full
// parser would add a second document model without removing the per-number work.
#include "io/fast_quadric.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <memory>

#include "algebra/decimal_recipe.hpp"
#include "algebra/shape_filter.hpp"
#include "io/fast_value.hpp"

namespace relpos::detail::io {
namespace {

using I = FastInterval;
using Entries = std::array<I, 16>;
using relpos::detail::DecimalRecipe;
using Reader = FastValue;
using Number = FastNumber;

/// A 4x4 array of numbers that is exactly symmetric.
bool symmetric_matrix(const Reader& r, int array, std::array<Number, 16>& out) {
  if (array < 0 || r.node(array).kind != FastKind::Array || r.node(array).count != 4) return false;
  std::size_t row = 0;
  for (int k = r.node(array).child; k >= 0; k = r.node(k).next, ++row) {
    std::array<Number, 4> x;
    if (!r.numbers(k, x)) return false;
    for (std::size_t j = 0; j < 4; ++j) out[4 * row + j] = x[j];
  }
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      if (!out[4 * i + j].d.same(out[4 * j + i].d)) return false;
  return true;
}

bool positive(const Number& x) { return !x.d.neg && !x.d.is_zero(); }

/// The storage of a certified quadric: its doubles when every enclosure is a point (the exact
/// matrix is then those doubles), else the enclosures with the numbers as the recipe.
relpos::detail::QuadricMatrix storage(const Entries& x, const DecimalRecipe& recipe) {
  relpos::detail::EnclosureMatrix4 enc;
  bool points = true;
  for (std::size_t k = 0; k < 16; ++k) {
    const I v = recipe.orientation > 0 ? x[k] : -x[k];
    enc.lo[k] = v.inf();
    enc.hi[k] = v.sup();
    points = points && v.inf() == v.sup();
  }
  if (points) return relpos::detail::QuadricMatrix(enc.lo);
  return relpos::detail::QuadricMatrix(enc, std::make_shared<const DecimalRecipe>(recipe));
}

/// The enclosures and identities of 16 numbers into x and the recipe.
void take_matrix(const std::array<Number, 16>& n, Entries& x, DecimalRecipe& recipe) {
  for (std::size_t k = 0; k < 16; ++k) {
    x[k] = n[k].x;
    recipe.n[k] = n[k].d;
  }
}

/// The entries the shape test reads, or null when this reader does not take the matrix. Short
/// numbers: x itself. A matrix with wide numbers (one scaled by a power of ten, fast_value.hpp) is
/// taken when its non-zero numbers' exponents span at most 2 kMaxExponent, so that its primitive
/// integer form is one of a matrix of short numbers (the size bound of fast_quadric.hpp), and each
/// enclosure lies within [2^-1020, 2^1020] in magnitude (the range the filters scale exactly,
/// semi_static_filter.cpp); its shape is then read on x scaled by the power of two that brings the
/// largest bound below 1 (exact: the scaled bounds stay normal; a positive factor changes no sign,
/// doc/math.md §1).
const Entries* shape_entries(const Reader& r, const std::array<Number, 16>& n, const Entries& x, Entries& scaled) {
  if (!r.any_wide()) return &x;
  int low = INT_MAX, high = INT_MIN;
  double mx = 0;
  for (std::size_t k = 0; k < 16; ++k) {
    if (n[k].d.is_zero()) continue;
    low = std::min(low, n[k].d.e);
    high = std::max(high, n[k].d.e);
    mx = std::max({mx, std::fabs(x[k].inf()), std::fabs(x[k].sup())});
  }
  if (high < low || high - low > 2 * Reader::kMaxExponent) return nullptr;
  for (std::size_t k = 0; k < 16; ++k)
    if (!n[k].d.is_zero() && !(std::min(std::fabs(x[k].inf()), std::fabs(x[k].sup())) >= 0x1p-1020 && mx <= 0x1p1020))
      return nullptr;
  const I scale(std::ldexp(1.0, -std::ilogb(mx) - 1));
  for (std::size_t k = 0; k < 16; ++k) scaled[k] = x[k] * scale;
  return &scaled;
}

/// The matrix of a 4x4 array or {"matrix": 4x4}, or -1.
int matrix_node(const Reader& r, int root) {
  if (r.node(root).kind == FastKind::Array) return root;
  if (r.node(root).kind == FastKind::Object && r.node(root).count == 1) return r.member(root, "matrix");
  return -1;
}

/// {"sphere": {"center" | "centre": [x, y, z], "radius": r}}: Ellipsoid::sphere, valid when r > 0.
int sphere_entries(const Reader& r, int root, Entries& x, DecimalRecipe& recipe) {
  if (r.node(root).kind != FastKind::Object || r.node(root).count != 1) return 0;
  const int sphere = r.member(root, "sphere");
  if (sphere < 0 || r.node(sphere).kind != FastKind::Object || r.node(sphere).count != 2) return 0;
  const int centre = r.member(sphere, "center") >= 0 ? r.member(sphere, "center") : r.member(sphere, "centre");
  const int radius = r.member(sphere, "radius");
  std::array<Number, 3> c;
  if (radius < 0 || r.node(radius).kind != FastKind::Number || !r.numbers(centre, c)) return 0;
  const Number& rad = r.node(radius).number;
  // The size bound: no wide number (the tree holds these four numbers and no other, by the counts).
  if (!positive(rad) || r.any_wide()) return 0;
  recipe.form = DecimalRecipe::Form::Sphere;
  recipe.n = {c[0].d, c[1].d, c[2].d, rad.d};
  x.fill(I(0));
  x[0] = x[5] = x[10] = I(1);
  for (std::size_t i = 0; i < 3; ++i) x[4 * i + 3] = x[12 + i] = -c[i].x;
  x[15] = CGAL::square(c[0].x) + CGAL::square(c[1].x) + CGAL::square(c[2].x) - CGAL::square(rad.x);
  return 1;
}

/// The entries of an ellipsoid's matrix (node m), in interval arithmetic, and its orientation (the
/// sign that makes Q3 positive definite); 0 when this reader does not take it. Rounding towards
/// +inf (the caller's guard).
int ellipsoid_matrix_entries(const Reader& r, int m, Entries& x, DecimalRecipe& recipe) {
  std::array<Number, 16> n;
  if (!symmetric_matrix(r, m, n) || n[0].d.is_zero()) return 0;
  const int want = n[0].d.neg ? -1 : 1;
  take_matrix(n, x, recipe);
  Entries scaled;
  const Entries* shape = shape_entries(r, n, x, scaled);
  return shape && shape_filter::certified_ellipsoid_intervals(*shape, want) == want ? want : 0;
}

/// The same for the ellipsoid of the text: a matrix or a sphere.
int ellipsoid_entries(const Reader& r, int root, Entries& x, DecimalRecipe& recipe) {
  const int m = matrix_node(r, root);
  return m < 0 ? sphere_entries(r, root, x, recipe) : ellipsoid_matrix_entries(r, m, x, recipe);
}

/// {"vertex": [x, y, z], "a": a, "b": b}: Paraboloid::standard without rotation, valid when a, b > 0.
int standard_entries(const Reader& r, int root, Entries& x, DecimalRecipe& recipe) {
  if (r.node(root).kind != FastKind::Object || r.node(root).count != 3) return 0;
  const int a = r.member(root, "a"), b = r.member(root, "b");
  std::array<Number, 3> v;
  if (a < 0 || b < 0 || r.node(a).kind != FastKind::Number || r.node(b).kind != FastKind::Number ||
      !r.numbers(r.member(root, "vertex"), v))
    return 0;
  const Number &na = r.node(a).number, &nb = r.node(b).number;
  // The size bound: no wide number (the tree holds these five numbers and no other, by the counts).
  if (!positive(na) || !positive(nb) || r.any_wide()) return 0;
  recipe.form = DecimalRecipe::Form::Standard;
  recipe.n = {v[0].d, v[1].d, v[2].d, na.d, nb.d};
  const I ia = I(1) / CGAL::square(na.x), ib = I(1) / CGAL::square(nb.x);
  x.fill(I(0));
  x[0] = ia;
  x[5] = ib;
  x[3] = x[12] = -ia * v[0].x;
  x[7] = x[13] = -ib * v[1].x;
  x[11] = x[14] = I(-0.5);
  x[15] = ia * CGAL::square(v[0].x) + ib * CGAL::square(v[1].x) + v[2].x;
  return 1;
}

/// The same for an elliptic paraboloid's matrix (the orientation makes Q3 positive semidefinite).
int paraboloid_matrix_entries(const Reader& r, int m, Entries& x, DecimalRecipe& recipe) {
  std::array<Number, 16> n;
  if (!symmetric_matrix(r, m, n)) return 0;
  // det Q3 = 0 exactly, from entries that are exactly zero (axis-aligned cups); else the general reader.
  if (!shape_filter::impl::zero_by_pattern(n[0].d.is_zero(), n[1].d.is_zero(), n[2].d.is_zero(), n[5].d.is_zero(),
                                           n[6].d.is_zero(), n[10].d.is_zero()))
    return 0;
  take_matrix(n, x, recipe);
  Entries scaled;
  const Entries* shape = shape_entries(r, n, x, scaled);
  return shape ? shape_filter::certified_paraboloid_intervals(*shape) : 0;
}

/// The same for the elliptic paraboloid of the text: a matrix or the standard form.
int paraboloid_entries(const Reader& r, int root, Entries& x, DecimalRecipe& recipe) {
  const int m = matrix_node(r, root);
  return m < 0 ? standard_entries(r, root, x, recipe) : paraboloid_matrix_entries(r, m, x, recipe);
}

/// The quadric of the text into `out` (made there: a quadric is a few hundred bytes), or false and
/// `out` empty: `entries` is ellipsoid_entries or paraboloid_entries, `make` the matching
/// make_ellipsoid or make_paraboloid. With `end`, the text starts with the value (fast_ellipsoid_at).
template <class Q, class Entries_of, class Make>
bool read_quadric(std::string_view text, bool doubles, std::size_t* end, Entries_of entries, Make make,
                  std::optional<Q>& out) {
  Entries x;
  DecimalRecipe recipe;
  recipe.doubles = doubles;
  recipe.orientation = 0;
  Reader r(text, doubles);
  const int root = end ? r.parse_prefix() : r.parse();
  if (end) *end = root >= 0 ? r.end() : std::string_view::npos;
  if (root >= 0) {
    CGAL::Protect_FPU_rounding<true> guard;  // Interval_nt<false>: rounding towards +inf
    r.enclose_decimals();
    recipe.orientation = entries(r, root, x, recipe);
  }
  if (recipe.orientation == 0) {
    out.reset();
    return false;
  }
  out.emplace(make(storage(x, recipe)));
  return true;
}

}  // namespace

bool fast_quadric_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Quadric>& out) {
  Entries x;
  DecimalRecipe recipe;
  recipe.doubles = doubles;
  recipe.orientation = 0;
  bool ellipsoid = true;
  Reader r(text, doubles);
  const int root = r.parse_prefix();
  end = root >= 0 ? r.end() : std::string_view::npos;
  const int m = root >= 0 ? matrix_node(r, root) : -1;
  if (m >= 0) {
    CGAL::Protect_FPU_rounding<true> guard;  // Interval_nt<false>: rounding towards +inf
    r.enclose_decimals();
    recipe.orientation = ellipsoid_matrix_entries(r, m, x, recipe);
    if (recipe.orientation == 0) {
      ellipsoid = false;
      recipe.orientation = paraboloid_matrix_entries(r, m, x, recipe);
    }
  }
  if (recipe.orientation == 0) {
    out.reset();
    return false;
  }
  // Quadric::of keeps the storage: the general reader's Quadric::from_matrix gives the same exact
  // matrix (the orientation of Q3 definite or semidefinite, math.md §14) and the same type.
  if (ellipsoid)
    out.emplace(Quadric::of(relpos::detail::make_ellipsoid(storage(x, recipe))));
  else
    out.emplace(Quadric::of(relpos::detail::make_paraboloid(storage(x, recipe))));
  return true;
}

std::optional<Ellipsoid> fast_ellipsoid(std::string_view text, bool doubles) {
  std::optional<Ellipsoid> e;
  read_quadric(text, doubles, nullptr, ellipsoid_entries, relpos::detail::make_ellipsoid, e);
  return e;
}

std::optional<Paraboloid> fast_paraboloid(std::string_view text, bool doubles) {
  std::optional<Paraboloid> p;
  read_quadric(text, doubles, nullptr, paraboloid_entries, relpos::detail::make_paraboloid, p);
  return p;
}

bool fast_ellipsoid_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Ellipsoid>& out) {
  return read_quadric(text, doubles, &end, ellipsoid_entries, relpos::detail::make_ellipsoid, out);
}

bool fast_paraboloid_at(std::string_view text, bool doubles, std::size_t& end, std::optional<Paraboloid>& out) {
  return read_quadric(text, doubles, &end, paraboloid_entries, relpos::detail::make_paraboloid, out);
}

}  // namespace relpos::detail::io
