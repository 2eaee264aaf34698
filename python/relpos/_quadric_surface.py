"""The surface of a relpos.Quadric near an ellipsoid, as grids for matplotlib (relpos.plot).

The quadric arrives in the ellipsoid's frame u (relpos._plot._Frame.local: q(u) = quad u^T An u +
lin^T u + h, already divided by its largest term), is diagonalized in floating point (the eigen-frame
of its quadratic part) and drawn as one or two parametrized patches of its type, clipped to the box
|u_i| <= width around the ellipsoid. Which eigenvalues are zero is read from the exact type, never
from the floats. Only the picture is in floating point: the position in the title is the exact one.
"""

import math

import numpy

#: How many eigenvalues of the quadratic part are not zero, for each type (doc/quadrics.md).
_RANK = {
    "ellipsoid": 3,
    "hyperboloid of one sheet": 3,
    "hyperboloid of two sheets": 3,
    "elliptic cone": 3,
    "elliptic paraboloid": 2,
    "hyperbolic paraboloid": 2,
    "elliptic cylinder": 2,
    "hyperbolic cylinder": 2,
    "parabolic cylinder": 1,
    "slab": 1,
    "half-space": 0,
}

#: The types whose equation keeps a linear term along a zero eigenvalue (the others have a centre line
#: or plane there, and a float remainder of that term is rounding).
_LINEAR = ("elliptic paraboloid", "hyperbolic paraboloid", "parabolic cylinder")


def _grid(a, b, n):
    return numpy.meshgrid(numpy.linspace(a[0], a[1], n), numpy.linspace(b[0], b[1], n))


def _plane(normal, h, reach, n):
    """The plane normal . y + h = 0 near y = 0: a square of half-side reach around the foot of 0."""
    norm = numpy.linalg.norm(normal)
    d = normal / norm
    foot = -h / norm * d
    e1 = numpy.cross(d, [1.0, 0.0, 0.0] if abs(d[0]) < 0.9 else [0.0, 1.0, 0.0])
    e1 /= numpy.linalg.norm(e1)
    e2 = numpy.cross(d, e1)
    s, t = _grid((-reach, reach), (-reach, reach), n)
    return [foot[:, None, None] + e1[:, None, None] * s + e2[:, None, None] * t]


def _patches(kind, An, quad, lin, h, width, n):
    """Patches (each a (3, n, n) array) in the eigen-frame y = V^T u, and V; u = V y."""
    reach = width * numpy.sqrt(3.0)  # the box |u_i| <= width lies in the ball |y| <= reach
    rank = _RANK[kind]
    if rank == 0:
        return _plane(lin, h, reach, n), numpy.eye(3)
    w, V = numpy.linalg.eigh(An * quad)
    order = numpy.argsort(-numpy.abs(w))  # the `rank` largest first, then the zero ones
    w, V = w[order], V[:, order]
    m = V.T @ lin
    N = list(range(rank))
    o = numpy.zeros(3)  # y = z - o: z centred where the square is completed
    for i in N:
        o[i] = m[i] / (2 * w[i])
    k = h - sum(m[i] ** 2 / (4 * w[i]) for i in N)  # sum_N w_i z_i^2 + (linear in the others) + k = 0
    if sum(w[i] < 0 for i in N) * 2 > rank or (rank == 1 and w[0] < 0):
        w, m, k = -w, -m, -k  # the same surface with the majority of the signs positive
    patches = []

    def span(i):  # z_i over the box
        return (o[i] - reach, o[i] + reach)

    if rank == 3:
        neg = [i for i in N if w[i] < 0]
        if not neg:  # ellipsoid: sum w_i z_i^2 = -k
            t, v = _grid((0, 2 * math.pi), (0, math.pi), n)
            r = numpy.sqrt(-k / w)
            patches.append(numpy.stack([r[0] * numpy.cos(t) * numpy.sin(v), r[1] * numpy.sin(t) * numpy.sin(v),
                                        r[2] * numpy.cos(v)]))
        else:  # hyperboloids, cone: w_i z_i^2 + w_j z_j^2 = -k - w_c z_c^2 along the odd axis c
            c = neg[0]
            i, j = [x for x in N if x != c]
            lo, hi = span(c)
            ts = numpy.linspace(lo, hi, n)
            if k > 0:  # two sheets: put their vertices on the grid
                v = numpy.sqrt(k / -w[c])
                ts = numpy.union1d(ts, [x for x in (-v, v) if lo < x < hi])
            theta = numpy.linspace(0, 2 * math.pi, n)
            T, TH = numpy.meshgrid(ts, theta)
            R = numpy.sqrt(-k - w[c] * T**2)  # NaN between the two sheets
            z = numpy.zeros((3,) + T.shape)
            z[c], z[i], z[j] = T, R / numpy.sqrt(w[i]) * numpy.cos(TH), R / numpy.sqrt(w[j]) * numpy.sin(TH)
            patches.append(z)
    elif rank == 2:
        i, j, a = 0, 1, 2  # a: the zero eigenvalue's axis
        if kind in _LINEAR:  # a paraboloid: a graph over (z_i, z_j)
            Zi, Zj = _grid(span(i), span(j), n)
            z = numpy.stack([Zi, Zj, -(w[i] * Zi**2 + w[j] * Zj**2 + k) / m[a]])
            patches.append(z)
        elif w[i] > 0 and w[j] > 0:  # elliptic cylinder
            T, TH = _grid(span(a), (0, 2 * math.pi), n)
            z = numpy.stack([numpy.sqrt(-k / w[i]) * numpy.cos(TH), numpy.sqrt(-k / w[j]) * numpy.sin(TH), T])
            patches.append(z)
        else:  # hyperbolic cylinder: w_p z_p^2 - |w_q| z_q^2 = -k with -k / w_p > 0, two branches
            p, q = (i, j) if -k / w[i] > 0 else (j, i)
            A, B = numpy.sqrt(-k / w[p]), numpy.sqrt(k / w[q])
            top = numpy.arcsinh((abs(o[q]) + reach) / B)
            T, S = _grid(span(a), (-top, top), n)
            for sign in (1, -1):
                z = numpy.zeros((3,) + T.shape)
                z[p], z[q], z[a] = sign * A * numpy.cosh(S), B * numpy.sinh(S), T
                patches.append(z)
    else:  # rank 1: w_0 z_0^2 + m_1 y_1 + m_2 y_2 + k = 0
        if kind in _LINEAR:  # parabolic cylinder: y along the linear term's direction d, free along e
            g = math.hypot(m[1], m[2])
            d = numpy.array([0.0, m[1], m[2]]) / g
            e = numpy.array([0.0, -m[2], m[1]]) / g
            Z0, E = _grid(span(0), (-reach, reach), n)
            zeta = -(w[0] * Z0**2 + k) / g
            z = d[:, None, None] * zeta + e[:, None, None] * E
            z[0] = Z0
            patches.append(z)
        else:  # slab: the planes z_0 = +-sqrt(-k / w_0)
            for sign in (1, -1):
                Y1, Y2 = _grid((-reach, reach), (-reach, reach), n)
                patches.append(numpy.stack([numpy.full_like(Y1, sign * numpy.sqrt(-k / w[0])), Y1, Y2]))
    for z in patches:
        z -= o[:, None, None]
    return patches, V


def surfaces(kind, local, width, n=48):
    """Grids (X, Y, Z) in u of the quadric of type `kind` given in the ellipsoid's frame by `local`
    (relpos._plot._Frame.local), NaN outside the box |u_i| <= width (all NaN when the quadric is too
    far from the ellipsoid, for its size, to reach the box)."""
    An, quad, lin, h = local
    with numpy.errstate(all="ignore"):
        patches, V = _patches(kind, An, quad, lin, h, width, n)
        out = []
        for z in patches:
            u = numpy.einsum("ij,jkl->ikl", V, z)
            far = ~numpy.all(numpy.isfinite(u), axis=0) | numpy.any(numpy.abs(u) > width, axis=0)
            u[:, far] = numpy.nan
            out.append((u[0], u[1], u[2]))
    return out
