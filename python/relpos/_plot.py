"""relpos.plot: a picture of a pair (matplotlib, 3D axes)."""

import math

import numpy


def _float_matrix(q):
    return numpy.array([[float(x) for x in row] for row in q.matrix()], dtype=float)


def ellipsoid_frame(e):
    """(centre, semi-axes, axes as columns) of an Ellipsoid, in floating point (for drawing)."""
    m = _float_matrix(e)
    M, v, v0 = m[:3, :3], m[:3, 3], m[3, 3]
    c = -numpy.linalg.solve(M, v)
    k = c @ M @ c - v0
    w, V = numpy.linalg.eigh(M)
    return c, numpy.sqrt(k / w), V


def ellipsoid_surface(e, n=40):
    """Grid (X, Y, Z) of the ellipsoid surface."""
    c, semi, V = ellipsoid_frame(e)
    u, t = numpy.meshgrid(numpy.linspace(0, 2 * math.pi, n), numpy.linspace(0, math.pi, n // 2))
    unit = numpy.stack([numpy.cos(u) * numpy.sin(t), numpy.sin(u) * numpy.sin(t), numpy.cos(t)])
    pts = numpy.einsum("ij,jkl->ikl", V @ numpy.diag(semi), unit) + c[:, None, None]
    return pts[0], pts[1], pts[2]


def _paraboloid_frame(p):
    """Eigen-frame of a paraboloid: (U, a1, a2, b) with U's first column along the axis (A = U diag(0,
    a1, a2) U^T) and b = U^T (the last column's first three entries)."""
    m = _float_matrix(p)
    A, b = m[:3, :3], m[:3, 3]
    w, U = numpy.linalg.eigh(A)  # ascending: w[0] = 0 along the axis
    return U, w[1], w[2], U.T @ b, m[3, 3]


def paraboloid_patch(p, center, half_width, n=40):
    """Grid (X, Y, Z) of the paraboloid over a disc of radius half_width around `center`,
    measured across the axis."""
    U, a1, a2, bu, b0 = _paraboloid_frame(p)
    cu = U.T @ center
    r, t = numpy.meshgrid(numpy.linspace(0, half_width, n // 2), numpy.linspace(0, 2 * math.pi, n))
    y1 = cu[1] + r * numpy.cos(t)
    y2 = cu[2] + r * numpy.sin(t)
    # a1 y1^2 + a2 y2^2 + 2 (b0' y0 + b1' y1 + b2' y2) + b0 = 0, solved for y0 along the axis.
    y0 = -(a1 * y1**2 + a2 * y2**2 + 2 * bu[1] * y1 + 2 * bu[2] * y2 + b0) / (2 * bu[0])
    pts = numpy.einsum("ij,jkl->ikl", U, numpy.stack([y0, y1, y2]))
    return pts[0], pts[1], pts[2]


def paraboloid_cup(p, depth, n=40):
    """Grid (X, Y, Z) of the cup of the paraboloid from its vertex to `depth` along its axis."""
    U, a1, a2, bu, b0 = _paraboloid_frame(p)
    # With u_i = y_i + b_i'/a_i: y0 = y0v + s^2 / (-2 b0') where s^2 = a1 u1^2 + a2 u2^2.
    v1, v2 = -bu[1] / a1, -bu[2] / a2
    y0v = -(b0 - bu[1] ** 2 / a1 - bu[2] ** 2 / a2) / (2 * bu[0])
    s, t = numpy.meshgrid(numpy.linspace(0, math.sqrt(2 * abs(bu[0]) * depth), n // 2), numpy.linspace(0, 2 * math.pi, n))
    y1 = v1 + s * numpy.cos(t) / math.sqrt(a1)
    y2 = v2 + s * numpy.sin(t) / math.sqrt(a2)
    y0 = y0v - s**2 / (2 * bu[0])
    pts = numpy.einsum("ij,jkl->ikl", U, numpy.stack([y0, y1, y2]))
    return pts[0], pts[1], pts[2]


def _cup_depth(p, e):
    """Depth (along the axis, from the vertex) that the cup needs to reach past the ellipsoid, the
    cup's rim radius across the axis at that depth, and the ellipsoid centre's distance from the axis."""
    U, a1, a2, bu, b0 = _paraboloid_frame(p)
    c, semi, V = ellipsoid_frame(e)
    size = float(semi.max())
    axis = U[:, 0]
    opening = -math.copysign(1.0, bu[0])  # y0 grows with s^2 when b0' < 0
    y0v = -(b0 - bu[1] ** 2 / a1 - bu[2] ** 2 / a2) / (2 * bu[0])
    reach = math.sqrt(float(axis @ V @ numpy.diag(semi**2) @ V.T @ axis))  # ellipsoid extent along the axis
    top = opening * (float(axis @ c) - y0v) + reach
    depth = max(top + 0.3 * size, 1.5 * size)
    rim = math.sqrt(2 * abs(bu[0]) * depth / min(a1, a2))
    across = U[:, 1:].T @ c - numpy.array([-bu[1] / a1, -bu[2] / a2])
    return depth, rim, float(numpy.linalg.norm(across))


def plot(e, p, ax=None, classification=None, half_width=None, title=None):
    """Draw paraboloid `p` near ellipsoid `e` and the ellipsoid, titled with the exact position.

    ax: a 3D matplotlib axes (default: a new figure). classification: a relpos.Classification to
    use instead of classifying again. half_width: radius of the paraboloid patch across its axis
    (default: three times the largest semi-axis). Returns ax.
    """
    import matplotlib.pyplot as plt

    from . import POSITION_MEANINGS, classify

    c = classification if classification is not None else classify(e, p, evidence="minimal")
    if ax is None:
        fig = plt.figure(figsize=(5, 5))
        ax = fig.add_subplot(projection="3d")
    centre, semi, _ = ellipsoid_frame(e)
    depth, rim, off_axis = _cup_depth(p, e)
    if half_width is None and rim <= 10 * float(semi.max()) + 2 * off_axis:
        X, Y, Z = paraboloid_cup(p, depth)  # the whole cup, from the vertex to past the ellipsoid
    else:
        h = half_width if half_width is not None else 3.0 * float(semi.max())
        X, Y, Z = paraboloid_patch(p, centre, h)
    ax.plot_surface(X, Y, Z, color="tab:blue", alpha=0.3, linewidth=0.3, edgecolor="navy", shade=True)
    X2, Y2, Z2 = ellipsoid_surface(e)
    ax.plot_surface(X2, Y2, Z2, color="tab:orange", alpha=0.6, linewidth=0, shade=True)
    pts = numpy.concatenate([numpy.stack([a.ravel() for a in (X, Y, Z)]), numpy.stack([a.ravel() for a in (X2, Y2, Z2)])], axis=1)
    lo, hi = pts.min(axis=1), pts.max(axis=1)
    span = numpy.maximum(hi - lo, 1e-9 * max(1.0, float(numpy.abs(pts).max())))
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(tuple(span))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    if title is None:
        title = "%s: %s" % (c.position, POSITION_MEANINGS.get(c.position, c.rule))
    ax.set_title(title)
    ax.tick_params(labelsize=7)
    return ax
