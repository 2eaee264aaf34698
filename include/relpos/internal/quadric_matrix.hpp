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

/// Builds the exact matrix of a quadric on first use (for a quadric read from text: the exact
/// parse of that text, run only when an exact stage or the evidence asks for the rationals).
class ExactSource {
 public:
  virtual ~ExactSource() = default;
  virtual Matrix4 build() const = 0;
};

/// The matrix of a validated quadric: exact rationals, and the doubles when every entry is one.
/// A quadric made from doubles (from_doubles) builds its rationals only on first use by an exact
/// stage (thread-safe: a quadric shared by several threads materializes once; copies share it);
/// so does one made from enclosures and an ExactSource.
class QuadricMatrix {
 public:
  explicit QuadricMatrix(Matrix4 m);
  /// Entries known by enclosures (not all lo == hi) and built exactly by `source` on first use.
  /// The caller proves the shape, the sign normalization and the size limit (within_size_limit()).
  QuadricMatrix(const EnclosureMatrix4& enclosure, std::shared_ptr<const ExactSource> source);
  /// From doubles that are all finite (checked by the caller); no heap allocation.
  explicit QuadricMatrix(const DoubleMatrix4& d);
  /// The same with d's power_of_two_normalized copy already computed (by the caller's filter).
  QuadricMatrix(const DoubleMatrix4& d, const std::optional<DoubleMatrix4>& normalized);
  QuadricMatrix(const QuadricMatrix& o)
      : d_(o.d_), n_(o.n_), enclosure_(o.enclosure_), source_(o.source_), m_(std::atomic_load(&o.m_)) {}
  /// Moves take the matrix without atomic operations: a quadric being moved is not shared (vectors
  /// of quadrics grow by moves, not by copies).
  QuadricMatrix(QuadricMatrix&& o) noexcept
      : d_(std::move(o.d_)),
        n_(std::move(o.n_)),
        enclosure_(std::move(o.enclosure_)),
        source_(std::move(o.source_)),
        m_(std::move(o.m_)) {}
  QuadricMatrix& operator=(QuadricMatrix&& o) noexcept {
    d_ = std::move(o.d_);
    n_ = std::move(o.n_);
    enclosure_ = std::move(o.enclosure_);
    source_ = std::move(o.source_);
    m_ = std::move(o.m_);
    return *this;
  }
  QuadricMatrix& operator=(const QuadricMatrix& o) {
    if (this != &o) {
      d_ = o.d_;
      n_ = o.n_;
      enclosure_ = o.enclosure_;
      source_ = o.source_;
      std::atomic_store(&m_, std::atomic_load(&o.m_));
    }
    return *this;
  }
  const Matrix4& matrix() const {
    const Matrix4* m = std::atomic_load(&m_).get();
    return m ? *m : materialize();
  }
  const std::optional<DoubleMatrix4>& doubles() const { return d_; }
  /// doubles(), power-of-two normalized once for the static filter (cached: a quadric is usually
  /// classified against many others).
  const std::optional<DoubleMatrix4>& filter_doubles() const { return n_; }
  /// Enclosures of the entries when the quadric was made from them (nullopt otherwise).
  const std::optional<EnclosureMatrix4>& enclosure() const { return enclosure_; }
  /// True when the primitive integer form is known to be within kMaxNormalizedBits without
  /// building it: doubles, or a source whose reader bounds its numbers.
  bool within_size_limit() const { return d_.has_value() || source_ != nullptr; }

 private:
  const Matrix4& materialize() const;
  std::optional<DoubleMatrix4> d_, n_;
  std::optional<EnclosureMatrix4> enclosure_;
  std::shared_ptr<const ExactSource> source_;
  mutable std::shared_ptr<const Matrix4> m_;
};

/// A quadric whose shape and sign normalization the caller has certified (src/io's fast reader).
Ellipsoid make_ellipsoid(QuadricMatrix m);
Paraboloid make_paraboloid(QuadricMatrix m);

}  // namespace detail

}  // namespace relpos
