"""relpos: the exact relative position of an ellipsoid and an elliptic paraboloid.

The five positions are interior (I), tangent from inside (TI), crossing (C), tangent from outside
(TE) and exterior (E). Every number is taken exactly: int, fractions.Fraction, decimal.Decimal and
str ("p/q", decimals such as "0.1" = 1/10) as the rational they denote, float and numpy floats as
the exact dyadic value they hold. doc/python.md describes the package.

    >>> import relpos
    >>> p = relpos.Paraboloid.standard((0, 0, 0), "1.2", "1.5")
    >>> e = relpos.Ellipsoid.sphere((0, "0.5", "92281/129600"), "1/4")
    >>> relpos.classify(e, p).position
    'I'
"""

import collections.abc as _abc
import json as _json
import math as _math
import operator as _operator
from decimal import Decimal
from fractions import Fraction
from typing import Any, Literal, Mapping, Optional, Sequence, Union

import numpy

from . import _cli, _relpos
from ._build import version as __version__
from ._relpos import Ellipsoid, FirstContact, Instant, Paraboloid, Quadric, Timeline

__all__ = [
    "Ellipsoid",
    "Paraboloid",
    "Quadric",
    "Classification",
    "QuadricClassification",
    "Certificate",
    "CertificateError",
    "Margin",
    "ContactAnswer",
    "SceneResult",
    "Instant",
    "FirstContact",
    "Timeline",
    "classify",
    "verify",
    "contact",
    "decide_positions",
    "scene",
    "first_contact",
    "timeline",
    "POSITION_NAMES",
    "POSITION_MEANINGS",
    "QUADRIC_POSITION_NAMES",
    "QUADRIC_TYPES",
    "STAGE_NAMES",
    "INVALID",
    "MAX_BITS",
    "plot",
    "distributed",
    "testing",
    "__version__",
]

#: An exact number: int, float (its exact dyadic value), Fraction, Decimal, numpy scalar or str
#: ("p/q", "-3", "0.1" = 1/10, "1.5e-7").
Number = Union[int, float, Fraction, Decimal, numpy.number, str]
#: Three numbers (a point or a vector).
Vector3 = Union[Sequence[Number], numpy.ndarray]
#: A 4x4 (or 3x3) matrix: nested sequences of numbers or a numpy array.
Matrix = Union[Sequence[Sequence[Number]], numpy.ndarray]
#: A quadric as the CLI reads it: a 4x4 matrix, or a dict in one of its JSON forms (doc/cli.md).
Description = Union[Matrix, Mapping[str, Any]]
#: A polynomial in time t: its coefficients, lowest degree first (or one number: a constant).
TimePolynomial = Union[Sequence[Number], Number]

#: Position names, indexed by the codes decide_positions and scene return.
POSITION_NAMES = ("I", "TI", "C", "TE", "E")

#: Position names of a general pair (relpos.Quadric), indexed by the codes decide_positions returns for
#: one: the five of POSITION_NAMES, then O, TO and EQ (the quadric an ellipsoid inside the ellipsoid,
#: inside and touching, the same ellipsoid).
QUADRIC_POSITION_NAMES = ("I", "TI", "C", "TE", "E", "O", "TO", "EQ")

#: The eleven types of relpos.Quadric, as Quadric.type names them.
QUADRIC_TYPES = (
    "ellipsoid",
    "hyperboloid of one sheet",
    "hyperboloid of two sheets",
    "elliptic cone",
    "elliptic paraboloid",
    "hyperbolic paraboloid",
    "elliptic cylinder",
    "hyperbolic cylinder",
    "parabolic cylinder",
    "slab",
    "half-space",
)

#: Stage names (what settled a scene body), indexed by the stage codes scene returns.
STAGE_NAMES = _relpos._STAGE_NAMES

#: What each position means.
POSITION_MEANINGS = {
    "I": "interior: the ellipsoid lies inside the paraboloid",
    "TI": "tangent from inside",
    "C": "crossing: the surfaces cross",
    "TE": "tangent from outside",
    "E": "exterior: the ellipsoid lies outside the paraboloid",
}

#: The code decide_positions(..., errors="code") gives a pair it cannot read (no position uses it).
INVALID = _relpos._INVALID


# ------------------------------------------------------------------------------------------------
# Ellipsoid and Paraboloid: the compiled classes, with typed Python methods. Each constructor hands
# a JSON form of the CLI to the compiled reader, so every number and every message is the CLI's.
# ------------------------------------------------------------------------------------------------


def _method(cls, name):
    def attach(function):
        inner = function.__func__ if isinstance(function, staticmethod) else function
        inner.__qualname__ = "%s.%s" % (cls.__name__, name)  # help() shows the public name
        inner.__name__ = name
        setattr(cls, name, function)
        return function

    return attach


def _define_quadric_methods(cls, role):
    built_init = cls.__init__
    built_matrix = cls._matrix

    @_method(cls, "__init__")
    def __init__(self, description: Description) -> None:
        if _relpos._is_built(self):
            raise TypeError("relpos.%s: the object is already built; make a new one" % cls.__name__)
        built_init(self, description)

    __init__.__doc__ = (
        "The %s a 4x4 symmetric matrix (nested sequences or a numpy array) describes, X^T m X = 0 with\n"
        "X = (x, y, z, 1), or a dict in any JSON form of the CLI (doc/cli.md, \"Quadric formats\").\n"
        "Raises ValueError with the CLI's message when it is not one, TypeError for an entry that is\n"
        "not a number." % role
    )

    @_method(cls, "matrix")
    def matrix(self) -> list:
        """The validated, sign-normalized matrix (inside is negative): 4 lists of 4 fractions.Fraction."""
        return built_matrix(self)

    def from_coefficients(coefficients: Sequence[Number]) -> cls:
        """From A..J of A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0."""
        return cls({"coefficients": coefficients})

    _method(cls, "from_coefficients")(staticmethod(from_coefficients))
    cls.__module__ = "relpos"


_define_quadric_methods(Ellipsoid, "ellipsoid")
_define_quadric_methods(Paraboloid, "paraboloid")
_define_quadric_methods(Quadric, "quadric")


@_method(Ellipsoid, "sphere")
@staticmethod
def _sphere(center: Vector3, radius: Number) -> Ellipsoid:
    """The sphere |x - center| = radius."""
    return Ellipsoid({"sphere": {"center": center, "radius": radius}})


@_method(Ellipsoid, "from_axes")
@staticmethod
def _from_axes(center: Vector3, axes: Vector3, rotation: Union[Sequence[Number], Matrix] = (1, 0, 0, 0)) -> Ellipsoid:
    """Semi-axes `axes` along the columns of a rotation: the quaternion q = (w, x, y, z) (R(q)/|q|^2,
    q need not be a unit) or an exactly orthogonal 3x3 matrix."""
    key = "rotation" if len(rotation) == 4 else "rotation_matrix"
    return Ellipsoid({"center": center, "axes": axes, key: rotation})


@_method(Ellipsoid, "from_map")
@staticmethod
def _ellipsoid_from_map(center: Vector3, linear: Matrix) -> Ellipsoid:
    """The image of the unit ball under x = center + L u (L an invertible 3x3 matrix)."""
    return Ellipsoid({"center": center, "map": linear})


@_method(Paraboloid, "standard")
@staticmethod
def _standard(vertex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = (1, 0, 0, 0)) -> Paraboloid:
    """x'^2/a^2 + y'^2/b^2 = z' in the frame with origin `vertex` and axes the columns of R(q)/|q|^2
    of the quaternion q = (w, x, y, z) (the cup opens along the third column)."""
    return Paraboloid({"vertex": vertex, "a": a, "b": b, "rotation": rotation})


@_method(Paraboloid, "from_map")
@staticmethod
def _paraboloid_from_map(linear: Matrix, translation: Vector3) -> Paraboloid:
    """The image of z = x^2 + y^2 under x = T u + t (T an invertible 3x3 matrix)."""
    return Paraboloid({"map": linear, "translation": translation})


# Quadric: any real quadric (doc/quadrics.md); the geometric forms are the dicts of a batch line's
# "quadric" (doc/cli.md, "General quadrics"), read by the CLI's reader.

Quadric.type = property(lambda self: self._type(), doc="The type's name, one of QUADRIC_TYPES.")

_IDENTITY = (1, 0, 0, 0)


@_method(Quadric, "sphere")
@staticmethod
def _quadric_sphere(center: Vector3, radius: Number) -> Quadric:
    """The ball |x - center| <= radius."""
    return Quadric({"type": "sphere", "center": center, "radius": radius})


@_method(Quadric, "ellipsoid")
@staticmethod
def _quadric_ellipsoid(center: Vector3, axes: Vector3, rotation: Sequence[Number] = _IDENTITY) -> Quadric:
    """x'^2/a^2 + y'^2/b^2 + z'^2/c^2 <= 1, axes = (a, b, c). The frame: origin at the first point, axes
    the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "ellipsoid", "center": center, "axes": axes, "rotation": rotation})


@_method(Quadric, "hyperboloid_one_sheet")
@staticmethod
def _quadric_hyperboloid_one_sheet(
    center: Vector3, axes: Vector3, rotation: Sequence[Number] = _IDENTITY,
) -> Quadric:
    """x'^2/a^2 + y'^2/b^2 - z'^2/c^2 <= 1, axes = (a, b, c): the region around the axis. The frame: origin
    at the first point, axes the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "hyperboloid of one sheet", "center": center, "axes": axes, "rotation": rotation})


@_method(Quadric, "hyperboloid_two_sheets")
@staticmethod
def _quadric_hyperboloid_two_sheets(
    center: Vector3, axes: Vector3, rotation: Sequence[Number] = _IDENTITY,
) -> Quadric:
    """x'^2/a^2 + y'^2/b^2 - z'^2/c^2 <= -1, axes = (a, b, c): the two caps. The frame: origin at the first
    point, axes the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "hyperboloid of two sheets", "center": center, "axes": axes, "rotation": rotation})


@_method(Quadric, "cone")
@staticmethod
def _quadric_cone(apex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = _IDENTITY) -> Quadric:
    """x'^2/a^2 + y'^2/b^2 <= z'^2: the double cone around the axis, apex at `apex`. The frame: origin at
    the first point, axes the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "elliptic cone", "apex": apex, "a": a, "b": b, "rotation": rotation})


@_method(Quadric, "elliptic_paraboloid")
@staticmethod
def _quadric_elliptic_paraboloid(
    vertex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = _IDENTITY,
) -> Quadric:
    """x'^2/a^2 + y'^2/b^2 <= z': inside the cup (as Paraboloid.standard). The frame: origin at the first
    point, axes the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "elliptic paraboloid", "vertex": vertex, "a": a, "b": b, "rotation": rotation})


@_method(Quadric, "hyperbolic_paraboloid")
@staticmethod
def _quadric_hyperbolic_paraboloid(
    vertex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = _IDENTITY,
) -> Quadric:
    """x'^2/a^2 - y'^2/b^2 <= z'. The frame: origin at the first point, axes the columns of R(q)/|q|^2 of
    the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "hyperbolic paraboloid", "vertex": vertex, "a": a, "b": b, "rotation": rotation})


@_method(Quadric, "elliptic_cylinder")
@staticmethod
def _quadric_elliptic_cylinder(
    center: Vector3, a: Number, b: Number, rotation: Sequence[Number] = _IDENTITY,
) -> Quadric:
    """x'^2/a^2 + y'^2/b^2 <= 1: the tube along the frame's z axis. The frame: origin at the first point,
    axes the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "elliptic cylinder", "center": center, "a": a, "b": b, "rotation": rotation})


@_method(Quadric, "hyperbolic_cylinder")
@staticmethod
def _quadric_hyperbolic_cylinder(
    center: Vector3, a: Number, b: Number, rotation: Sequence[Number] = _IDENTITY,
) -> Quadric:
    """x'^2/a^2 - y'^2/b^2 <= 1: the connected middle, along the frame's z axis. The frame: origin at the
    first point, axes the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "hyperbolic cylinder", "center": center, "a": a, "b": b, "rotation": rotation})


@_method(Quadric, "parabolic_cylinder")
@staticmethod
def _quadric_parabolic_cylinder(vertex: Vector3, a: Number, rotation: Sequence[Number] = _IDENTITY) -> Quadric:
    """x'^2/a^2 <= z': the convex side, ruled along the frame's y axis. The frame: origin at the first
    point, axes the columns of R(q)/|q|^2 of the quaternion rotation = (w, x, y, z)."""
    return Quadric({"type": "parabolic cylinder", "vertex": vertex, "a": a, "rotation": rotation})


@_method(Quadric, "half_space")
@staticmethod
def _quadric_half_space(normal: Vector3, offset: Number) -> Quadric:
    """{x : normal . x <= offset} (normal != 0)."""
    return Quadric({"type": "half-space", "normal": normal, "offset": offset})


@_method(Quadric, "slab")
@staticmethod
def _quadric_slab(normal: Vector3, low: Number, high: Number) -> Quadric:
    """{x : low <= normal . x <= high} (normal != 0, low < high)."""
    return Quadric({"type": "slab", "normal": normal, "low": low, "high": high})


@_method(Quadric, "of")
@staticmethod
def _quadric_of(body: Union[Ellipsoid, Paraboloid]) -> Quadric:
    """The same solid as a relpos.Ellipsoid or relpos.Paraboloid, as a Quadric (its exact matrix)."""
    if not isinstance(body, (Ellipsoid, Paraboloid)):
        raise TypeError("Quadric.of: body must be a relpos.Ellipsoid or relpos.Paraboloid, got %s"
                        % type(body).__name__)
    return Quadric(body.matrix())


def _rebuild(cls, texts):
    """Unpickles an Ellipsoid, Paraboloid or Quadric (its __reduce__ names this function)."""
    return _relpos._rebuild(cls, texts)


# ------------------------------------------------------------------------------------------------
# Answers: plain Python objects over the CLI's JSON objects.
# ------------------------------------------------------------------------------------------------


class _Answer:
    """Read-only fields of one of the CLI's JSON answers."""

    __slots__ = ("_data",)

    def __init__(self, fields: Mapping[str, Any]) -> None:
        """From the fields of the CLI's JSON answer (as classify / contact return them)."""
        if _is_set(self, "_data"):
            raise TypeError("relpos.%s: the object is already built; make a new one" % type(self).__name__)
        if not isinstance(fields, _abc.Mapping) or not all(isinstance(k, str) for k in fields):
            raise TypeError(
                "relpos.%s: fields: expected a mapping of str keys (the CLI's JSON answer), got %s"
                % (type(self).__name__, type(fields).__name__)
            )
        self._data = dict(fields)

    @classmethod
    def _of(cls, fields):
        """An answer from the fields the library wrote (no check: they are the CLI's)."""
        answer = cls.__new__(cls)
        answer._data = fields
        return answer

    @property
    def _fields(self):
        if not _is_set(self, "_data"):
            raise TypeError("relpos.%s: the object was made by __new__ without __init__ (not built)" % type(self).__name__)
        return self._data

    def as_dict(self) -> dict:
        """All fields, as in the CLI's JSON (without "id"); a fresh copy."""
        return _json.loads(_json.dumps(self._fields))

    def __eq__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return self._fields == other._fields

    __hash__ = None


def _is_set(obj, slot):
    try:
        getattr(obj, slot)
    except AttributeError:
        return False
    return True


def _field(name, doc):
    def get(self):
        fields = self._fields
        if name not in fields:
            raise AttributeError(
                "relpos.%s has no %r: the answer does not hold it%s"
                % (type(self).__name__, name, _MINIMAL_NOTE if type(self) is Classification else "")
            )
        return fields[name]

    return property(get, doc=doc)


_MINIMAL_NOTE = " (evidence='minimal' gives position, small, contact, rule and stage; classify with evidence='full')"


class Certificate(_Answer):
    """Evidence for a position that anyone can check with rational arithmetic (doc/certificates.md).

    kind: "definite" (a lambda with lambda P + E definite: I or E), "tangent" (lambda and the contact
    point), "hard-tangent" (lambda in Q(sqrt d) and the contact set), "crossing" (a point inside and
    a point outside the paraboloid on the ellipsoid) or "none". A general pair's certificate
    (relpos.Quadric, doc/quadrics.md) has the multiplier "t" in place of "lambda", and the kind
    "equal" (EQ: the ratio of the two matrices). to_json() gives the CLI's JSON form; relpos.verify
    checks it.
    """

    __slots__ = ()

    @property
    def kind(self) -> str:
        """"definite", "tangent", "hard-tangent", "crossing", "equal" or "none"."""
        f = self._fields
        if "inside" in f:
            return "crossing"
        if "contact_set" in f:
            return "hard-tangent"
        if "contact" in f:
            return "tangent"
        if "ratio" in f:
            return "equal"
        return "definite" if "lambda" in f or "t" in f else "none"

    def to_json(self) -> dict:
        """The certificate's JSON object, as in `relpos batch` (numbers as exact strings)."""
        return self.as_dict()

    def __repr__(self):
        return "relpos.Certificate(kind=%r)" % self.kind


class Margin(_Answer):
    """s*, the factor by which the ellipsoid, scaled about its centre, first touches the paraboloid,
    exactly, with its proof: the fields of the "margin" object of `relpos batch --margin`
    (doc/certificates.md, "Margins").

    s* > 1 for I and E, s* = 1 for TI and TE, s* < 1 for C, s* = 0 when the centre lies on the
    paraboloid. approx is the double nearest s* (math.inf beyond the double range, null in the JSON
    form); lo <= s* <= hi ('p/q'), lo == hi exactly when s* is rational; polynomial is its minimal
    polynomial (integer coefficients as strings, lowest degree first); below and above are the
    certificates of the pair scaled by lo (I or E) and by hi (C), at that of the pair scaled by a
    rational s* (TI or TE). relpos.verify checks it.
    """

    __slots__ = ()

    @property
    def approx(self) -> float:
        """The double nearest s*: math.inf beyond the double range (null in the JSON form)."""
        a = self._fields["approx"]
        return _math.inf if a is None else a

    lo = _field("lo", "A rational lower bound of s* ('p/q').")
    hi = _field("hi", "A rational upper bound of s* ('p/q'); equal to lo when s* is rational.")
    polynomial = _field("polynomial", "The minimal polynomial of s*: integer coefficients as strings, lowest degree first.")

    @property
    def below(self) -> Optional[Certificate]:
        """The certificate of the pair with the ellipsoid scaled by lo (I or E), when lo < hi."""
        c = self._fields.get("below")
        return None if c is None else Certificate(c)

    @property
    def above(self) -> Optional[Certificate]:
        """The certificate of the pair with the ellipsoid scaled by hi (C), when lo < hi."""
        c = self._fields.get("above")
        return None if c is None else Certificate(c)

    @property
    def at(self) -> Optional[Certificate]:
        """The certificate of the pair scaled by a rational s* > 0 (TI or TE)."""
        c = self._fields.get("at")
        return None if c is None else Certificate(c)

    def __repr__(self):
        return "relpos.Margin(approx=%r, lo=%r, hi=%r)" % (self.approx, self.lo, self.hi)


class CertificateError(ValueError):
    """relpos.verify: the certificate does not prove the position (the message says why)."""


class _Classified(_Answer):
    """What every classification carries beside its fields: the meta echoed and the certificate."""

    __slots__ = ()

    @property
    def meta(self) -> Any:
        """The meta value given to classify (None when none was)."""
        return self._fields.get("meta")

    @property
    def certificate(self) -> Optional[Certificate]:
        """The certificate (evidence="full"), else None."""
        c = self._fields.get("certificate")
        return None if c is None else Certificate(c)


class Classification(_Classified):
    """The answer for one pair, with its evidence: the fields of the JSON object `relpos batch` writes.

    position ("I", "TI", "C", "TE" or "E", for an ellipsoid of any size), small, contact (True or
    False), rule (the deciding rule in one sentence), stage (which arithmetic settled it),
    rho_vs_one, rho, certificate (a Certificate with full evidence, else None). as_dict() returns
    every field.
    """

    __slots__ = ()

    position = _field("position", "The position: 'I', 'TI', 'C', 'TE' or 'E'.")
    small = _field("small", "Whether the ellipsoid is small (rho <= 1, math.md §5).")
    contact = _field("contact", "Whether the surfaces meet (TI, C, TE).")
    rule = _field("rule", "The deciding rule, one sentence.")
    stage = _field("stage", "The stage that settled the answer (STAGE_NAMES).")
    rho_vs_one = _field("rho_vs_one", "'<1', '=1' or '>1'.")
    rho = _field("rho", "rho exactly ('p/q') when it is rational, else None.")

    @property
    def margin(self) -> Optional[Margin]:
        """The margin s* with its proof (classify(..., margin=True)), else None."""
        m = self._fields.get("margin")
        return None if m is None else Margin(m)

    def __repr__(self):
        f = self._fields
        return "relpos.Classification(position=%r, small=%r, contact=%r, stage=%r)" % (
            f["position"],
            f["small"],
            f["contact"],
            f["stage"],
        )


class QuadricClassification(_Classified):
    """The answer for an ellipsoid and a relpos.Quadric (doc/quadrics.md): the fields of the JSON object
    `relpos batch` writes for a line with "quadric".

    position ("I", "TI", "C", "TE", "E", and "O", "TO", "EQ" when the quadric is an ellipsoid),
    contact ("none", "touching" or "crossing"), quadric_type (one of QUADRIC_TYPES), rule, stage
    ("filter" or "exact"); with evidence="full" also f and d (the exact coefficients of det(Q + tE)
    and det(B + tM), lowest degree first), roots (their real roots) and certificate. as_dict()
    returns every field.
    """

    __slots__ = ()

    position = _field("position", "The position: one of QUADRIC_POSITION_NAMES.")
    contact = _field("contact", "'none', 'touching' or 'crossing'.")
    quadric_type = _field("quadric_type", "The quadric's type, one of QUADRIC_TYPES.")
    rule = _field("rule", "The deciding rule, one sentence.")
    stage = _field("stage", "'filter' (certified doubles) or 'exact'.")
    f = _field("f", "det(Q + t E): exact coefficients ('p/q'), lowest degree first (evidence='full').")
    d = _field("d", "det(B + t M): exact coefficients ('p/q'), lowest degree first (evidence='full').")
    roots = _field("roots", "The distinct real roots of f and d with intervals and multiplicities (evidence='full').")

    def __repr__(self):
        f = self._fields
        return "relpos.QuadricClassification(position=%r, quadric_type=%r, stage=%r)" % (
            f["position"],
            f["quadric_type"],
            f["stage"],
        )


class ContactAnswer(_Answer):
    """Whether the surfaces meet (doc/contact.md): the fields of `relpos classify --contact-only --json`.

    contact: "none", "touching", "crossing", "meet" (kind not certified) or "unknown"; position and
    rule: the classifier's when it ran; decided_by: what settled it.
    """

    __slots__ = ()

    contact = _field("contact", "'none', 'touching', 'crossing', 'meet' or 'unknown'.")
    position = _field("position", "The classifier's position, or None when it did not decide.")
    rule = _field("rule", "The deciding rule, one sentence (or None).")
    decided_by = _field("decided_by", "What settled the answer.")

    def __repr__(self):
        return "relpos.ContactAnswer(contact=%r, position=%r)" % (self.contact, self.position)


def _check_pair(e, p, function, general=False):
    if not isinstance(e, Ellipsoid):
        raise TypeError("%s: e must be a relpos.Ellipsoid, got %s" % (function, type(e).__name__))
    if general and isinstance(p, Quadric):
        return
    if not isinstance(p, Paraboloid):
        raise TypeError("%s: p must be a relpos.Paraboloid%s, got %s"
                        % (function, " or relpos.Quadric" if general else "", type(p).__name__))


#: The pair size limit's default and largest value (`relpos ... --max-bits`, doc/cli.md, Limits).
MAX_BITS = _relpos._MAX_BITS
_LARGEST_MAX_BITS = 1 << 32


def _max_bits(max_bits):
    if max_bits is MAX_BITS:  # the default
        return max_bits
    if isinstance(max_bits, bool) or not hasattr(type(max_bits), "__index__"):
        raise TypeError("max_bits: expected an int from %d to 2**32, got %s" % (MAX_BITS, type(max_bits).__name__))
    max_bits = _operator.index(max_bits)
    if not MAX_BITS <= max_bits <= _LARGEST_MAX_BITS:
        raise ValueError("max_bits: expected an int from %d (the default) to 2**32, got %d" % (MAX_BITS, max_bits))
    return max_bits


def classify(
    e: Ellipsoid,
    p: Union[Paraboloid, Quadric],
    evidence: Literal["full", "minimal"] = "full",
    margin: bool = False,
    margin_bits: int = 40,
    meta: Any = None,
    max_bits: int = MAX_BITS,
) -> Union[Classification, QuadricClassification]:
    """Classify ellipsoid `e` against paraboloid `p` exactly.

    evidence="full" gives the same fields as `relpos batch` / `relpos classify --json` (exact
    coefficients of f and s, multiple roots, rho, the certificate); "minimal" the fields of `relpos
    batch --evidence minimal` (position, small, contact, rule, stage). margin=True adds the field
    "margin" (`relpos batch --margin`, the Margin s*: how far the answer is from changing), its
    enclosure of relative width 2**-margin_bits (1 to 1000). meta: any JSON value, carried through
    untouched as the answer's last member "meta" (as `relpos batch` echoes a line's "meta"). Raises
    ValueError on bad input (with the CLI's message), also for a pair beyond the size limit max_bits
    (`--max-bits`: a safe default that can be raised; doc/cli.md, "Limits", measures the cost). The
    GIL is released; one pair is not interrupted by Ctrl-C (within the default limit it takes well
    under a second).

    With a relpos.Quadric as p (any real quadric, doc/quadrics.md) the answer is a
    QuadricClassification, the fields `relpos batch` writes for a line with "quadric"; margin=True
    is refused (s* is defined for a paraboloid only); max_bits is the size limit as for a paraboloid
    (a batch line's with "quadric").
    """
    _check_pair(e, p, "classify", general=True)
    if not isinstance(evidence, str) or evidence not in ("full", "minimal"):
        raise ValueError("evidence: expected 'full' or 'minimal', got %s" % _shown(evidence))
    if not isinstance(margin, bool):
        raise TypeError("margin: expected a bool, got %s" % type(margin).__name__)
    if isinstance(margin_bits, bool) or not isinstance(margin_bits, int):
        raise TypeError("margin_bits: expected an int, got %s" % type(margin_bits).__name__)
    general = isinstance(p, Quadric)
    if general:
        if margin:
            raise ValueError("margin: the margin s* is defined for an ellipsoid and an elliptic paraboloid only")
        fields = _json.loads(_relpos._classify_quadric_json(e, p, evidence == "full", max_bits=_max_bits(max_bits)))
    else:
        fields = _json.loads(_relpos._classify_json(e, p, evidence == "full", _max_bits(max_bits)))
    if margin:
        fields["margin"] = _json.loads(_relpos._margin_json(e, p, margin_bits))
    if meta is not None:
        try:
            fields["meta"] = _json.loads(_json.dumps(meta))
        except (TypeError, ValueError) as err:
            raise TypeError("meta: expected a JSON value (dict, list, str, number, bool, None): %s" % err)
    return (QuadricClassification if general else Classification)._of(fields)


def verify(e: Ellipsoid, p: Union[Paraboloid, Quadric], answer: Union[Classification, QuadricClassification]) -> None:
    """Check answer.certificate for answer.position with the library's independent verifier (exact
    rational arithmetic, no code of the classifier; `relpos verify`), and answer.margin when it has
    one. Returns None when they prove the position (and s*); raises CertificateError saying why not,
    ValueError when there is no certificate. With a relpos.Quadric as p, answer is the
    QuadricClassification of classify(e, p) and the general verifier checks it (doc/quadrics.md)."""
    _check_pair(e, p, "verify", general=True)
    general = isinstance(p, Quadric)
    expected = QuadricClassification if general else Classification
    if not isinstance(answer, expected):
        raise TypeError("verify: answer must be a relpos.%s, got %s" % (expected.__name__, type(answer).__name__))
    fields = answer._fields
    position = fields.get("position")
    names = QUADRIC_POSITION_NAMES if general else POSITION_NAMES
    if position not in names:
        # Not an answer of relpos: nothing to check the certificate against.
        raise CertificateError("answer.position: expected one of %s, got %s" % (", ".join(names), _shown(position)))
    certificate = fields.get("certificate")
    if certificate is None:
        raise ValueError("verify: the answer has no certificate (classify with evidence='full')")
    if not isinstance(certificate, _abc.Mapping):
        raise CertificateError("%s: answer.certificate: expected a JSON object, got %s" % (position, _shown(certificate)))
    try:
        text = _json.dumps(certificate, allow_nan=False)
    except (TypeError, ValueError) as err:
        raise CertificateError("%s: answer.certificate: not JSON: %s" % (position, err)) from None
    try:
        reason = (_relpos._verify_quadric if general else _relpos._verify)(e, p, position, text)
    except ValueError as err:  # the certificate's JSON does not have the form of doc/certificates.md
        raise CertificateError("%s: %s" % (position, err)) from None
    if reason is not None:
        raise CertificateError(position + ": " + reason)
    if general:
        return
    margin = answer.margin
    if margin is not None:
        reason = _relpos._verify_margin(e, p, _json.dumps(margin.as_dict()))
        if reason is not None:
            raise CertificateError("margin: " + reason)


def _shown(value, limit=60):
    """A short repr of a value for a message (never a whole array or answer)."""
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def contact(e: Ellipsoid, p: Paraboloid, max_bits: int = MAX_BITS) -> ContactAnswer:
    """Whether the surfaces meet, certified like the position and also for bodies that are not small
    (doc/contact.md; `relpos classify --contact-only`). max_bits: the size limit, as for classify.
    The GIL is released."""
    _check_pair(e, p, "contact")
    return ContactAnswer._of(_json.loads(_relpos._contact_json(e, p, _max_bits(max_bits))))


# ------------------------------------------------------------------------------------------------
# Many pairs: numpy arrays in, numpy codes out.
# ------------------------------------------------------------------------------------------------


#: The most threads a call takes (`relpos batch --threads`' limit); 0 means every core.
_MAX_THREADS = 1024


def _thread_count(threads):
    if isinstance(threads, bool) or not hasattr(type(threads), "__index__"):
        raise TypeError("threads: expected an int from 0 to %d, got %s" % (_MAX_THREADS, type(threads).__name__))
    threads = _operator.index(threads)
    if not 0 <= threads <= _MAX_THREADS:
        raise ValueError("threads: expected an int from 0 to %d (0: every core), got %d" % (_MAX_THREADS, threads))
    return threads


def decide_positions(
    E: Union[numpy.ndarray, Mapping[str, Any]],
    P: Union[numpy.ndarray, Mapping[str, Any], Quadric],
    threads: int = 0,
    errors: Literal["raise", "code"] = "raise",
    symmetrize: Optional[Literal["upper"]] = None,
    max_bits: int = MAX_BITS,
) -> numpy.ndarray:
    """Positions of many pairs given as numpy matrices or parameters, exactly, on all cores.

    E: array (n, 4, 4) of ellipsoid matrices, or the parameters a float code starts from, a dict
    {"center": (n, 3), "axes": (n, 3), "rotation": (n, 4)} (semi-axes along the columns of the
    quaternion's rotation; "rotation" may be left out). P: array (n, 4, 4), or one (4, 4) matrix
    shared by all, or {"vertex": (n, 3), "a": (n,), "b": (n,), "rotation": (n, 4)} (an array
    without the leading n is shared by every pair). Every entry is read exactly: float64, float32,
    float16, numpy.longdouble and integer arrays (of any width) as the numbers they hold; any other
    dtype raises TypeError. Parameters are never refused for their shape (a rotated paraboloid
    rounded into a matrix usually is). symmetrize="upper" reads each matrix from its upper triangle
    (a float code's R D R^T is symmetric only up to rounding). Returns a numpy int8 array of codes
    into POSITION_NAMES (0 = "I" ... 4 = "E"). threads=0 uses every core; the GIL is released while
    deciding. errors="raise" raises ValueError naming the first invalid pair ("E[17]: ellipsoid:
    ...", and for a matrix what to pass instead); errors="code" gives such a pair the code INVALID
    (-1) instead. max_bits: the size limit, as for classify (long doubles and 64-bit integers may
    exceed it). Ctrl-C stops the call (KeyboardInterrupt) within a fraction of a second.

    P may also be one relpos.Quadric (any real quadric, doc/quadrics.md) shared by every pair: the
    codes are then indices into QUADRIC_POSITION_NAMES (5 = "O", 6 = "TO", 7 = "EQ" besides the
    five), each pair decided as classify(e, q) decides it, the size limit (max_bits) a batch line's.
    """
    if not isinstance(errors, str) or errors not in ("raise", "code"):
        raise ValueError("errors: expected 'raise' or 'code', got %s" % _shown(errors))
    if symmetrize not in (None, "upper"):
        raise ValueError("symmetrize: expected None or 'upper', got %r" % (symmetrize,))
    if isinstance(P, Quadric):
        E = dict(E) if isinstance(E, Mapping) else E
        return _relpos._decide_positions_quadric(
            E, P, _thread_count(threads), errors == "raise", symmetrize == "upper", _max_bits(max_bits)
        )
    E = dict(E) if isinstance(E, Mapping) else E
    P = dict(P) if isinstance(P, Mapping) else P
    return _relpos._decide_positions(
        E, P, _thread_count(threads), errors == "raise", symmetrize == "upper", _max_bits(max_bits)
    )


class SceneResult:
    """The positions of many bodies against one paraboloid (relpos.scene).

    positions: int8 codes into POSITION_NAMES; contact: int8, 1 the surfaces meet, 0 they do not;
    stages: int8 codes into STAGE_NAMES (an early-out certificate or the classifier stage);
    threads: the threads used. counts() and stage_counts() tally them by name.
    """

    __slots__ = ("_data",)

    def __init__(self, positions: numpy.ndarray, contact: numpy.ndarray, stages: numpy.ndarray, threads: int) -> None:
        """From the arrays relpos.scene computes."""
        if _is_set(self, "_data"):
            raise TypeError("relpos.SceneResult: the object is already built; make a new one")
        self._data = (positions, contact, stages, threads)

    def _get(self, k):
        if not _is_set(self, "_data"):
            raise TypeError("relpos.SceneResult: the object was made by __new__ without __init__ (not built)")
        return self._data[k]

    positions = property(lambda self: self._get(0), doc="int8 codes into POSITION_NAMES, one per body.")
    contact = property(lambda self: self._get(1), doc="int8: 1 the surfaces meet, 0 they do not.")
    stages = property(lambda self: self._get(2), doc="int8 codes into STAGE_NAMES: what settled each body.")
    threads = property(lambda self: self._get(3), doc="The number of threads used.")

    def names(self) -> numpy.ndarray:
        """The positions as names ("I" ... "E")."""
        return numpy.array(POSITION_NAMES)[self.positions]

    def counts(self) -> dict:
        """{position name: number of bodies}."""
        return {name: int((self.positions == k).sum()) for k, name in enumerate(POSITION_NAMES)}

    def stage_counts(self) -> dict:
        """{stage name: number of bodies it settled}."""
        return {name: int((self.stages == k).sum()) for k, name in enumerate(STAGE_NAMES)}

    def __repr__(self):
        return "relpos.SceneResult(%d bodies, %r)" % (len(self.positions), self.counts())


def scene(
    p: Union[Paraboloid, Description],
    bodies: Union[numpy.ndarray, Sequence[Ellipsoid]],
    threads: int = 0,
    early_outs: bool = True,
    max_bits: int = MAX_BITS,
) -> SceneResult:
    """Many bodies against one paraboloid with the library's scene (`relpos scene`): the paraboloid is
    prepared once, certified early-outs settle most bodies without the classifier, the rest go
    through it, on `threads` threads (0 = every core; the GIL is released).

    bodies: a sequence of Ellipsoid, or matrices (n, 4, 4) read exactly as by decide_positions (a
    bad one raises ValueError "bodies[i]: ellipsoid: ..."). early_outs=False sends every body through
    the classifier (the same positions). max_bits: the size limit, as for classify ("bodies[i]:
    numbers too large: ..."). Ctrl-C stops the call (KeyboardInterrupt) within a fraction of a second.
    """
    if isinstance(p, Quadric):
        raise TypeError("scene: p must be a relpos.Paraboloid or a paraboloid's description, got Quadric (many "
                        "ellipsoids against a relpos.Quadric: decide_positions(E, q), or `relpos scene --quadric`)")
    if not isinstance(p, Paraboloid):
        p = Paraboloid(p)
    return SceneResult(*_relpos._scene(p, bodies, _thread_count(threads), bool(early_outs), _max_bits(max_bits)))


# ------------------------------------------------------------------------------------------------
# Motion: exact instants.
# ------------------------------------------------------------------------------------------------

_MOTION_DOC = """
    The ellipsoid e (placed as given) moves by x(t) = R(t)(y - pivot) + pivot + c(t): translation
    c(t) is 3 polynomials in t, rotation q(t) = (w, x, y, z) 4 polynomials (the rotation
    R(q)/|q|^2; q must not vanish on [t0, t1]), each a list of exact coefficients, lowest degree
    first (["-9/4", 0, 1] is t^2 - 9/4), or one number. pivot: "origin", "center" (of e) or a
    point ("centre" is accepted too). The paraboloid is fixed. Instants are exact (relpos.Instant).
    The CLI's limits apply (degree 12, 512-bit coefficients; doc/cli.md), and its time budget:
    max_seconds (default 60, as `relpos motion --max-seconds`; None: none) ends the computation with
    TimeoutError. The GIL is released; Ctrl-C stops the computation (KeyboardInterrupt).
"""

Pivot = Union[Literal["origin", "center", "centre"], Vector3]

#: `relpos motion --max-seconds`' default and largest value.
_DEFAULT_MAX_SECONDS = 60
_LARGEST_MAX_SECONDS = 86400


def _max_seconds(value):
    if value is None:
        return 0.0
    if isinstance(value, bool) or not isinstance(value, (int, float, Fraction, Decimal, numpy.integer, numpy.floating)):
        raise TypeError("max_seconds: expected a number of seconds or None, got %s" % type(value).__name__)
    if not 0 < value <= _LARGEST_MAX_SECONDS:
        raise ValueError("max_seconds: expected more than 0 and at most %d seconds (or None), got %s"
                         % (_LARGEST_MAX_SECONDS, value))
    return float(value)


def _motion_function(name, compute, result, summary):
    """The public motion function `name`: checks the pair and runs the compiled `compute`."""

    def function(
        e: Ellipsoid,
        p: Paraboloid,
        t0: Number,
        t1: Number,
        translation: Optional[Sequence[TimePolynomial]] = None,
        rotation: Optional[Sequence[TimePolynomial]] = None,
        pivot: Pivot = "origin",
        max_seconds: Optional[float] = _DEFAULT_MAX_SECONDS,
    ) -> result:
        _check_pair(e, p, name)
        return compute(e, p, t0, t1, translation, rotation, pivot, _max_seconds(max_seconds))

    function.__name__ = function.__qualname__ = name
    function.__doc__ = summary + "\n" + _MOTION_DOC
    return function


first_contact = _motion_function(
    "first_contact",
    _relpos._first_contact,
    FirstContact,
    "The certified first contact on [t0, t1] of a body exterior at t0 (`relpos motion --first-contact`).",
)
timeline = _motion_function(
    "timeline",
    _relpos._timeline,
    Timeline,
    "Every change of position on [t0, t1], for an ellipsoid of any size (`relpos motion`).",
)

for _cls in (Instant, FirstContact, Timeline):
    _cls.__module__ = "relpos"


def _made_by_relpos(cls, makers):
    """cls(...) raises a TypeError saying where its objects come from (pybind11 would say "No
    constructor defined" with the extension's module name)."""

    @_method(cls, "__init__")
    def __init__(self) -> None:
        raise TypeError("relpos.%s objects are made by %s, not directly" % (cls.__name__, makers))

    __init__.__doc__ = "Not callable: relpos.%s objects are made by %s." % (cls.__name__, makers)


_made_by_relpos(Instant, "relpos.first_contact and relpos.timeline")
_made_by_relpos(FirstContact, "relpos.first_contact")
_made_by_relpos(Timeline, "relpos.timeline")



@_method(Instant, "decimal")
def _decimal(self, digits: int = 12) -> str:
    """The correctly rounded decimal with `digits` significant digits (1..1000)."""
    if isinstance(digits, bool) or not hasattr(type(digits), "__index__"):
        raise TypeError("digits: expected an int from 1 to 1000, got %s" % type(digits).__name__)
    digits = _operator.index(digits)
    if not 1 <= digits <= 1000:
        raise ValueError("digits: expected an int from 1 to 1000, got %d" % digits)
    return self._decimal(digits)


def _instant_order(name, holds):
    def method(self, other):
        c = self._compare(other)
        return NotImplemented if c is None else holds(c)

    method.__name__ = name
    method.__qualname__ = "Instant." + name
    method.__doc__ = "Exact comparison with an Instant or a real number (int, float, Fraction, Decimal)."
    setattr(Instant, name, method)


# Exact order (relpos::AlgebraicReal::compare): equal algebraic instants compare equal.
for _name, _holds in (
    ("__eq__", lambda c: c == 0),
    ("__ne__", lambda c: c != 0),
    ("__lt__", lambda c: c < 0),
    ("__le__", lambda c: c <= 0),
    ("__gt__", lambda c: c > 0),
    ("__ge__", lambda c: c >= 0),
):
    _instant_order(_name, _holds)


@_method(Timeline, "position_at")
def _position_at(self, t: Number) -> str:
    """The position at an exact time t in [t0, t1]."""
    return self._position_at(t)


# ------------------------------------------------------------------------------------------------
# Pictures and the cluster.
# ------------------------------------------------------------------------------------------------


def plot(e: Ellipsoid, p: Union[Paraboloid, Quadric], ax: Any = None, **kwargs: Any) -> Any:
    """Draw the pair (matplotlib 3D axes) titled with its position; returns the axes. See relpos._plot."""
    from ._plot import plot as _plot

    _check_pair(e, p, "plot", general=True)

    return _plot(e, p, ax=ax, **kwargs)


def __getattr__(name):
    # relpos.distributed is imported on first use (it imports dask.distributed, which is slow), and
    # relpos.testing too (the oracle for float code, doc/oracle.md).
    if name in ("distributed", "testing"):
        import importlib

        return importlib.import_module("." + name, __name__)
    raise AttributeError("module 'relpos' has no attribute %r" % name)
