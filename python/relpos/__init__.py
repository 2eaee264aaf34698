"""relpos: the exact relative position of an ellipsoid and an elliptic paraboloid.

The five positions are interior (I), tangent from inside (TI), crossing (C), tangent from outside
(TE) and exterior (E). Every number is taken exactly: int, fractions.Fraction and str ("p/q",
decimals such as "0.1" = 1/10) as the rational they denote, float as the exact dyadic value of the
double. doc/python.md describes the package.

    >>> import relpos
    >>> p = relpos.Paraboloid.standard((0, 0, 0), "1.2", "1.5")
    >>> e = relpos.Ellipsoid.sphere((0, "0.5", "92281/129600"), "1/4")
    >>> relpos.classify(e, p).position
    'I'
"""

import json as _json

from . import _cli, _relpos
from ._build import version as __version__
from ._relpos import Ellipsoid, Paraboloid

__all__ = [
    "Ellipsoid",
    "Paraboloid",
    "Classification",
    "classify",
    "decide_positions",
    "POSITION_NAMES",
    "POSITION_MEANINGS",
    "plot",
    "distributed",
    "__version__",
]

#: Position names, indexed by the codes decide_positions returns.
POSITION_NAMES = ("I", "TI", "C", "TE", "E")

#: What each position means.
POSITION_MEANINGS = {
    "I": "interior: the ellipsoid lies inside the paraboloid",
    "TI": "tangent from inside",
    "C": "crossing: the surfaces cross",
    "TE": "tangent from outside",
    "E": "exterior: the ellipsoid lies outside the paraboloid",
}


class Classification:
    """The answer for one pair, with its evidence: the fields of the JSON object `relpos batch` writes.

    Attributes: position ("I", "TI", "C", "TE" or "E", for an ellipsoid of any size), small,
    contact (True or False),
    rule (the deciding rule in one sentence), stage (which arithmetic settled it), rho_vs_one, rho.
    as_dict() returns every field.
    """

    __slots__ = ("_fields",)

    def __init__(self, fields):
        self._fields = fields

    position = property(lambda self: self._fields["position"])
    small = property(lambda self: self._fields["small"])
    contact = property(lambda self: self._fields["contact"])
    rule = property(lambda self: self._fields["rule"])
    stage = property(lambda self: self._fields["stage"])
    rho_vs_one = property(lambda self: self._fields["rho_vs_one"])
    rho = property(lambda self: self._fields["rho"])

    def as_dict(self):
        """All fields, as in the CLI's JSON (without "id"); a fresh copy."""
        return _json.loads(_json.dumps(self._fields))

    def __eq__(self, other):
        return isinstance(other, Classification) and self._fields == other._fields

    def __repr__(self):
        return "relpos.Classification(position=%r, small=%r, contact=%r, stage=%r)" % (
            self.position,
            self.small,
            self.contact,
            self.stage,
        )


def classify(e, p, evidence="full"):
    """Classify ellipsoid `e` against paraboloid `p` exactly.

    evidence="full" gives the same fields as `relpos batch` / `relpos classify --json` (exact
    coefficients of f and s, multiple roots, rho); "minimal" only what the decision needs.
    Raises ValueError on bad input (with the CLI's message).
    """
    if not isinstance(e, Ellipsoid):
        raise TypeError("classify: e must be a relpos.Ellipsoid, got %s" % type(e).__name__)
    if not isinstance(p, Paraboloid):
        raise TypeError("classify: p must be a relpos.Paraboloid, got %s" % type(p).__name__)
    if evidence not in ("full", "minimal"):
        raise ValueError("evidence: expected 'full' or 'minimal', got %r" % (evidence,))
    return Classification(_json.loads(_relpos._classify_json(e, p, evidence == "full")))


def _float64_array(a, name):
    import numpy

    a = numpy.asarray(a)
    if a.dtype != numpy.float64:
        if a.dtype.kind not in "iuf":
            raise ValueError("%s: expected a float64 array, got dtype %s" % (name, a.dtype))
        converted = a.astype(numpy.float64)
        if a.dtype.kind in "iu" and not numpy.array_equal(converted.astype(a.dtype), a):
            raise ValueError("%s: integer entries not exactly representable as float64" % name)
        a = converted
    return numpy.ascontiguousarray(a)


def decide_positions(E, P, threads=0):
    """Positions of many pairs given as float64 matrices, exactly, on all cores.

    E: array (n, 4, 4) of ellipsoid matrices; P: array (n, 4, 4), or one (4, 4) matrix shared by all.
    Each double is taken as its exact value. Returns a numpy int8 array of codes into
    POSITION_NAMES (0 = "I" ... 4 = "E"). threads=0 uses every core; the GIL is released while deciding.
    Raises ValueError naming the index of an invalid matrix ("E[17]: ellipsoid: ...").
    """
    return _relpos._decide_positions(_float64_array(E, "E"), _float64_array(P, "P"), int(threads))


def plot(e, p, ax=None, **kwargs):
    """Draw the pair (matplotlib 3D axes) titled with its position; returns the axes. See relpos._plot."""
    from ._plot import plot as _plot

    return _plot(e, p, ax=ax, **kwargs)


def __getattr__(name):
    # relpos.distributed is imported on first use (it imports dask.distributed, which is slow).
    if name == "distributed":
        import importlib

        return importlib.import_module(".distributed", __name__)
    raise AttributeError("module 'relpos' has no attribute %r" % name)
