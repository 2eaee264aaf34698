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


def paraboloid_patch(p, center, half_width, n=40):
    """Grid (X, Y, Z) of the paraboloid over a disc of radius half_width around `center`,
    measured across the axis (the patch near the ellipsoid)."""
    m = _float_matrix(p)
    A, b, b0 = m[:3, :3], m[:3, 3], m[3, 3]
    w, U = numpy.linalg.eigh(A)  # ascending: w[0] = 0 along the axis
    a1, a2 = w[1], w[2]
    bu = U.T @ b
    cu = U.T @ center
    r, t = numpy.meshgrid(numpy.linspace(0, half_width, n // 2), numpy.linspace(0, 2 * math.pi, n))
    y1 = cu[1] + r * numpy.cos(t)
    y2 = cu[2] + r * numpy.sin(t)
    # a1 y1^2 + a2 y2^2 + 2 (b0' y0 + b1' y1 + b2' y2) + b0 = 0, solved for y0 along the axis.
    y0 = -(a1 * y1**2 + a2 * y2**2 + 2 * bu[1] * y1 + 2 * bu[2] * y2 + b0) / (2 * bu[0])
    pts = numpy.einsum("ij,jkl->ikl", U, numpy.stack([y0, y1, y2]))
    return pts[0], pts[1], pts[2]


def plot(e, p, ax=None, classification=None, half_width=None, title=None):
    """Draw paraboloid `p` near ellipsoid `e` and the ellipsoid, titled with the exact position.

    ax: a 3D matplotlib axes (default: a new figure). classification: a relpos.Classification to
    use instead of classifying again. half_width: radius of the paraboloid patch across its axis
    (default: twice the largest semi-axis). Returns ax.
    """
    import matplotlib.pyplot as plt

    from . import POSITION_MEANINGS, classify

    c = classification if classification is not None else classify(e, p, evidence="minimal")
    if ax is None:
        fig = plt.figure(figsize=(5, 5))
        ax = fig.add_subplot(projection="3d")
    centre, semi, _ = ellipsoid_frame(e)
    h = half_width if half_width is not None else 2.0 * float(semi.max())
    X, Y, Z = paraboloid_patch(p, centre, h)
    ax.plot_surface(X, Y, Z, color="tab:blue", alpha=0.35, linewidth=0.2, edgecolor="tab:blue", shade=True)
    X2, Y2, Z2 = ellipsoid_surface(e)
    ax.plot_surface(X2, Y2, Z2, color="tab:orange", alpha=0.9, linewidth=0, shade=True)
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
    return ax
