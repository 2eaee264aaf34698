# Type stub of the package relpos (doc/python.md): the compiled classes and the Python layer.
from decimal import Decimal
from fractions import Fraction
from typing import Any, Literal, Mapping, Optional, Sequence, Union, overload

import numpy

from . import distributed as distributed
from . import testing as testing

__version__: str

Number = Union[int, float, Fraction, Decimal, numpy.number, str]
Vector3 = Union[Sequence[Number], numpy.ndarray]
Matrix = Union[Sequence[Sequence[Number]], numpy.ndarray]
Description = Union[Matrix, Mapping[str, Any]]
TimePolynomial = Union[Sequence[Number], Number]
Pivot = Union[Literal["origin", "center", "centre"], Vector3]

POSITION_NAMES: tuple[str, str, str, str, str]
STAGE_NAMES: tuple[str, ...]
POSITION_MEANINGS: dict[str, str]
QUADRIC_POSITION_NAMES: tuple[str, str, str, str, str, str, str, str]
QUADRIC_TYPES: tuple[str, ...]
INVALID: int
MAX_BITS: int

class _Quadric:
    def matrix(self) -> list[list[Fraction]]: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class Ellipsoid(_Quadric):
    """A validated ellipsoid (sign-normalized: inside is negative)."""

    def __init__(self, description: Description) -> None: ...
    @staticmethod
    def sphere(center: Vector3, radius: Number) -> Ellipsoid: ...
    @staticmethod
    def from_axes(
        center: Vector3, axes: Vector3, rotation: Union[Sequence[Number], Matrix] = (1, 0, 0, 0)
    ) -> Ellipsoid: ...
    @staticmethod
    def from_map(center: Vector3, linear: Matrix) -> Ellipsoid: ...
    @staticmethod
    def from_coefficients(coefficients: Sequence[Number]) -> Ellipsoid: ...

class Paraboloid(_Quadric):
    """A validated elliptic paraboloid (inside the cup is negative)."""

    def __init__(self, description: Description) -> None: ...
    @staticmethod
    def standard(vertex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = (1, 0, 0, 0)) -> Paraboloid: ...
    @staticmethod
    def from_map(linear: Matrix, translation: Vector3) -> Paraboloid: ...
    @staticmethod
    def from_coefficients(coefficients: Sequence[Number]) -> Paraboloid: ...

class Quadric(_Quadric):
    """A validated real quadric of one of eleven types; its solid is {X^T Q X <= 0} (doc/quadrics.md)."""

    def __init__(self, description: Description) -> None: ...
    @property
    def type(self) -> str: ...
    @staticmethod
    def from_coefficients(coefficients: Sequence[Number]) -> Quadric: ...
    @staticmethod
    def of(body: Union[Ellipsoid, Paraboloid]) -> Quadric: ...
    @staticmethod
    def sphere(center: Vector3, radius: Number) -> Quadric: ...
    @staticmethod
    def ellipsoid(center: Vector3, axes: Vector3, rotation: Sequence[Number] = (1, 0, 0, 0)) -> Quadric: ...
    @staticmethod
    def hyperboloid_one_sheet(center: Vector3, axes: Vector3, rotation: Sequence[Number] = (1, 0, 0, 0)) -> Quadric: ...
    @staticmethod
    def hyperboloid_two_sheets(
        center: Vector3, axes: Vector3, rotation: Sequence[Number] = (1, 0, 0, 0)
    ) -> Quadric: ...
    @staticmethod
    def cone(apex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = (1, 0, 0, 0)) -> Quadric: ...
    @staticmethod
    def elliptic_paraboloid(
        vertex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = (1, 0, 0, 0)
    ) -> Quadric: ...
    @staticmethod
    def hyperbolic_paraboloid(
        vertex: Vector3, a: Number, b: Number, rotation: Sequence[Number] = (1, 0, 0, 0)
    ) -> Quadric: ...
    @staticmethod
    def elliptic_cylinder(
        center: Vector3, a: Number, b: Number, rotation: Sequence[Number] = (1, 0, 0, 0)
    ) -> Quadric: ...
    @staticmethod
    def hyperbolic_cylinder(
        center: Vector3, a: Number, b: Number, rotation: Sequence[Number] = (1, 0, 0, 0)
    ) -> Quadric: ...
    @staticmethod
    def parabolic_cylinder(vertex: Vector3, a: Number, rotation: Sequence[Number] = (1, 0, 0, 0)) -> Quadric: ...
    @staticmethod
    def half_space(normal: Vector3, offset: Number) -> Quadric: ...
    @staticmethod
    def slab(normal: Vector3, low: Number, high: Number) -> Quadric: ...

class Certificate:
    def __init__(self, fields: Mapping[str, Any]) -> None: ...
    @property
    def kind(self) -> Literal["definite", "tangent", "hard-tangent", "crossing", "equal", "none"]: ...
    def to_json(self) -> dict[str, Any]: ...
    def as_dict(self) -> dict[str, Any]: ...

class CertificateError(ValueError): ...

class Margin:
    def __init__(self, fields: Mapping[str, Any]) -> None: ...
    approx: float
    lo: str
    hi: str
    polynomial: list[str]
    @property
    def below(self) -> Optional[Certificate]: ...
    @property
    def above(self) -> Optional[Certificate]: ...
    @property
    def at(self) -> Optional[Certificate]: ...
    def as_dict(self) -> dict[str, Any]: ...

class Classification:
    def __init__(self, fields: Mapping[str, Any]) -> None: ...
    position: str
    small: bool
    contact: bool
    rule: str
    stage: str
    rho_vs_one: str
    rho: Optional[str]
    @property
    def meta(self) -> Any: ...
    @property
    def certificate(self) -> Optional[Certificate]: ...
    @property
    def margin(self) -> Optional[Margin]: ...
    def as_dict(self) -> dict[str, Any]: ...

class QuadricClassification:
    def __init__(self, fields: Mapping[str, Any]) -> None: ...
    position: str
    contact: str
    quadric_type: str
    rule: str
    stage: str
    f: list[str]
    d: list[str]
    roots: list[dict[str, Any]]
    @property
    def meta(self) -> Any: ...
    @property
    def certificate(self) -> Optional[Certificate]: ...
    def as_dict(self) -> dict[str, Any]: ...

class ContactAnswer:
    def __init__(self, fields: Mapping[str, Any]) -> None: ...
    contact: str
    position: Optional[str]
    rule: Optional[str]
    decided_by: str
    def as_dict(self) -> dict[str, Any]: ...

class SceneResult:
    def __init__(self, positions: numpy.ndarray, contact: numpy.ndarray, stages: numpy.ndarray, threads: int) -> None: ...
    positions: numpy.ndarray
    contact: numpy.ndarray
    stages: numpy.ndarray
    threads: int
    def names(self) -> numpy.ndarray: ...
    def counts(self) -> dict[str, int]: ...
    def stage_counts(self) -> dict[str, int]: ...

class Instant:
    @property
    def exact(self) -> Optional[Fraction]: ...
    @property
    def interval(self) -> tuple[Fraction, Fraction]: ...
    @property
    def polynomial(self) -> list[int]: ...
    def decimal(self, digits: int = 12) -> str: ...
    def __float__(self) -> float: ...
    def __eq__(self, other: object) -> bool: ...
    def __lt__(self, other: Union[Instant, int, float, Fraction, Decimal]) -> bool: ...
    def __le__(self, other: Union[Instant, int, float, Fraction, Decimal]) -> bool: ...
    def __gt__(self, other: Union[Instant, int, float, Fraction, Decimal]) -> bool: ...
    def __ge__(self, other: Union[Instant, int, float, Fraction, Decimal]) -> bool: ...
    def __hash__(self) -> int: ...

class FirstContact:
    kind: Literal["contact", "none", "not-exterior-at-start"]
    start_position: str
    time: Optional[Instant]
    position: Optional[str]
    how: str

class Timeline:
    instants: list[dict[str, Any]]
    intervals: list[dict[str, Any]]
    spans: list[dict[str, Any]]
    changes: list[dict[str, Any]]
    def position_at(self, t: Number) -> str: ...

@overload
def classify(
    e: Ellipsoid,
    p: Paraboloid,
    evidence: Literal["full", "minimal"] = "full",
    margin: bool = False,
    margin_bits: int = 40,
    meta: Any = None,
    max_bits: int = 4096,
) -> Classification: ...
@overload
def classify(
    e: Ellipsoid,
    p: Quadric,
    evidence: Literal["full", "minimal"] = "full",
    margin: bool = False,
    margin_bits: int = 40,
    meta: Any = None,
    max_bits: int = 4096,
) -> QuadricClassification: ...
def verify(
    e: Ellipsoid, p: Union[Paraboloid, Quadric], answer: Union[Classification, QuadricClassification]
) -> None: ...
def contact(e: Ellipsoid, p: Paraboloid, max_bits: int = 4096) -> ContactAnswer: ...
def decide_positions(
    E: Union[numpy.ndarray, Mapping[str, Any]],
    P: Union[numpy.ndarray, Mapping[str, Any], Quadric],
    threads: int = 0,
    errors: Literal["raise", "code"] = "raise",
    symmetrize: Optional[Literal["upper"]] = None,
    max_bits: int = 4096,
) -> numpy.ndarray: ...
def scene(
    p: Union[Paraboloid, Description],
    bodies: Union[numpy.ndarray, Sequence[Ellipsoid]],
    threads: int = 0,
    early_outs: bool = True,
    max_bits: int = 4096,
) -> SceneResult: ...
def first_contact(
    e: Ellipsoid, p: Paraboloid, t0: Number, t1: Number, translation: Optional[Sequence[TimePolynomial]] = None,
    rotation: Optional[Sequence[TimePolynomial]] = None, pivot: Pivot = "origin", max_seconds: Optional[float] = 60,
) -> FirstContact: ...
def timeline(
    e: Ellipsoid, p: Paraboloid, t0: Number, t1: Number, translation: Optional[Sequence[TimePolynomial]] = None,
    rotation: Optional[Sequence[TimePolynomial]] = None, pivot: Pivot = "origin", max_seconds: Optional[float] = 60,
) -> Timeline: ...
def plot(e: Ellipsoid, p: Union[Paraboloid, Quadric], ax: Any = None, **kwargs: Any) -> Any: ...
