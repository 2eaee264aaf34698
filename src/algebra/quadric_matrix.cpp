// The storage of a quadric's matrix (internal/quadric_matrix.hpp) apart from its construction from
// doubles (quadric_doubles.cpp): the exact doubles of a rational matrix, the storage of a
// rational matrix or of an enclosure with its decimal recipe, the doubles given back, and the exact
// matrix built once, on first use.
#include <gmp.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>

#include "algebra/decimal_recipe.hpp"
#include "algebra/quadric_doubles.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

std::optional<DoubleMatrix4> detail::exact_doubles(const Matrix4& m) {
  DoubleMatrix4 d;
  for (std::size_t i = 0; i < 16; ++i) {
    // A double is n 2^j / 2^k in lowest terms with odd |n| < 2^53 (and in range): tested on the integers,
    // without building a rational from the double (an allocation per entry).
    const mpq_srcptr q = m.a[i].mpq();
    if (mpq_sgn(q) == 0) {
      d[i] = 0;
      continue;
    }
    const std::size_t den_bits = mpz_sizeinbase(mpq_denref(q), 2);
    const std::size_t significant = mpz_sizeinbase(mpq_numref(q), 2) - mpz_scan1(mpq_numref(q), 0);
    if (significant > 53 || mpz_scan1(mpq_denref(q), 0) != den_bits - 1) return std::nullopt;
    d[i] = mpq_get_d(q);  // exact when in range: a 53-bit integer over a power of two
    if (!std::isfinite(d[i]) || d[i] == 0) return std::nullopt;
    if (std::fabs(d[i]) < DBL_MIN && Rational(d[i]) != m.a[i]) return std::nullopt;  // subnormal: check
  }
  return d;
}

namespace detail {

QuadricMatrix::QuadricMatrix(Matrix4 m) : v_{} {
  if (const std::optional<DoubleMatrix4> d = exact_doubles(m)) *this = QuadricMatrix(*d);
  m_ = std::make_shared<const Matrix4>(std::move(m));
}

QuadricMatrix::QuadricMatrix(const EnclosureMatrix4& enclosure, std::shared_ptr<const DecimalRecipe> recipe)
    : v_{}, cold_(std::make_shared<const Cold>(Cold{enclosure, std::move(recipe)})) {}

std::optional<DoubleMatrix4> QuadricMatrix::doubles() const {
  if (!has_doubles()) return std::nullopt;
  if (!(flags_ & kNormalized)) return v_;
  DoubleMatrix4 d;
  if (flags_ & kPlainScale) {
    const std::uint64_t bits = static_cast<std::uint64_t>(exponent_ + 1023) << 52;
    double scale;
    std::memcpy(&scale, &bits, sizeof scale);  // 2^exponent_
    for (std::size_t i = 0; i < 16; ++i) d[i] = v_[i] * scale;
  } else {
    for (std::size_t i = 0; i < 16; ++i) d[i] = std::ldexp(v_[i], exponent_);  // exact: d is representable
  }
  return d;
}

const Matrix4& QuadricMatrix::materialize() const {
  auto built = std::make_shared<Matrix4>();
  if (const std::optional<DoubleMatrix4> d = doubles()) {
    for (std::size_t i = 0; i < 16; ++i) built->a[i] = Rational((*d)[i]);  // finite: exact
  } else {
    *built = exact_matrix(*cold_->recipe);
  }
  std::shared_ptr<const Matrix4> expected;
  std::shared_ptr<const Matrix4> desired = std::move(built);
  // The first thread to finish publishes its matrix; the others use that one (same values).
  if (std::atomic_compare_exchange_strong(&m_, &expected, desired)) return *desired;
  return *expected;
}

Ellipsoid make_ellipsoid(QuadricMatrix m) { return Ellipsoid(std::move(m)); }
Paraboloid make_paraboloid(QuadricMatrix m) { return Paraboloid(std::move(m)); }

}  // namespace detail

}  // namespace relpos
