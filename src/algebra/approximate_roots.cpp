#include "algebra/approximate_roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace relpos::detail {
namespace {

/// Polynomial value in doubles (coefficients c[0..N]). The degree is a template parameter so
/// that every loop below unrolls; the operations and their order are those of the written loops.
template <int N>
double horner(const double* c, double x) {
  double v = c[N];
  for (int i = N - 1; i >= 0; --i) v = v * x + c[i];
  return v;
}

/// The safeguarded Newton iteration for a root of c in [lo, hi] where c changes sign (flo: the value
/// at lo), started at the midpoint.
struct Bracket {
  double x = 0, lo = 0, hi = 0;
  double half_step = 0;  // half the last step (at first half the bracket), computed as the step's test reads it
  bool flo_negative = false;
  int steps = 0;
  static Bracket of(double lo, double hi, double flo) {
    return {lo + (hi - lo) / 2, lo, hi, (hi - lo) / 2, flo < 0, 0};
  }
};

/// One step for c of degree N (a template parameter: the loops unroll): Newton steps kept inside the
/// shrinking bracket, bisection when a step leaves it or does not halve the bracket (safeguarded
/// Newton), until the bracket or the step is below 2^-50 of the root, or after 2100 steps. A handful
/// of steps instead of the ~70 of plain bisection; the result is only an approximation, certified
/// afterwards by exact signs. False when done, the root in b.x. Always inlined: a call per step
/// would cost about as much as the step.
template <int N>
[[gnu::always_inline]] inline bool newton_step(const double* c, Bracket& b) {
  const double x = b.x;
  double fx = c[N], dfx = 0;  // value and derivative by Horner
  for (int i = N - 1; i >= 0; --i) {
    dfx = dfx * x + fx;
    fx = fx * x + c[i];
  }
  if (fx == 0) return false;
  if ((fx < 0) == b.flo_negative)
    b.lo = x;
  else
    b.hi = x;
  const double tol = 0x1p-50 * std::max(std::fabs(b.lo), std::fabs(b.hi));
  if (!(b.hi - b.lo > tol)) return false;
  double next = x - fx / dfx;
  const bool inside = next > b.lo && next < b.hi;
  if (!inside || !(std::fabs(next - x) < b.half_step)) next = b.lo + (b.hi - b.lo) / 2;  // bisect
  const double step = std::fabs(next - x);
  b.half_step = step / 2;
  if (!(next > b.lo && next < b.hi)) return false;  // the bracket cannot shrink further
  b.x = next;
  return !(inside && step <= tol) && ++b.steps < 2100;  // a Newton step this small: converged
}

/// A root of c (degree N) in a bracket.
template <int N>
double bracketed_root(const double* c, Bracket b) {
  while (newton_step<N>(c, b)) {
  }
  return b.x;
}

/// The roots in two brackets, their steps interleaved: each step touches only its own bracket, so
/// the iterates are those of bracketed_root, while the two chains of dependent floating-point
/// operations (Horner, division) overlap in the processor (an iteration is bound by their latency).
/// The brackets are local copies: their state stays in registers.
template <int N>
void bracketed_roots(const double* c, Bracket a, Bracket b, double& root_a, double& root_b) {
  bool more_a = true, more_b = true;
  while (more_a && more_b) {
    more_a = newton_step<N>(c, a);
    more_b = newton_step<N>(c, b);
  }
  while (more_a) more_a = newton_step<N>(c, a);
  while (more_b) more_b = newton_step<N>(c, b);
  root_a = a.x;
  root_b = b.x;
}

/// Approximate real roots of c (degree N <= 4, c[N] != 0) in (-bound, bound), increasing, into
/// out[0..count): the roots of the derivative split the line into monotone pieces, each with at most
/// one sign change. The brackets are solved in pairs from the outside in (the two outer ones, far
/// from the roots of the derivative, take the most steps, and about as many). Fixed arrays (no
/// allocation): a few hundred nanoseconds.
template <int N>
int approximate_real_roots(const double* c, double bound, double* out) {
  if constexpr (N == 1) {
    out[0] = -c[0] / c[1];
    return 1;
  } else {
    double d[N], inner[N], cuts[N + 2];
    for (int i = 1; i <= N; ++i) d[i - 1] = i * c[i];
    const int m = approximate_real_roots<N - 1>(d, bound, inner);
    int cut_count = 0;
    cuts[cut_count++] = -bound;
    for (int k = 0; k < m; ++k)
      if (inner[k] > cuts[cut_count - 1] && inner[k] < bound) cuts[cut_count++] = inner[k];
    cuts[cut_count++] = bound;
    Bracket brackets[N];
    int count = 0, bracket_count = 0, at[N];  // at: where each bracket's root goes in out
    double b = horner<N>(c, cuts[0]);
    for (int k = 0; k + 1 < cut_count; ++k) {
      const double a = b;  // the value at each cut computed once
      b = horner<N>(c, cuts[k + 1]);
      if (a == 0) {
        // The last entry, when a bracket's root still to come, lies below its bracket's upper cut,
        // itself below cuts[k]: NaN (unequal to everything) says the same.
        if (count == 0 || out[count - 1] != cuts[k]) out[count++] = cuts[k];
      } else if ((a < 0) != (b < 0) && b != 0) {
        brackets[bracket_count] = Bracket::of(cuts[k], cuts[k + 1], a);
        at[bracket_count++] = count;
        out[count++] = std::numeric_limits<double>::quiet_NaN();
      }
    }
    int first = 0, last = bracket_count - 1;
    for (; first < last; ++first, --last)
      bracketed_roots<N>(c, brackets[first], brackets[last], out[at[first]], out[at[last]]);
    if (first == last) out[at[first]] = bracketed_root<N>(c, brackets[first]);
    return count;
  }
}

}  // namespace

int approximate_real_roots(const double* c, int n, double bound, double* out) {
  switch (n) {
    case 1:
      return approximate_real_roots<1>(c, bound, out);
    case 2:
      return approximate_real_roots<2>(c, bound, out);
    case 3:
      return approximate_real_roots<3>(c, bound, out);
    case 4:
      return approximate_real_roots<4>(c, bound, out);
    default:
      throw std::logic_error("approximate_real_roots: degree outside 1..4");
  }
}

}  // namespace relpos::detail
