// The storage of a validated quadric's matrix (internal: not part of the public API; quadric.hpp
// includes it because Ellipsoid and Paraboloid hold one by value). Library code reaches it through
// storage_of(quadric).
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <optional>

namespace relpos {

struct Matrix4;
using DoubleMatrix4 = std::array<double, 16>;
class Ellipsoid;
class Paraboloid;

namespace detail {

/// Certified double enclosures lo[i] <= entry i <= hi[i] of a matrix (row-major) whose entries are
/// not all doubles: the filters' input for a quadric read from decimal text.
struct EnclosureMatrix4 {
  DoubleMatrix4 lo{}, hi{};
};

/// d scaled by the power of two that brings its largest entry into [1/2, 1) (what
/// power_of_two_normalized returns), written to `out`, with the exponent that gives it back:
/// d = out * 2^exponent, exactly; `plain` when that is one multiplication per entry (2^exponent
/// normal, no entry of d subnormal). False (out unspecified) when an entry would become subnormal,
/// or d is zero or not finite.
bool normalize_doubles(const DoubleMatrix4& d, DoubleMatrix4& out, int& exponent, bool& plain);

/// What a quadric read from text was made of (its form and numbers): defined in src/algebra, opaque
/// here. The exact matrix is built from it on first use.
struct DecimalRecipe;

/// The matrix of a validated quadric: exact rationals, and the doubles when every entry is one.
/// A quadric made from doubles (from_doubles) builds its rationals only on first use by an exact
/// stage (thread-safe: a quadric shared by several threads materializes once; copies share it);
/// so does one made from enclosures and a recipe.
///
/// Compact on purpose (168 bytes): the hot loop of decide_position reads only the 16 normalized
/// doubles at the start of the object, so the doubles are stored once, normalized, with the power
/// of two that gives them back exactly; enclosures and the recipe of a quadric read from text live
/// out of line.
class QuadricMatrix {
 public:
  explicit QuadricMatrix(Matrix4 m);
  /// Entries known by enclosures (not all lo == hi) and built exactly from `recipe` on first use.
  /// The caller proves the shape, the sign normalization and the size limit (within_size_limit()).
  QuadricMatrix(const EnclosureMatrix4& enclosure, std::shared_ptr<const DecimalRecipe> recipe);
  /// From doubles; no heap allocation. Normalized (filter_doubles()) only when they are symmetric and
  /// finite: the shape tests of the callers read them.
  explicit QuadricMatrix(const DoubleMatrix4& d);
  /// -Q for a quadric made from doubles whose exact matrix is not built yet (a matrix given with
  /// the other orientation, found by the caller's shape test).
  void negate_doubles();
  QuadricMatrix(const QuadricMatrix& o)
      : v_(o.v_), exponent_(o.exponent_), flags_(o.flags_), cold_(o.cold_), m_(std::atomic_load(&o.m_)) {}
  /// Moves take the matrix without atomic operations: a quadric being moved is not shared (vectors
  /// of quadrics grow by moves, not by copies).
  QuadricMatrix(QuadricMatrix&& o) noexcept
      : v_(o.v_), exponent_(o.exponent_), flags_(o.flags_), cold_(std::move(o.cold_)), m_(std::move(o.m_)) {}
  QuadricMatrix& operator=(QuadricMatrix&& o) noexcept {
    v_ = o.v_;
    exponent_ = o.exponent_;
    flags_ = o.flags_;
    cold_ = std::move(o.cold_);
    m_ = std::move(o.m_);
    return *this;
  }
  QuadricMatrix& operator=(const QuadricMatrix& o) {
    if (this != &o) {
      v_ = o.v_;
      exponent_ = o.exponent_;
      flags_ = o.flags_;
      cold_ = o.cold_;
      std::atomic_store(&m_, std::atomic_load(&o.m_));
    }
    return *this;
  }
  const Matrix4& matrix() const {
    const Matrix4* m = std::atomic_load(&m_).get();
    return m ? *m : materialize();
  }
  /// Whether every entry is exactly a double.
  bool has_doubles() const { return (flags_ & kDoubles) != 0; }
  /// The entries as doubles (nullopt unless has_doubles()), given back exactly from the stored form.
  std::optional<DoubleMatrix4> doubles() const;
  /// The doubles, power-of-two normalized once for the static filter (power_of_two_normalized);
  /// null when there are none, they are not symmetric (no quadric: its shape test rejects it) or
  /// they cannot be normalized without losing bits.
  const DoubleMatrix4* filter_doubles() const { return (flags_ & kNormalized) ? &v_ : nullptr; }
  /// Enclosures of the entries when the quadric was made from them (null otherwise).
  const EnclosureMatrix4* enclosure() const { return cold_ ? &cold_->enclosure : nullptr; }
  /// The recipe of a quadric made from enclosures (null otherwise).
  const DecimalRecipe* recipe() const { return cold_ ? cold_->recipe.get() : nullptr; }
  /// True when the primitive integer form is known to be within kMaxNormalizedBits without
  /// building it: doubles, or a recipe whose reader bounds its numbers.
  bool within_size_limit() const { return has_doubles() || cold_ != nullptr; }

 private:
  static constexpr unsigned char kDoubles = 1, kNormalized = 2, kPlainScale = 4;
  /// What a quadric read from text keeps besides its enclosures' use in the filters.
  struct Cold {
    EnclosureMatrix4 enclosure;
    std::shared_ptr<const DecimalRecipe> recipe;
  };
  const Matrix4& materialize() const;
  /// kNormalized: the normalized doubles, and the doubles are v_ * 2^exponent_; kDoubles alone: the
  /// doubles themselves (exponent_ 0); neither: zeros. Not zero-initialised by the constructor from
  /// doubles, which writes every entry (a rep stos costs as much as the normalization).
  DoubleMatrix4 v_;
  int exponent_ = 0;
  unsigned char flags_ = 0;
  std::shared_ptr<const Cold> cold_;
  mutable std::shared_ptr<const Matrix4> m_;
};

/// The library's access to a quadric's construction and storage (quadric.hpp).
struct QuadricAccess;

/// A quadric whose shape and sign normalization the caller has certified (src/io's fast reader).
Ellipsoid make_ellipsoid(QuadricMatrix m);
Paraboloid make_paraboloid(QuadricMatrix m);

}  // namespace detail

}  // namespace relpos
