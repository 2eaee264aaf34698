"""A float implementation to judge: the paper's rule in plain doubles (doc/oracle.md, "Walkthrough").

This is the kind of code relpos is an oracle for, not code to use: the pair's matrices from its
parameters, the characteristic quartic f(l) = det(l P + E), its discriminant, and the sign rule, all
in Python floats (IEEE doubles), with the usual tolerance for "zero":

    |Disc(f)| <= 1e-12 * scale  ->  tangent: TE when f has a positive root (sign changes), else TI
    Disc(f) < 0                  ->  C (two real roots and a non-real pair)
    Disc(f) > 0                  ->  E with two positive roots (two sign changes), else I
"""

from itertools import combinations, permutations


def rotation(q):
    """R(q) / |q|^2 of a quaternion (w, x, y, z), entry by entry."""
    w, x, y, z = q
    n = w * w + x * x + y * y + z * z
    return [
        [(w * w + x * x - y * y - z * z) / n, 2 * (x * y - w * z) / n, 2 * (x * z + w * y) / n],
        [2 * (x * y + w * z) / n, (w * w - x * x + y * y - z * z) / n, 2 * (y * z - w * x) / n],
        [2 * (x * z - w * y) / n, 2 * (y * z + w * x) / n, (w * w - x * x - y * y + z * z) / n],
    ]


def rdrt(r, d):
    """(R diag(d)) R^T, as two matrix products."""
    rd = [[r[i][k] * d[k] for k in range(3)] for i in range(3)]
    return [[rd[i][0] * r[j][0] + rd[i][1] * r[j][1] + rd[i][2] * r[j][2] for j in range(3)] for i in range(3)]


def assemble(m, u, corner):
    return [m[0] + [u[0]], m[1] + [u[1]], m[2] + [u[2]], u + [corner]]


def ellipsoid_matrix(centre, axes, q):
    m = rdrt(rotation(q), [1 / (a * a) for a in axes])
    mc = [sum(m[i][j] * centre[j] for j in range(3)) for i in range(3)]
    return assemble(m, [-v for v in mc], sum(centre[i] * mc[i] for i in range(3)) - 1)


def paraboloid_matrix(vertex, a, b, q):
    r = rotation(q)
    m = rdrt(r, [1 / (a * a), 1 / (b * b), 0.0])
    mv = [sum(m[i][j] * vertex[j] for j in range(3)) for i in range(3)]
    axis = [r[0][2], r[1][2], r[2][2]]
    u = [-mv[i] - axis[i] / 2 for i in range(3)]
    return assemble(m, u, sum(vertex[i] * mv[i] for i in range(3)) + sum(axis[i] * vertex[i] for i in range(3)))


def _det(m):
    """Determinant by the Leibniz formula (4x4)."""
    total = 0.0
    for p in permutations(range(4)):
        sign = 1
        for i in range(4):
            for j in range(i + 1, 4):
                if p[i] > p[j]:
                    sign = -sign
        prod = 1.0
        for i in range(4):
            prod *= m[i][p[i]]
        total += sign * prod
    return total


def quartic(p, e):
    """Coefficients f0..f4 of det(l P + E): each the sum of the determinants with k columns from P."""
    f = [0.0] * 5
    for k in range(5):
        for cols in combinations(range(4), k):
            f[k] += _det([[p[i][j] if j in cols else e[i][j] for j in range(4)] for i in range(4)])
    return f


def position_of_matrices(e, p):
    e4, d, c, b, a = quartic(p, e)  # f = a l^4 + b l^3 + c l^2 + d l + e4
    i = 12 * a * e4 - 3 * b * d + c * c
    j = 72 * a * c * e4 + 9 * b * c * d - 27 * a * d * d - 27 * e4 * b * b - 2 * c * c * c
    disc27 = 4 * i * i * i - j * j
    scale = max(abs(4 * i * i * i), j * j)
    coefficients = [e4, d, c, b, a]
    changes = sum((coefficients[k] < 0) != (coefficients[k + 1] < 0) for k in range(4))
    if abs(disc27) <= 1e-12 * scale:
        return "TE" if changes >= 2 else "TI"
    if disc27 < 0:
        return "C"
    return "E" if changes >= 2 else "I"


def position(centre, axes, e_rotation, vertex, a, b, p_rotation):
    """The position the paper's rule gives in doubles, from the parameters a float code holds."""
    return position_of_matrices(ellipsoid_matrix(centre, axes, e_rotation), paraboloid_matrix(vertex, a, b, p_rotation))
