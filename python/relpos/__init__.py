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
import operator as _operator

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
    "INVALID",
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


def _is_set(obj, slot):
    try:
        getattr(obj, slot)
    except AttributeError:
        return False
    return True


def _refuse_second_init(cls):
    """cls.__init__ raising TypeError on an object already built (pybind11 would ignore the call)."""
    built_init = cls.__init__

    def __init__(self, *args, **kwargs):
        if _relpos._is_built(self):
            raise TypeError("relpos.%s: the object is already built; make a new one" % cls.__name__)
        built_init(self, *args, **kwargs)

    __init__.__doc__ = built_init.__doc__
    cls.__init__ = __init__


def _rebuild(cls, texts):
    """Unpickles an Ellipsoid or Paraboloid (its __reduce__ names this function)."""
    return _relpos._rebuild(cls, texts)


_refuse_second_init(Ellipsoid)
_refuse_second_init(Paraboloid)


class Classification:
    """The answer for one pair, with its evidence: the fields of the JSON object `relpos batch` writes.

    Attributes: position ("I", "TI", "C", "TE" or "E", for an ellipsoid of any size), small,
    contact (True or False),
    rule (the deciding rule in one sentence), stage (which arithmetic settled it), rho_vs_one, rho.
    as_dict() returns every field.
    """

    __slots__ = ("_data",)

    def __init__(self, fields):
        if _is_set(self, "_data"):
            raise TypeError("relpos.Classification: the object is already built; make a new one")
        self._data = fields

    @property
    def _fields(self):
        if not _is_set(self, "_data"):
            raise TypeError("relpos.Classification: the object was made by __new__ without __init__ (not built)")
        return self._data

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
        if not isinstance(other, Classification):
            return NotImplemented
        return self._fields == other._fields

    __hash__ = None

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


#: The code decide_positions(..., errors="code") gives a pair it cannot read (no position uses it).
INVALID = _relpos._INVALID


def _thread_count(threads):
    if isinstance(threads, bool) or not hasattr(type(threads), "__index__"):
        raise TypeError("threads: expected a non-negative int, got %s" % type(threads).__name__)
    threads = _operator.index(threads)
    if threads < 0:
        raise ValueError("threads: expected a non-negative int, got %d" % threads)
    return threads


def decide_positions(E, P, threads=0, errors="raise"):
    """Positions of many pairs given as numpy matrices, exactly, on all cores.

    E: array (n, 4, 4) of ellipsoid matrices; P: array (n, 4, 4), or one (4, 4) matrix shared by all.
    Every entry is read exactly: float64, float32, float16, numpy.longdouble and integer arrays (of
    any width) as the numbers they hold; any other dtype raises TypeError. Returns a numpy int8 array
    of codes into POSITION_NAMES (0 = "I" ... 4 = "E"). threads=0 uses every core; the GIL is
    released while deciding. errors="raise" raises ValueError naming the first invalid matrix
    ("E[17]: ellipsoid: ..."); errors="code" gives such a pair the code INVALID (-1) instead.
    """
    if errors not in ("raise", "code"):
        raise ValueError("errors: expected 'raise' or 'code', got %r" % (errors,))
    return _relpos._decide_positions(E, P, _thread_count(threads), errors == "raise")


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
