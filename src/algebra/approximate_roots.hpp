// Approximate real roots of a polynomial of degree <= 4 in doubles, without allocation: the
// proposals that roots.hpp's fast path then certifies by exact signs (double_sign.hpp). Nothing
// here is certified; a wrong proposal only sends the caller to the general path.
#pragma once

namespace relpos::detail {

/// Approximate real roots of c (degree n in 1..4, c[n] != 0) in (-bound, bound), increasing, into
/// out[0..count), count returned: the roots of the derivative split the line into monotone pieces,
/// each with at most one sign change, solved by safeguarded Newton steps to about 2^-50 of the root.
/// A root at a piece's end is reported once; std::logic_error for a degree outside 1..4.
int approximate_real_roots(const double* c, int n, double bound, double* out);

}  // namespace relpos::detail
