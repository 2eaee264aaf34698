// The certificate polynomials of the scene early-outs (math.md §13).
//
// P(x) on the ellipsoid (x - c)^T M (x - c) <= k is bounded through P(c + d) = P(c) + g.d + d^T A d
// (g = grad P(c)): max g.d = sqrt(k g^T M^-1 g), 0 <= d^T A d <= k * mu_max with mu_max the largest
// eigenvalue of A relative to M. Cleared of denominators (D = det M > 0, K = -det E > 0), the
// certificates become signs of the polynomials of ContainmentQuantities / SphereQuantities below.
#pragma once

namespace relpos {

// ------------------------------------------------------------------------------------------------
// The certificate polynomials, generic over the number type (RunningBound in the filter, exact
// rationals in the tests).
// ------------------------------------------------------------------------------------------------

/// Entries of a symmetric 4x4 matrix [[Q3, q], [q^T, q0]] as the ten numbers the certificates use.
template <class NT>
struct SymmetricEntries {
  NT q00, q11, q22, q01, q02, q12;  ///< Q3
  NT q0, q1, q2;                    ///< q (the last column)
  NT q33;                           ///< q0
};

/// The ten entries of a symmetric 4x4 matrix given entry by entry (get(i, j), i <= j).
template <class NT, class Get>
SymmetricEntries<NT> entries(Get get) {
  return {get(0, 0), get(1, 1), get(2, 2), get(0, 1), get(0, 2), get(1, 2), get(0, 3), get(1, 3), get(2, 3), get(3, 3)};
}

/// adj(Q3) of the 3x3 block (the other fields are left default): adj(A) of a paraboloid, the
/// constant the containment certificates need.
template <class NT>
SymmetricEntries<NT> adjugate3(const SymmetricEntries<NT>& p) {
  SymmetricEntries<NT> adj{};
  adj.q00 = p.q11 * p.q22 - p.q12 * p.q12;
  adj.q11 = p.q00 * p.q22 - p.q02 * p.q02;
  adj.q22 = p.q00 * p.q11 - p.q01 * p.q01;
  adj.q01 = p.q02 * p.q12 - p.q01 * p.q22;
  adj.q02 = p.q01 * p.q12 - p.q02 * p.q11;
  adj.q12 = p.q01 * p.q02 - p.q00 * p.q12;
  return adj;
}

/// Ellipsoid E = [[M, e], [e^T, e0]] against paraboloid P = [[A, p], [p^T, p0]]. With
/// y = adj(M) e (so the centre is c = -y / D) and w = D p - A y (so grad P(c) = 2 w / D):
///   D  = det M                              (> 0)
///   K  = e . y - e0 D = -det E              (> 0; k = K / D is the level: (x-c)^T M (x-c) <= k)
///   Pn = y^T A y - 2 D p . y + D^2 p0       = D^2 P(c)
///   W  = w^T adj(M) w                       (D^3 g^T M^-1 g / 4)
///   S1 = tr(adj(M) A), S2 = tr(adj(A) M)    (s(l) = det(l A + M) = S2 l^2 + S1 l + D)
/// Inside: D^2 max P <= Pn + 2 sqrt(K W) + K S1 (mu_max <= mu_1 + mu_2 = S1 / D), so
///   T = Pn + K S1 < 0 and T^2 > 4 K W            =>  P < 0 on the closed solid ellipsoid.
/// Outside: D^2 min P >= Pn - 2 sqrt(K W) (P is convex), so
///   Pn > 0 and Pn^2 > 4 K W                       =>  P > 0 on the closed solid ellipsoid.
template <class NT>
struct ContainmentQuantities {
  NT D, K, Pn, W, S1, S2;
  /// adj_a: adj(A) of the paraboloid (needed for S2 only).
  ContainmentQuantities(const SymmetricEntries<NT>& e, const SymmetricEntries<NT>& p,
                        const SymmetricEntries<NT>& adj_a) {
    compute<false>(e, p, adj_a);
  }
  /// The same when A (hence adj(A)) is diagonal: the products with zero entries left out.
  struct DiagonalA {};
  ContainmentQuantities(const SymmetricEntries<NT>& e, const SymmetricEntries<NT>& p, const SymmetricEntries<NT>& adj_a,
                        DiagonalA) {
    compute<true>(e, p, adj_a);
  }
  NT inside_t() const { return Pn + K * S1; }
  /// Must be > 0 (with inside_t() < 0) for the inside certificate.
  NT inside_gap() const {
    const NT t = inside_t();
    return t * t - NT(4) * K * W;
  }
  /// Must be > 0 (with Pn > 0) for the outside certificate.
  NT outside_gap() const { return Pn * Pn - NT(4) * K * W; }

 private:
  template <bool kDiagonalA>
  void compute(const SymmetricEntries<NT>& e, const SymmetricEntries<NT>& p, const SymmetricEntries<NT>& adj_a) {
    // adj(M), symmetric.
    const NT a00 = e.q11 * e.q22 - e.q12 * e.q12, a11 = e.q00 * e.q22 - e.q02 * e.q02,
             a22 = e.q00 * e.q11 - e.q01 * e.q01;
    const NT a01 = e.q02 * e.q12 - e.q01 * e.q22, a02 = e.q01 * e.q12 - e.q02 * e.q11,
             a12 = e.q01 * e.q02 - e.q00 * e.q12;
    D = e.q00 * a00 + e.q01 * a01 + e.q02 * a02;
    const NT y0 = a00 * e.q0 + a01 * e.q1 + a02 * e.q2, y1 = a01 * e.q0 + a11 * e.q1 + a12 * e.q2,
             y2 = a02 * e.q0 + a12 * e.q1 + a22 * e.q2;
    K = e.q0 * y0 + e.q1 * y1 + e.q2 * y2 - e.q33 * D;
    NT ay0, ay1, ay2;  // A y
    if constexpr (kDiagonalA) {
      ay0 = p.q00 * y0;
      ay1 = p.q11 * y1;
      ay2 = p.q22 * y2;
    } else {
      ay0 = p.q00 * y0 + p.q01 * y1 + p.q02 * y2;
      ay1 = p.q01 * y0 + p.q11 * y1 + p.q12 * y2;
      ay2 = p.q02 * y0 + p.q12 * y1 + p.q22 * y2;
    }
    Pn = (y0 * ay0 + y1 * ay1 + y2 * ay2) - NT(2) * D * (p.q0 * y0 + p.q1 * y1 + p.q2 * y2) + D * D * p.q33;
    const NT w0 = D * p.q0 - ay0, w1 = D * p.q1 - ay1, w2 = D * p.q2 - ay2;
    W = w0 * (a00 * w0 + a01 * w1 + a02 * w2) + w1 * (a01 * w0 + a11 * w1 + a12 * w2) +
        w2 * (a02 * w0 + a12 * w1 + a22 * w2);
    if constexpr (kDiagonalA) {
      S1 = a00 * p.q00 + a11 * p.q11 + a22 * p.q22;
      S2 = adj_a.q00 * e.q00 + adj_a.q11 * e.q11 + adj_a.q22 * e.q22;
    } else {
      S1 = a00 * p.q00 + a11 * p.q11 + a22 * p.q22 + NT(2) * (a01 * p.q01 + a02 * p.q02 + a12 * p.q12);
      S2 = adj_a.q00 * e.q00 + adj_a.q11 * e.q11 + adj_a.q22 * e.q22 +
           NT(2) * (adj_a.q01 * e.q01 + adj_a.q02 * e.q02 + adj_a.q12 * e.q12);
    }
  }
};

/// The same for a sphere, M = m I (m > 0): with K' = e.e - m e0, Pn' = e^T A e - 2 m p.e + m^2 p0,
/// w' = m p - A e, W' = w'.w' one has K = m^2 K', Pn = m^4 Pn', W = m^6 W', and the sphere's
/// radius^2 is K'/m^2, so max d^T A d = (K'/m^2) lambda_max(A). With lmax >= lambda_max(A):
///   Inside:  T' = Pn' + K' lmax < 0 and T'^2 > 4 K' W';   Outside: Pn' > 0 and Pn'^2 > 4 K' W'.
template <class NT>
struct SphereQuantities {
  NT m, Kp, Pnp, Wp;
  SphereQuantities(const SymmetricEntries<NT>& e, const SymmetricEntries<NT>& p) : m(e.q00) {
    Kp = e.q0 * e.q0 + e.q1 * e.q1 + e.q2 * e.q2 - m * e.q33;
    const NT ae0 = p.q00 * e.q0 + p.q01 * e.q1 + p.q02 * e.q2, ae1 = p.q01 * e.q0 + p.q11 * e.q1 + p.q12 * e.q2,
             ae2 = p.q02 * e.q0 + p.q12 * e.q1 + p.q22 * e.q2;
    Pnp =
        (e.q0 * ae0 + e.q1 * ae1 + e.q2 * ae2) - NT(2) * m * (p.q0 * e.q0 + p.q1 * e.q1 + p.q2 * e.q2) + m * m * p.q33;
    const NT w0 = m * p.q0 - ae0, w1 = m * p.q1 - ae1, w2 = m * p.q2 - ae2;
    Wp = w0 * w0 + w1 * w1 + w2 * w2;
  }
  /// The same quantities when A is diagonal (a paraboloid whose axes are the coordinate axes, the
  /// usual container): the products with its zero entries left out.
  struct DiagonalA {};
  SphereQuantities(const SymmetricEntries<NT>& e, const SymmetricEntries<NT>& p, DiagonalA) : m(e.q00) {
    Kp = e.q0 * e.q0 + e.q1 * e.q1 + e.q2 * e.q2 - m * e.q33;
    const NT ae0 = p.q00 * e.q0, ae1 = p.q11 * e.q1, ae2 = p.q22 * e.q2;
    Pnp =
        (e.q0 * ae0 + e.q1 * ae1 + e.q2 * ae2) - NT(2) * m * (p.q0 * e.q0 + p.q1 * e.q1 + p.q2 * e.q2) + m * m * p.q33;
    const NT w0 = m * p.q0 - ae0, w1 = m * p.q1 - ae1, w2 = m * p.q2 - ae2;
    Wp = w0 * w0 + w1 * w1 + w2 * w2;
  }
  NT inside_t(const NT& lmax) const { return Pnp + Kp * lmax; }
  NT inside_gap(const NT& lmax) const {
    const NT t = inside_t(lmax);
    return t * t - NT(4) * Kp * Wp;
  }
  NT outside_gap() const { return Pnp * Pnp - NT(4) * Kp * Wp; }
};

}  // namespace relpos
