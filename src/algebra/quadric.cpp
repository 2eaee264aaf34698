#include "relpos/quadric.hpp"

#include <gmp.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include "algebra/double_bits.hpp"
#include "algebra/forms.hpp"
#include "algebra/shape_filter.hpp"
#include "relpos/error.hpp"

namespace relpos {
namespace {

int sgn(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

/// Determinant of the principal submatrix of q on the given index set (Laplace, n <= 4).
Rational principal_minor(const Matrix4& q, const int* idx, int n) {
  if (n == 0) return Rational(1);
  if (n == 1) return q(idx[0], idx[0]);
  Rational det(0);
  // expand along the first row of the submatrix
  for (int c = 0; c < n; ++c) {
    int rows[3], cols[3], k = 0;
    for (int j = 0; j < n; ++j)
      if (j != c) cols[k++] = idx[j];
    for (int i = 1; i < n; ++i) rows[i - 1] = idx[i];
    // minor on rows x cols (not principal in general): small explicit cases
    Rational m;
    if (n == 2) {
      m = q(rows[0], cols[0]);
    } else if (n == 3) {
      m = q(rows[0], cols[0]) * q(rows[1], cols[1]) - q(rows[0], cols[1]) * q(rows[1], cols[0]);
    } else {
      m = q(rows[0], cols[0]) *
              (q(rows[1], cols[1]) * q(rows[2], cols[2]) - q(rows[1], cols[2]) * q(rows[2], cols[1])) -
          q(rows[0], cols[1]) *
              (q(rows[1], cols[0]) * q(rows[2], cols[2]) - q(rows[1], cols[2]) * q(rows[2], cols[0])) +
          q(rows[0], cols[2]) * (q(rows[1], cols[0]) * q(rows[2], cols[1]) - q(rows[1], cols[1]) * q(rows[2], cols[0]));
    }
    Rational term = q(idx[0], idx[c]) * m;
    det += (c % 2 == 0) ? term : -term;
  }
  return det;
}

/// Inertia (positive, negative) of the leading n x n block of a symmetric matrix. The characteristic
/// polynomial of a real symmetric matrix has only real roots, so Descartes' rule of signs counts its
/// positive and negative roots exactly. det(xI - S) = sum_k (-1)^k E_k x^(n-k), E_k the sum of the
/// k x k principal minors.
std::pair<int, int> inertia(const Matrix4& q, int n) {
  std::array<Rational, 5> e{};  // E_0..E_n
  for (int mask = 0; mask < (1 << n); ++mask) {
    int idx[4], k = 0;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i)) idx[k++] = i;
    e[static_cast<std::size_t>(k)] += principal_minor(q, idx, k);
  }
  auto variations = [&](bool negate_x) {
    int count = 0, last = 0;
    for (int k = 0; k <= n; ++k) {
      // coefficient of x^(n-k): (-1)^k E_k; evaluated at -x it gains (-1)^(n-k)
      int s = sgn(e[static_cast<std::size_t>(k)]) * ((k % 2) ? -1 : 1);
      if (negate_x && ((n - k) % 2)) s = -s;
      if (s == 0) continue;
      if (last != 0 && s != last) ++count;
      last = s;
    }
    return count;
  };
  return {variations(false), variations(true)};
}

Rational det4(const Matrix4& q) {
  static const int all[4] = {0, 1, 2, 3};
  return principal_minor(q, all, 4);
}

Matrix4 negated(const Matrix4& q) {
  Matrix4 r;
  for (std::size_t i = 0; i < 16; ++i) r.a[i] = -q.a[i];
  return r;
}

void require_symmetric(const Matrix4& q) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (q(i, j) != q(j, i))
        throw InputError("matrix is not symmetric: entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) +
                         ") = " + to_string(q(i, j)) + " but entry (" + std::to_string(j + 1) + "," +
                         std::to_string(i + 1) + ") = " + to_string(q(j, i)));
}

Matrix3 inverse3(const Matrix3& m, const char* what) {
  Matrix3 c;  // cofactor transpose
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      c(i, j) = m(r0, c0) * m(r1, c1) - m(r0, c1) * m(r1, c0);
    }
  Rational det = m(0, 0) * c(0, 0) + m(0, 1) * c(1, 0) + m(0, 2) * c(2, 0);
  if (det == 0) throw InputError(std::string(what) + " is singular (determinant 0)");
  for (auto& x : c.a) x /= det;
  return c;
}

/// Q_world = H^-T Q_local H^-1 for the affine map x = L u + t (H = [[L, t], [0, 1]]).
Matrix4 push_forward(const Matrix4& local, const Matrix3& l, const Vector3& t, const char* what) {
  Matrix3 li = inverse3(l, what);
  Matrix4 hi;  // H^-1 = [[L^-1, -L^-1 t], [0, 1]]
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) hi(i, j) = li(i, j);
    hi(i, 3) = -(li(i, 0) * t[0] + li(i, 1) * t[1] + li(i, 2) * t[2]);
  }
  hi(3, 3) = Rational(1);
  Matrix4 tmp, out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k)
        if (!CGAL::is_zero(local(i, k)) && !CGAL::is_zero(hi(k, j))) s += local(i, k) * hi(k, j);
      tmp(i, j) = s;
    }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s(0);
      for (int k = 0; k < 4; ++k)
        if (!CGAL::is_zero(hi(k, i)) && !CGAL::is_zero(tmp(k, j))) s += hi(k, i) * tmp(k, j);
      out(i, j) = s;
    }
  return out;
}

Matrix3 check_orthogonal(const Matrix3& r) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational s(0);
      for (int k = 0; k < 3; ++k) s += r(k, i) * r(k, j);
      if (s != Rational(i == j ? 1 : 0))
        throw InputError(
            "rotation matrix is not exactly orthogonal (R^T R != I); give the rotation as a quaternion, "
            "which is exact for any rational components, or use the linear-map form");
    }
  return r;
}

template <std::size_t N>
std::array<Rational, N> exact_array(const std::array<double, N>& d) {
  std::array<Rational, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = exact_rational(d[i]);
  return out;
}

/// |c|^2 - r^2 with one reduction instead of a canonicalisation per operation: over the lcm L of
/// the denominators, (sum_i (c_i L)^2 - (r L)^2) / L^2, reduced along L's split (decimal text puts
/// only 2s and 5s there).
Rational squared_norm_minus(const Vector3& c, const Rational& r) {
  Integer l(1), num, t;  // fresh: written through mpz()
  forms::lcm_of_denominators(c.begin(), c.end(), l);
  forms::fold_lcm(l.mpz(), mpq_denref(r.mpq()));
  for (const Rational& x : c) {
    forms::scaled_numerator(x, l, t.mpz());
    mpz_addmul(num.mpz(), t.mpz(), t.mpz());
  }
  forms::scaled_numerator(r, l, t.mpz());
  mpz_submul(num.mpz(), t.mpz(), t.mpz());
  return forms::divided_by_power(num, forms::split_scale(l), 2);
}

std::string found(QuadricKind k) {
  std::string s = to_string(k);
  const char* article = (s[0] == 'a' || s[0] == 'e' || s[0] == 'i' || s[0] == 'o' || s[0] == 'u') ? "an " : "a ";
  return article + s;
}

}  // namespace

std::optional<DoubleMatrix4> exact_doubles(const Matrix4& m) {
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

namespace {

/// Two 64-bit lanes of bits and eight 16-bit lanes (GCC/Clang vector extension; SSE2 on x86-64).
typedef long long Bits2 __attribute__((vector_size(16)));
typedef short Words8 __attribute__((vector_size(16)));

Words8 words_max(Words8 a, Words8 b) { return a > b ? a : b; }  // pmaxsw
Words8 words_min(Words8 a, Words8 b) { return a < b ? a : b; }  // pminsw

// normalize_doubles, inlined into the constructor from doubles (which has just read the same
// entries for its symmetry test). Run for every quadric made from doubles, on the top 16 bits of
// each entry's bits (sign, exponent, 4 bits of the significand), eight entries at a time: the
// largest top word of the |entries| gives the largest exponent (0x7ff: an infinity or a NaN), and
// the smallest top word of |entry| - 1 (as integers, compared unsigned; zero wraps to the largest)
// the exponent of the smallest non-zero |entry|, or one less when that entry is a power of two
// (then the exact scalar code below decides). Only rare cases (an entry that would turn subnormal,
// a largest entry in the top binade) take that code.
[[gnu::always_inline]] inline bool normalize(const DoubleMatrix4& in, DoubleMatrix4& out, int& exponent, bool& plain) {
  const Bits2 magnitude = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL}, one = {1, 1};
  const Bits2 flip = {static_cast<long long>(0x8000800080008000ULL), static_cast<long long>(0x8000800080008000ULL)};
  Words8 top[8], low[8];  // |x|, and (|x| - 1) with its words' signs flipped (signed order = unsigned order)
  for (std::size_t k = 0; k < 8; ++k) {
    Bits2 x;
    std::memcpy(&x, &in[2 * k], sizeof x);
    const Bits2 a = x & magnitude;
    top[k] = reinterpret_cast<Words8>(a);
    low[k] = reinterpret_cast<Words8>((a - one) ^ flip);
  }
  // The two halves folded onto each other: the top word of the first entry is lane 3 on a
  // little-endian machine, lane 0 on a big-endian one (no branch).
  constexpr int kTop = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? 3 : 0;
  auto fold = [](Words8 w) { return __builtin_shufflevector(w, w, 4, 5, 6, 7, 0, 1, 2, 3); };
  Words8 hi = words_max(words_max(words_max(top[0], top[1]), words_max(top[2], top[3])),
                        words_max(words_max(top[4], top[5]), words_max(top[6], top[7])));
  Words8 lo = words_min(words_min(words_min(low[0], low[1]), words_min(low[2], low[3])),
                        words_min(words_min(low[4], low[5]), words_min(low[6], low[7])));
  hi = words_max(hi, fold(hi));
  lo = words_min(lo, fold(lo));
  const int top_exponent = hi[kTop] >> 4;                        // biased exponent of the largest |entry|
  if (top_exponent == 0 || top_exponent == 0x7ff) return false;  // zero or subnormal; infinity or NaN
  // Biased exponent of the smallest non-zero |entry| (or one less, see above): 0 when it is subnormal.
  const unsigned lo_word = static_cast<std::uint16_t>(lo[kTop]) ^ 0x8000u;
  const int lo_exponent = static_cast<int>(lo_word >> 4);
  const int emax = top_exponent - 1023;
  const int k = -emax - 1;
  exponent = emax + 1;
  // Common case: every non-zero entry normal, and the smallest stays normal once scaled by 2^k.
  if (lo_exponent >= 1 && lo_exponent - 1023 + k >= -1022 && k >= -1022) {
    const double s = power_of_two(k);
    const Lanes2 scale = {s, s};
    for (std::size_t i = 0; i < 8; ++i) {
      Lanes2 x;
      std::memcpy(&x, &in[2 * i], sizeof x);
      x = x * scale;  // exact
      std::memcpy(&out[2 * i], &x, sizeof x);
    }
    plain = exponent <= 1023;
    return true;
  }
  // 2^-(e+1) is below the normal range when e = 1023: then scale in two exact steps. No entry may
  // turn subnormal, and each must be kept exactly: scaling back must give it again (a product below
  // DBL_MIN may have been rounded, in any rounding mode even up to DBL_MIN itself; scaling back by
  // powers of two is exact).
  const bool two_steps = k < -1022;
  const double pre = two_steps ? 0x1p-512 : 1.0, scale = power_of_two(two_steps ? k + 512 : k);
  const double back_pre = two_steps ? 0x1p512 : 1.0, back_scale = power_of_two(two_steps ? -k - 512 : -k);
  bool lost = false, subnormal = false;
  for (std::size_t i = 0; i < 16; ++i) {
    out[i] = in[i] * pre * scale;
    lost = lost || (in[i] != 0 && std::fabs(out[i]) < DBL_MIN) || out[i] * back_scale * back_pre != in[i];
    subnormal = subnormal || (in[i] != 0 && std::fabs(in[i]) < DBL_MIN);
  }
  plain = !subnormal && exponent <= 1023;  // no entry subnormal, 2^exponent normal
  return !lost;
}

}  // namespace

bool normalize_doubles(const DoubleMatrix4& in, DoubleMatrix4& out, int& exponent, bool& plain) {
  return normalize(in, out, exponent, plain);
}

QuadricMatrix::QuadricMatrix(Matrix4 m) : v_{} {
  if (const std::optional<DoubleMatrix4> d = exact_doubles(m)) *this = QuadricMatrix(*d);
  m_ = std::make_shared<const Matrix4>(std::move(m));
}

QuadricMatrix::QuadricMatrix(const DoubleMatrix4& d) : flags_(kDoubles) {
  bool plain;
  // Not symmetric: no quadric (the shape tests, which read the normalized doubles, reject it).
  if (shape_filter::impl::symmetric(d) && normalize(d, v_, exponent_, plain)) {
    flags_ |= kNormalized | (plain ? kPlainScale : 0);
  } else {
    v_ = d;
    exponent_ = 0;
  }
}

void QuadricMatrix::negate_doubles() {
  for (double& x : v_) x = -x;
}

QuadricMatrix::QuadricMatrix(const EnclosureMatrix4& enclosure, std::shared_ptr<const ExactSource> source)
    : v_{}, cold_(std::make_shared<const Cold>(Cold{enclosure, std::move(source)})) {}

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
    *built = cold_->source->build();
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

std::string to_string(QuadricKind kind) {
  switch (kind) {
    case QuadricKind::Ellipsoid:
      return "ellipsoid";
    case QuadricKind::ImaginaryEllipsoid:
      return "imaginary ellipsoid (no real point)";
    case QuadricKind::Point:
      return "single point (degenerate ellipsoid, det = 0)";
    case QuadricKind::HyperboloidOneSheet:
      return "hyperboloid of one sheet";
    case QuadricKind::HyperboloidTwoSheets:
      return "hyperboloid of two sheets";
    case QuadricKind::Cone:
      return "cone";
    case QuadricKind::EllipticParaboloid:
      return "elliptic paraboloid";
    case QuadricKind::HyperbolicParaboloid:
      return "hyperbolic paraboloid";
    case QuadricKind::EllipticCylinder:
      return "elliptic cylinder";
    case QuadricKind::ImaginaryEllipticCylinder:
      return "imaginary elliptic cylinder (no real point)";
    case QuadricKind::Line:
      return "line (pair of imaginary planes)";
    case QuadricKind::HyperbolicCylinder:
      return "hyperbolic cylinder";
    case QuadricKind::IntersectingPlanes:
      return "pair of intersecting planes";
    case QuadricKind::ParabolicCylinder:
      return "parabolic cylinder";
    case QuadricKind::ParallelPlanes:
      return "pair of parallel planes";
    case QuadricKind::ImaginaryParallelPlanes:
      return "pair of imaginary parallel planes (no real point)";
    case QuadricKind::DoublePlane:
      return "double plane";
    case QuadricKind::NotQuadratic:
      return "equation without quadratic terms (a plane or nothing)";
  }
  return "unknown quadric";
}

QuadricKind classify_quadric(const Matrix4& q) {
  require_symmetric(q);
  auto [p3, n3] = inertia(q, 3);
  auto [p4, n4] = inertia(q, 4);
  if (p3 < n3) {  // orientation does not change the type: normalize to p3 >= n3
    std::swap(p3, n3);
    std::swap(p4, n4);
  }
  const int rank4 = p4 + n4;
  const int s = sgn(det4(q));
  if (p3 == 3) return s < 0 ? QuadricKind::Ellipsoid : (s > 0 ? QuadricKind::ImaginaryEllipsoid : QuadricKind::Point);
  if (p3 == 2 && n3 == 1)
    return s > 0 ? QuadricKind::HyperboloidOneSheet : (s < 0 ? QuadricKind::HyperboloidTwoSheets : QuadricKind::Cone);
  if (p3 == 2 && n3 == 0) {
    if (rank4 == 4) return QuadricKind::EllipticParaboloid;
    if (rank4 == 3)
      return (n4 == 1 || p4 == 1) ? QuadricKind::EllipticCylinder : QuadricKind::ImaginaryEllipticCylinder;
    return QuadricKind::Line;
  }
  if (p3 == 1 && n3 == 1) {
    if (rank4 == 4) return QuadricKind::HyperbolicParaboloid;
    if (rank4 == 3) return QuadricKind::HyperbolicCylinder;
    return QuadricKind::IntersectingPlanes;
  }
  if (p3 == 1) {
    if (rank4 == 3) return QuadricKind::ParabolicCylinder;
    if (rank4 == 2) return (p4 == 1 && n4 == 1) ? QuadricKind::ParallelPlanes : QuadricKind::ImaginaryParallelPlanes;
    return QuadricKind::DoublePlane;
  }
  return QuadricKind::NotQuadratic;
}

Matrix4 matrix_from_coefficients(const Coefficients10& c) {
  const Rational half(1, 2);
  Matrix4 m;
  m(0, 0) = c[0];
  m(1, 1) = c[1];
  m(2, 2) = c[2];
  m(3, 3) = c[9];
  m(0, 1) = m(1, 0) = c[3] * half;
  m(0, 2) = m(2, 0) = c[4] * half;
  m(1, 2) = m(2, 1) = c[5] * half;
  m(0, 3) = m(3, 0) = c[6] * half;
  m(1, 3) = m(3, 1) = c[7] * half;
  m(2, 3) = m(3, 2) = c[8] * half;
  return m;
}

Matrix3 rotation_from_quaternion(const Quaternion& q) {
  const Rational &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  Rational n = w * w + x * x + y * y + z * z;
  if (n == 0) throw InputError("rotation quaternion is zero");
  Matrix3 r;
  r(0, 0) = w * w + x * x - y * y - z * z;
  r(0, 1) = 2 * (x * y - w * z);
  r(0, 2) = 2 * (x * z + w * y);
  r(1, 0) = 2 * (x * y + w * z);
  r(1, 1) = w * w - x * x + y * y - z * z;
  r(1, 2) = 2 * (y * z - w * x);
  r(2, 0) = 2 * (x * z - w * y);
  r(2, 1) = 2 * (y * z + w * x);
  r(2, 2) = w * w - x * x - y * y + z * z;
  for (auto& v : r.a) v /= n;
  return r;
}

namespace {

bool exactly_symmetric(const Matrix4& q) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (q(i, j) != q(j, i)) return false;
  return true;
}

/// Certified enclosures of the entries (CGAL::to_interval; rounding towards +inf by the caller).
std::array<shape_filter::impl::I, 16> entry_intervals(const Matrix4& q) {
  std::array<shape_filter::impl::I, 16> x;
  for (std::size_t k = 0; k < 16; ++k) x[k] = shape_filter::impl::I(CGAL::to_interval(q.a[k]));
  return x;
}

/// The shape of a rational matrix as a filtered predicate: the orientation (+1 or -1, the sign of
/// the first entry) when intervals around the entries certify a real ellipsoid, else 0 and the
/// exact classification decides (and names what the matrix is).
int filtered_ellipsoid(const Matrix4& e) {
  const int want = CGAL::sign(e(0, 0));
  if (want == 0 || !exactly_symmetric(e)) return 0;
  CGAL::Protect_FPU_rounding<true> guard;
  return shape_filter::certified_ellipsoid_intervals(entry_intervals(e), want) == want ? want : 0;
}

/// The same for an elliptic paraboloid: the sign of the trace of Q3 when certain. det Q3 = 0 is
/// exact (zero factors, else the rational determinant: nine products, far cheaper than the
/// inertia).
int filtered_paraboloid(const Matrix4& p) {
  if (!exactly_symmetric(p)) return 0;
  if (!shape_filter::impl::zero_by_pattern(CGAL::is_zero(p.a[0]), CGAL::is_zero(p.a[1]), CGAL::is_zero(p.a[2]),
                                           CGAL::is_zero(p.a[5]), CGAL::is_zero(p.a[6]), CGAL::is_zero(p.a[10]))) {
    if (!CGAL::is_zero(shape_filter::impl::det3<Rational>(p.a))) return 0;
  }
  CGAL::Protect_FPU_rounding<true> guard;
  return shape_filter::certified_paraboloid_intervals(entry_intervals(p));
}

}  // namespace

Ellipsoid Ellipsoid::from_matrix(const Matrix4& e) {
  if (const int orientation = filtered_ellipsoid(e)) return Ellipsoid(orientation > 0 ? e : negated(e));
  QuadricKind k = classify_quadric(e);
  if (k == QuadricKind::EllipticParaboloid)
    throw InputError(
        "not an ellipsoid: the matrix describes an elliptic paraboloid (ellipsoid and paraboloid swapped?)");
  if (k != QuadricKind::Ellipsoid) throw InputError("not an ellipsoid: the matrix describes " + found(k));
  // Q3 is definite; make it positive definite (interior X^T E X < 0).
  return Ellipsoid(e(0, 0) > 0 ? e : negated(e));
}

namespace {

/// The exact rationals of 16 doubles; InputError (exact_rational's message) on NaN or infinity.
Matrix4 exact_matrix(const DoubleMatrix4& d) {
  Matrix4 m;
  for (std::size_t i = 0; i < 16; ++i) m.a[i] = exact_rational(d[i]);
  return m;
}

bool all_finite(const DoubleMatrix4& d) {
  for (double x : d)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

// flatten: the constructor and the signs in doubles in one frame, the values just normalized read
// without a call between; the rest (intervals, the exact path) out of line.
[[gnu::flatten]] Ellipsoid Ellipsoid::from_doubles(const DoubleMatrix4& e) {
  // Built in the returned object (one return: no copy of the 16 doubles) and normalized in place;
  // normalized doubles are finite, so all_finite runs only when the normalization did not.
  Ellipsoid out(e);
  const DoubleMatrix4* normalized = out.m_.filter_doubles();
  int orientation = shape_filter::certified_ellipsoid_in_doubles(normalized);
  if (orientation == 0) {
    [&]() __attribute__((noinline)) {
      orientation = normalized || all_finite(e) ? shape_filter::certified_ellipsoid_by_intervals(e) : 0;
      // Not certified (or not an ellipsoid): the exact path decides and names what the matrix is.
      if (orientation == 0) out = Ellipsoid(*from_matrix(exact_matrix(e)).doubles());
    }
    ();
  }
  if (orientation < 0) out.m_.negate_doubles();
  return out;
}

Ellipsoid Ellipsoid::from_coefficients(const Coefficients10& c) { return from_matrix(matrix_from_coefficients(c)); }

Ellipsoid Ellipsoid::translated(const Vector3& d) const {
  const Matrix4& q = matrix();
  Matrix4 m = q;
  Rational e0 = q(3, 3);
  for (int i = 0; i < 3; ++i) {
    Rational md(0);  // (M d)_i
    for (int j = 0; j < 3; ++j) md += q(i, j) * d[static_cast<std::size_t>(j)];
    const Rational& di = d[static_cast<std::size_t>(i)];
    m(i, 3) = m(3, i) = q(i, 3) - md;
    e0 += di * (md - 2 * q(i, 3));  // - 2 e_i d_i + d_i (M d)_i
  }
  m(3, 3) = e0;
  return Ellipsoid(std::move(m));
}

Ellipsoid Ellipsoid::sphere(const Vector3& c, const Rational& r) {
  if (r <= 0) throw InputError("sphere radius must be positive, got " + to_string(r));
  Matrix4 m;
  for (int i = 0; i < 3; ++i) {
    m(i, i) = Rational(1);
    m(i, 3) = m(3, i) = -c[static_cast<std::size_t>(i)];
  }
  m(3, 3) = squared_norm_minus(c, r);
  return Ellipsoid(m);
}

Ellipsoid Ellipsoid::sphere(const std::array<double, 3>& c, double r) {
  return sphere(exact_array(c), exact_rational(r));
}

Ellipsoid Ellipsoid::from_axes(const std::array<double, 3>& c, const std::array<double, 3>& ax,
                               const std::array<double, 4>& q) {
  return from_axes(exact_array(c), exact_array(ax), Quaternion(exact_array(q)));
}

Ellipsoid Ellipsoid::from_axes(const Vector3& c, const Vector3& ax, const Quaternion& q) {
  return from_axes(c, ax, rotation_from_quaternion(q));
}

Ellipsoid Ellipsoid::from_axes(const Vector3& c, const Vector3& ax, const Matrix3& rot) {
  for (const auto& a : ax)
    if (a <= 0) throw InputError("ellipsoid semi-axes must be positive, got " + to_string(a));
  check_orthogonal(rot);
  Matrix3 l;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l(i, j) = rot(i, j) * ax[static_cast<std::size_t>(j)];
  return from_map(c, l);
}

Ellipsoid Ellipsoid::from_map(const Vector3& c, const Matrix3& l) {
  Matrix4 unit;  // x^2 + y^2 + z^2 - 1
  unit(0, 0) = unit(1, 1) = unit(2, 2) = Rational(1);
  unit(3, 3) = Rational(-1);
  // The image of the unit ball under an invertible affine map: an ellipsoid, positive definite block
  // (Sylvester's law of inertia): no validation, no sign normalization.
  return Ellipsoid(push_forward(unit, l, c, "ellipsoid linear map"));
}

Paraboloid Paraboloid::from_matrix(const Matrix4& p) {
  if (const int orientation = filtered_paraboloid(p)) return Paraboloid(orientation > 0 ? p : negated(p));
  QuadricKind k = classify_quadric(p);
  if (k == QuadricKind::Ellipsoid)
    throw InputError(
        "not an elliptic paraboloid: the matrix describes an ellipsoid (ellipsoid and paraboloid swapped?)");
  if (k != QuadricKind::EllipticParaboloid)
    throw InputError("not an elliptic paraboloid: the matrix describes " + found(k));
  // Q3 is semidefinite of rank 2; its trace has the sign of its non-zero eigenvalues.
  return Paraboloid(p(0, 0) + p(1, 1) + p(2, 2) > 0 ? p : negated(p));
}

// The same steps as Ellipsoid::from_doubles with the paraboloid's certifier, written out: a template
// over both would have to be a friend of both classes for these few lines.
[[gnu::flatten]] Paraboloid Paraboloid::from_doubles(const DoubleMatrix4& p) {
  Paraboloid out(p);
  const DoubleMatrix4* normalized = out.m_.filter_doubles();
  int orientation = shape_filter::certified_paraboloid_in_doubles(p, normalized);
  if (orientation == 0) {
    [&]() __attribute__((noinline)) {
      orientation = normalized || all_finite(p) ? shape_filter::certified_paraboloid_by_intervals(p) : 0;
      if (orientation == 0) out = Paraboloid(*from_matrix(exact_matrix(p)).doubles());
    }
    ();
  }
  if (orientation < 0) out.m_.negate_doubles();
  return out;
}

Paraboloid Paraboloid::from_coefficients(const Coefficients10& c) { return from_matrix(matrix_from_coefficients(c)); }

Paraboloid Paraboloid::standard(const Vector3& v, const Rational& a, const Rational& b, const Quaternion& q) {
  if (a <= 0 || b <= 0)
    throw InputError("paraboloid parameters a, b must be positive, got a = " + to_string(a) + ", b = " + to_string(b));
  const Rational ia = forms::inverse_square(a), ib = forms::inverse_square(b);
  // A congruence of the standard paraboloid by an invertible affine map is an elliptic paraboloid
  // with the same orientation (Sylvester's law of inertia): no validation, no sign normalization.
  if (q[0] != 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) {
    // No rotation: (x - v)^T A (x - v) - (z - v_z), written directly (the common case).
    Matrix4 m;
    m(0, 0) = ia;
    m(1, 1) = ib;
    m(2, 3) = m(3, 2) = Rational(-1, 2);
    if (v[0] == 0 && v[1] == 0) {  // a vertex on the z axis (the usual input): no products of zeros
      m(3, 3) = v[2];
      return Paraboloid(std::move(m));
    }
    m(0, 3) = m(3, 0) = -ia * v[0];
    m(1, 3) = m(3, 1) = -ib * v[1];
    m(3, 3) = ia * v[0] * v[0] + ib * v[1] * v[1] + v[2];
    return Paraboloid(std::move(m));
  }
  Matrix4 local;
  local(0, 0) = ia;
  local(1, 1) = ib;
  local(2, 3) = local(3, 2) = Rational(-1, 2);
  return Paraboloid(push_forward(local, rotation_from_quaternion(q), v, "paraboloid rotation"));
}

Paraboloid Paraboloid::standard(const std::array<double, 3>& v, double a, double b, const std::array<double, 4>& q) {
  return standard(exact_array(v), exact_rational(a), exact_rational(b), Quaternion(exact_array(q)));
}

Paraboloid Paraboloid::from_map(const Matrix3& l, const Vector3& t) {
  Matrix4 local;  // x^2 + y^2 - z
  local(0, 0) = local(1, 1) = Rational(1);
  local(2, 3) = local(3, 2) = Rational(-1, 2);
  return Paraboloid(push_forward(local, l, t, "paraboloid linear map"));  // valid by construction
}

namespace {

/// An upper bound on normalized_bits(m) from the lcm of the denominators alone: each entry of the
/// integer form, num * (l / den), has at most bits(num) + bits(l) - bits(den) + 1 bits.
std::size_t normalized_bits_bound(const Matrix4& m) {
  Integer l(1);
  forms::lcm_of_denominators(m.a.begin(), m.a.end(), l);
  const std::size_t lb = mpz_sizeinbase(l.mpz(), 2);
  std::size_t bound = 0;
  for (const Rational& q : m.a)
    bound = std::max(bound, mpz_sizeinbase(mpq_numref(q.mpq()), 2) + lb + 1 - mpz_sizeinbase(mpq_denref(q.mpq()), 2));
  return bound;
}

}  // namespace

std::size_t normalized_bits(const Matrix4& m) {
  Integer l(1), g(0);
  forms::lcm_of_denominators(m.a.begin(), m.a.end(), l);
  std::array<Integer, 16> z;
  for (std::size_t i = 0; i < 16; ++i) {
    forms::scaled_numerator(m.a[i], l, z[i].mpz());
    mpz_gcd(g.mpz(), g.mpz(), z[i].mpz());
  }
  if (g == 0) return 0;
  std::size_t bits = 0;
  for (auto& x : z) {
    if (x == 0) continue;
    mpz_divexact(x.mpz(), x.mpz(), g.mpz());
    bits = std::max<std::size_t>(bits, mpz_sizeinbase(x.mpz(), 2));
  }
  return bits;
}

std::size_t normalized_pair_bits(const Ellipsoid& e, const Paraboloid& p) {
  return std::max(normalized_bits(e.matrix()), normalized_bits(p.matrix()));
}

std::size_t check_normalized_pair_size(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit) {
  if (limit.max_bits < kMaxNormalizedBits)
    throw InputError("the size limit is at least " + std::to_string(kMaxNormalizedBits) + " bits, got " +
                     std::to_string(limit.max_bits) + " (it can be raised, not lowered: doc/cli.md, Limits)");
  // A matrix of doubles is within the limit whatever its entries: its primitive form has at most
  // 2098 bits (every double is a multiple of 2^-1074 below 2^1024), so the check costs nothing then and
  // never builds the exact matrix of a quadric made from doubles.
  static_assert(kMaxNormalizedBits >= 2098, "every matrix of doubles must pass");
  // The bound from the lcm alone settles ordinary inputs (decimals with their powers of ten) without
  // the gcd and the products.
  auto bits_of = [&](const Matrix4& m) {
    const std::size_t bound = normalized_bits_bound(m);
    return bound <= kMaxNormalizedBits ? bound : normalized_bits(m);
  };
  const std::size_t bits = std::max(storage_of(e).within_size_limit() ? 0 : bits_of(e.matrix()),
                                    storage_of(p).within_size_limit() ? 0 : bits_of(p.matrix()));
  if (bits > limit.max_bits)
    throw InputError(
        "numbers too large: a matrix of the pair, divided by its own content (its primitive integer "
        "form), has " +
        std::to_string(bits) + "-bit entries, beyond the limit of " + std::to_string(limit.max_bits) +
        (limit.max_bits == kMaxNormalizedBits ? " bits (kMaxNormalizedBits, doc/cli.md, Limits)"
                                              : " bits (the limit given, doc/cli.md, Limits)"));
  return bits;
}

}  // namespace relpos
