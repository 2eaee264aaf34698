"""relpos.plot: a picture of a pair (matplotlib, 3D axes).

Any pair the library decides can be drawn, whatever its scale (a sphere of radius 1e-160 at the
vertex, a sphere at height 1e160): the geometry is computed in a frame centred on the ellipsoid and
measured in units of its size, x = c + s u, from the exact matrices (fractions), and only then
turned into floating point, so no intermediate overflows or underflows. The axes show x, y, z when
those floats can be drawn as they are; otherwise they show u, labelled with the centre c and the
unit s.
"""

import math
from decimal import Context, Decimal
from fractions import Fraction

import numpy

from . import _quadric_surface

#: Half the width of the view around the ellipsoid when the cup is not drawn whole, in its size.
_WINDOW = 3.0


class PlotError(ValueError):
    """The pair cannot be drawn in floating point (the message says why)."""


def _log2(q):
    """About log2 |q| for a non-zero Fraction (an integer, within 1)."""
    return abs(q.numerator).bit_length() - q.denominator.bit_length()


def _ratio(a, b):
    """The float a / b of two Fractions, b != 0; 0.0 when it underflows, +-inf when it overflows."""
    q = a / b
    if q == 0:
        return 0.0
    e = _log2(q)
    if e > 1023:
        return math.copysign(math.inf, q)
    if e < -1080:
        return 0.0
    return float(q)


def _text(q):
    """A short decimal text of a Fraction of any size ("1.5e+160")."""
    if q == 0:
        return "0"
    d = Context(prec=4).divide(Decimal(q.numerator), Decimal(q.denominator))
    return "%s" % d.normalize(Context(prec=4))


def _solve3(m, v):
    """m^-1 v for a 3x3 matrix of Fractions (Cramer's rule)."""

    def det(a):
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))

    d = det(m)
    out = []
    for k in range(3):
        a = [[v[i] if j == k else m[i][j] for j in range(3)] for i in range(3)]
        out.append(det(a) / d)
    return out


def _normalized(rows):
    """A matrix of Fractions divided by its largest entry, as floats, and that entry."""
    top = max(abs(x) for row in rows for x in row)
    return numpy.array([[_ratio(x, top) for x in row] for row in rows]), top


class _Frame:
    """The pair in the frame x = c + s u of the ellipsoid (c its centre, s a power of two near its
    largest semi-axis), every number computed exactly before it becomes a float."""

    def __init__(self, e, p):
        E = e.matrix()
        M = [row[:3] for row in E[:3]]
        b = [E[i][3] for i in range(3)]
        self.c = [-x for x in _solve3(M, b)]  # the centre: M c = -b
        k = -(sum(b[i] * self.c[i] for i in range(3)) + E[3][3])  # (x - c)^T M (x - c) = k
        Mn, m = _normalized(M)
        w, V = numpy.linalg.eigh(Mn)  # M = m V diag(w) V^T
        if not (numpy.all(numpy.isfinite(w)) and w.min() > 0):
            raise PlotError("plot: the ellipsoid's axes are too unequal to draw in floating point")
        # semi-axis_i^2 = (k / m) / w_i; s = 2^j near the largest one.
        km = k / m
        j = (_log2(km) - math.floor(math.log2(w.min()))) // 2
        self.s = Fraction(2) ** j
        self.semi = numpy.sqrt(_ratio(km, self.s * self.s) / w)  # in units of s
        self.axes = V
        if not numpy.all(numpy.isfinite(self.semi)):
            raise PlotError("plot: the ellipsoid's axes are too unequal to draw in floating point")
        if p is not None:
            self._paraboloid(p)

    def local(self, P):
        """The second body's q(x) = x^T A x + 2 b^T x + d in u, as floats: (An, quad, lin, h) with
        q / scale = quad u^T An u + lin^T u + h, An = A / (its largest entry) (None when A = 0) and
        scale the largest term; the small terms may become 0 (negligible at this scale)."""
        A = [row[:3] for row in P[:3]]
        bp = [P[i][3] for i in range(3)]
        g = [sum(A[i][j] * self.c[j] for j in range(3)) + bp[i] for i in range(3)]
        h = sum(self.c[i] * (g[i] + bp[i]) for i in range(3)) + P[3][3]
        if any(x != 0 for row in A for x in row):
            An, a = _normalized(A)
        else:
            An, a = None, Fraction(0)
        quad = self.s * self.s * a
        scale = max([abs(quad)] + [abs(2 * self.s * x) for x in g] + [abs(h)])
        lin = numpy.array([_ratio(2 * self.s * x, scale) for x in g])
        return An, _ratio(quad, scale), lin, _ratio(h, scale)

    def _paraboloid(self, p):
        # The paraboloid in u: s^2 u^T A u + 2 s g^T u + h = 0 with g = A c + b_P, h = P(c).
        An, quad, lin, self.h = self.local(p.matrix())
        wa, U = numpy.linalg.eigh(An)  # ascending: wa[0] = 0 along the axis
        self.U = U
        self.a = wa[1:] * quad  # y0 along the axis, y1, y2 across it
        self.l = U.T @ lin
        if self.l[0] == 0 or not numpy.all(numpy.isfinite(self.l)):
            raise PlotError("plot: the paraboloid is too far from the ellipsoid, for its size, to draw in floating point")

    def ellipsoid(self, n=40):
        """Grid (X, Y, Z) of the ellipsoid surface, in u."""
        t, v = numpy.meshgrid(numpy.linspace(0, 2 * math.pi, n), numpy.linspace(0, math.pi, n // 2))
        unit = numpy.stack([numpy.cos(t) * numpy.sin(v), numpy.sin(t) * numpy.sin(v), numpy.cos(v)])
        pts = numpy.einsum("ij,jkl->ikl", self.axes @ numpy.diag(self.semi), unit)
        return pts[0], pts[1], pts[2]

    def _on_surface(self, y1, y2):
        """The paraboloid's points over (y1, y2) across its axis, in u."""
        y0 = -(self.a[0] * y1**2 + self.a[1] * y2**2 + self.l[1] * y1 + self.l[2] * y2 + self.h) / self.l[0]
        pts = numpy.einsum("ij,jkl->ikl", self.U, numpy.stack([y0, y1, y2]))
        return pts[0], pts[1], pts[2]

    def cup(self, n=40):
        """The cup from its vertex to just past the ellipsoid, in u, or None when the whole cup would
        dwarf the ellipsoid (or cannot be computed at this scale)."""
        if min(self.a) <= 0:
            return None
        with numpy.errstate(all="ignore"):
            v1, v2 = -self.l[1] / (2 * self.a[0]), -self.l[2] / (2 * self.a[1])  # the vertex across the axis
            y0v = -(self.h - self.a[0] * v1**2 - self.a[1] * v2**2) / self.l[0]
            opening = -math.copysign(1.0, self.l[0])  # y0 grows inside the cup
            reach = math.sqrt(float(self.U[:, 0] @ self.axes @ numpy.diag(self.semi**2) @ self.axes.T @ self.U[:, 0]))
            size = float(self.semi.max())
            depth = max(opening * (0.0 - y0v) + reach + 0.3 * size, 1.5 * size)  # the centre is u = 0
            rim = math.sqrt(abs(self.l[0]) * depth / min(self.a))
            off_axis = math.hypot(v1, v2)
        if not all(map(math.isfinite, (v1, v2, y0v, depth, rim))) or rim > 10 * size + 2 * off_axis:
            return None
        r, t = numpy.meshgrid(numpy.linspace(0, math.sqrt(abs(self.l[0]) * depth), n // 2),
                              numpy.linspace(0, 2 * math.pi, n))
        return self._on_surface(v1 + r * numpy.cos(t) / numpy.sqrt(self.a[0]),
                                v2 + r * numpy.sin(t) / numpy.sqrt(self.a[1]))

    def patch(self, half_width, n=40):
        """The paraboloid over a disc of radius half_width (in u) around the ellipsoid's centre, across
        the axis; the points farther than the view along the axis are left out (NaN)."""
        r, t = numpy.meshgrid(numpy.linspace(0, half_width, n // 2), numpy.linspace(0, 2 * math.pi, n))
        X, Y, Z = self._on_surface(r * numpy.cos(t), r * numpy.sin(t))
        far = (numpy.abs(X) > half_width) | (numpy.abs(Y) > half_width) | (numpy.abs(Z) > half_width)
        for a in (X, Y, Z):
            a[far] = numpy.nan
        return X, Y, Z

    def world(self):
        """(offset, unit) floats mapping u to x = offset + unit u, when they draw faithfully; None
        otherwise: the centre too far for the size, or a unit whose fourth power leaves floating
        point (matplotlib's shading multiplies four coordinate differences)."""
        s = float(self.s) if -1000 < _log2(self.s) < 1000 else 0.0
        if not 1e-50 < s < 1e50:
            return None
        if any(x != 0 and _log2(x / self.s) > 40 for x in self.c):  # x = c + s u would lose u's digits
            return None
        return numpy.array([float(x) for x in self.c]), s


def plot(e, p, ax=None, classification=None, half_width=None, title=None, max_bits=None):
    """Draw paraboloid (or relpos.Quadric) `p` near ellipsoid `e` and the ellipsoid, titled with the
    exact position.

    ax: a 3D matplotlib axes (default: a new figure). classification: a relpos.Classification (a
    relpos.QuadricClassification for a Quadric) to use instead of classifying again (max_bits: the
    size limit of that classification). half_width: radius of the paraboloid patch across its axis,
    or half the side of the box around the ellipsoid a Quadric is drawn in (default: three times the
    largest semi-axis). Returns ax. Raises relpos._plot.PlotError (a ValueError) saying why when the
    pair cannot be drawn in floating point (axes of the ellipsoid differing by hundreds of orders of
    magnitude, a paraboloid too far for its size; a Quadric too far is left out of the view, and the
    title says so).
    """
    import matplotlib.pyplot as plt

    from . import MAX_BITS, POSITION_MEANINGS, Quadric, classify

    c = classification
    if c is None:
        c = classify(e, p, evidence="minimal", max_bits=MAX_BITS if max_bits is None else max_bits)
    general = isinstance(p, Quadric)
    frame = _Frame(e, None if general else p)
    world = frame.world()
    h = _WINDOW * float(frame.semi.max())
    if half_width is not None:
        h = half_width / world[1] if world else half_width
    if general:
        sheets = _quadric_surface.surfaces(p.type, frame.local(p.matrix()), h)
    else:
        cup = frame.cup() if half_width is None else None
        sheets = [cup if cup is not None else frame.patch(h)]  # the whole cup, from the vertex to past the ellipsoid
    X2, Y2, Z2 = frame.ellipsoid()
    if world is not None:  # x = offset + unit u
        (ox, oy, oz), unit = world
        sheets = [(ox + unit * X, oy + unit * Y, oz + unit * Z) for X, Y, Z in sheets]
        X2, Y2, Z2 = ox + unit * X2, oy + unit * Y2, oz + unit * Z2
    if ax is None:
        fig = plt.figure(figsize=(5, 5))
        ax = fig.add_subplot(projection="3d")
    pts = [numpy.stack([a.ravel() for a in (X2, Y2, Z2)])]
    for X, Y, Z in sheets:
        shown = numpy.isfinite(Z)
        pts.insert(-1, numpy.stack([a[shown] for a in (X, Y, Z)]))
        if shown.any():
            # A quadric's sheet too small for the view (an ellipsoid 10^-150 the size of the ball) has
            # normals that underflow: drawn unshaded.
            shade = not general or numpy.ptp(pts[-2], axis=1).max() > 1e-6 * numpy.ptp(pts[-1], axis=1).max()
            ax.plot_surface(X, Y, Z, color="tab:blue", alpha=0.3, linewidth=0.3, edgecolor="navy", shade=bool(shade))
    shown = any(pt.shape[1] for pt in pts[:-1])
    ax.plot_surface(X2, Y2, Z2, color="tab:orange", alpha=0.6, linewidth=0, shade=True)
    pts = numpy.concatenate(pts, axis=1)
    lo, hi = pts.min(axis=1), pts.max(axis=1)
    span = hi - lo
    span = numpy.maximum(span, 1e-9 * max(span.max(), numpy.abs(pts).max()) or 1.0)
    ax.set_xlim(lo[0], lo[0] + span[0])
    ax.set_ylim(lo[1], lo[1] + span[1])
    ax.set_zlim(lo[2], lo[2] + span[2])
    ax.set_box_aspect(tuple(span / span.max()))
    if world is not None:
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
    else:
        unit = _text(frame.s)
        for axis, name, centre in zip((ax.set_xlabel, ax.set_ylabel, ax.set_zlabel), "xyz", frame.c):
            axis("(%s - %s) / %s" % (name, _text(centre), unit), fontsize=7)
    body = "the %s" % p.type if general else "the paraboloid"
    if title is None:
        if general:
            title = "%s: %s, %s" % (c.position, p.type, c.contact)
        else:
            title = "%s: %s" % (c.position, POSITION_MEANINGS.get(c.position, c.rule))
        if not shown:
            title += "\n(%s lies outside this view of the ellipsoid)" % body
    ax.set_title(title)
    ax.tick_params(labelsize=7)
    return ax
