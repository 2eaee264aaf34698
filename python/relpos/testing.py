"""relpos.testing: judge floating-point code against exact answers (doc/oracle.md).

    import relpos.testing as rt
    cases = rt.cases(["offaxis", "tiny", "special"], n=50, eps=["1e-3", "1e-9", "0"])
    report = rt.judge(lambda c: my_position(c.center, c.axes, c.e_rotation, c.vertex, c.a, c.b, c.p_rotation), cases)
    print(report.table())                 # error rate per family and eps, as `relpos judge` prints it
    report.plot("errors.png")             # error rate against eps, with the float baselines
    rt.assert_positions(my_answers, cases, tolerance="1e-9")   # pytest-friendly

The cases and the judge are the C++ ones of `relpos cases` and `relpos judge` (relpos._relpos._cases
and _judge): the same lines, counts and chart. pairs() is a hypothesis strategy when Debian's
python3-hypothesis is installed.
"""

import json as _json
import os as _os
from fractions import Fraction as _Fraction
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import numpy

from . import _relpos

__all__ = ["FAMILIES", "DEFAULT_EPS", "Case", "Cases", "Report", "cases", "judge", "assert_positions", "pairs"]

#: The case families (name, description), in the order `relpos cases all` writes them.
FAMILIES = tuple(_relpos._FAMILIES)
#: The default epsilons of `relpos cases` (exact numbers as text; "0" gives the exact tangencies).
DEFAULT_EPS = tuple(_relpos._DEFAULT_EPS.split(","))


class Case:
    """One case: what a float code starts from (doubles), the truths, and the exact form.

    center, axes, e_rotation (quaternion w, x, y, z), vertex, a, b, p_rotation: the parameters as
    Python floats (the doubles nearest the exact ones); E, P: the 4x4 matrices a float code computes
    from them (numpy float64; doc/oracle.md gives the formulas); position: the truth by construction
    (relpos's for the random family); double_position: relpos on the doubles of the parameters;
    matrix_position: relpos on E and P (upper triangles), None when they are no longer a pair
    (matrix_error says why); exact_ellipsoid, exact_paraboloid: the exact forms (dicts of "p/q"
    strings, for relpos.Ellipsoid / relpos.Paraboloid); margin: s* of the exact pair with its proof
    (a dict, as `relpos batch --margin` writes it);
    line: the JSON line of `relpos cases`.
    """

    __slots__ = ("id", "family", "eps", "index", "side", "position", "double_position", "matrix_position",
                 "matrix_error", "margin", "center", "axes", "e_rotation", "vertex", "a", "b", "p_rotation", "E",
                 "P", "exact_ellipsoid", "exact_paraboloid", "line")

    def __init__(self, line: str) -> None:
        """From one line of `relpos cases`."""
        data = _json.loads(line)
        meta = data["meta"]
        d = meta["double"]
        e, p = d["ellipsoid"], d["paraboloid"]
        self.id = data["id"]
        self.family = meta["family"]
        self.eps = meta["eps"]
        self.index = meta["index"]
        self.side = meta["side"]
        self.position = meta["position"]
        self.double_position = meta["double_position"]
        self.matrix_position = meta["matrix_position"]
        self.matrix_error = meta.get("matrix_error")
        self.margin = meta.get("margin")
        self.center, self.axes, self.e_rotation = e["center"], e["axes"], e["rotation"]
        self.vertex, self.a, self.b, self.p_rotation = p["vertex"], p["a"], p["b"], p["rotation"]
        self.E = numpy.array(d["E"], dtype=numpy.float64)
        self.P = numpy.array(d["P"], dtype=numpy.float64)
        self.exact_ellipsoid = data["ellipsoid"]
        self.exact_paraboloid = data["paraboloid"]
        self.line = line

    def __repr__(self):
        return "relpos.testing.Case(%r, position=%r)" % (self.id, self.position)


class Cases(Sequence):
    """Cases of `relpos cases`, as numpy arrays (one row per case) and Case objects (cases[i]).

    ids, family, eps (the text given), side, position (the labels: the truth by construction),
    double_position, matrix_position (None where the matrices are refused): numpy object arrays;
    center, axes (n, 3), e_rotation (n, 4), vertex (n, 3), a, b (n,), p_rotation (n, 4), E, P
    (n, 4, 4): float64 arrays of the doubles a float code holds (relpos.decide_positions reads the
    parameters as they are: E=cases.ellipsoid_parameters, P=cases.paraboloid_parameters). lines: the
    JSON lines; write(path) saves them for `relpos batch` and `relpos judge`.
    """

    def __init__(self, lines: Union[str, Iterable[str]]) -> None:
        """From the text (or the lines) of `relpos cases`."""
        if isinstance(lines, str):
            lines = lines.splitlines()
        self._cases = [Case(line) for line in lines if line.strip()]
        c = self._cases

        def column(name, dtype=object):
            return numpy.array([getattr(x, name) for x in c], dtype=dtype)

        self.lines = [x.line for x in c]
        self.ids = column("id")
        self.family = column("family")
        self.eps = column("eps")
        self.side = column("side")
        self.position = column("position")
        self.labels = self.position
        self.double_position = column("double_position")
        self.matrix_position = column("matrix_position")
        shapes = {"center": 3, "axes": 3, "e_rotation": 4, "vertex": 3, "p_rotation": 4}
        for name, width in shapes.items():
            setattr(self, name, numpy.array([getattr(x, name) for x in c], dtype=numpy.float64).reshape(len(c), width))
        self.a = column("a", numpy.float64)
        self.b = column("b", numpy.float64)
        self.E = numpy.array([x.E for x in c], dtype=numpy.float64).reshape(len(c), 4, 4)
        self.P = numpy.array([x.P for x in c], dtype=numpy.float64).reshape(len(c), 4, 4)

    @property
    def ellipsoid_parameters(self) -> dict:
        """{"center", "axes", "rotation"}: the ellipsoids' parameters for relpos.decide_positions."""
        return {"center": self.center, "axes": self.axes, "rotation": self.e_rotation}

    @property
    def paraboloid_parameters(self) -> dict:
        """{"vertex", "a", "b", "rotation"}: the paraboloids' parameters for relpos.decide_positions."""
        return {"vertex": self.vertex, "a": self.a, "b": self.b, "rotation": self.p_rotation}

    def __len__(self):
        return len(self._cases)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return Cases(self.lines[i])
        return self._cases[i]

    def text(self) -> str:
        """The JSON lines, as `relpos cases` writes them."""
        return "".join(line + "\n" for line in self.lines)

    def write(self, path: Union[str, "_os.PathLike"]) -> None:
        """Save the lines (for `relpos batch` and `relpos judge`)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.text())

    def __repr__(self):
        return "relpos.testing.Cases(%d cases)" % len(self)


def cases(
    families: Union[str, Sequence[str]] = "all",
    n: int = 100,
    eps: Optional[Sequence[Any]] = None,
    seed: int = 1,
    threads: int = 0,
) -> Cases:
    """The cases of `relpos cases FAMILIES --n N --eps EPS --seed SEED` (doc/oracle.md): pairs whose
    position is known by construction, near tangency at relative distances eps (exact numbers: str,
    int or Fraction; floats are read as their shortest decimal text), with the doubles a float code
    holds. The same seed gives the same cases."""
    if isinstance(families, str):
        families = [families]
    eps_text = [] if eps is None else [_eps_text(e) for e in eps]
    return Cases(_relpos._cases(list(families), int(n), eps_text, int(seed), int(threads), "exact"))


def _eps_text(e):
    if isinstance(e, str):
        return e
    if isinstance(e, float):
        return repr(e)
    if isinstance(e, (int, _Fraction)) or hasattr(e, "__index__"):
        return str(e)
    raise TypeError("eps: expected str, int, float or Fraction, got %s" % type(e).__name__)


_TRUTH_FIELD = {"exact": "position", "double": "double_position", "matrix": "matrix_position"}


class Report:
    """What `relpos judge` reports (doc/oracle.md): total, groups (error rates per family and eps
    or the keys of `by`), confusion (truth -> answer -> count), unmatched (malformed, unknown and
    duplicate answers), misses (each with a `relpos classify` command), curves and warnings.
    table("md" | "csv") prints it as the CLI does; plot(path) writes the chart as PNG."""

    def __init__(self, cases_text, answers_text, options, result):
        """From relpos._relpos._judge's result (made by relpos.testing.judge)."""
        self._inputs = (cases_text, answers_text, options)
        data, self._md, self._csv, self._png = result
        self._data = _json.loads(data)
        for key in ("total", "groups", "confusion", "unmatched", "misses", "curves", "warnings"):
            setattr(self, key, self._data[key])
        self.error_rate = self.total["error_rate"]

    def table(self, format: str = "md") -> str:
        """The Markdown (default) or CSV report of `relpos judge`."""
        if format not in ("md", "csv"):
            raise ValueError("format: expected 'md' or 'csv', got %r" % (format,))
        return self._md if format == "md" else self._csv

    def to_dict(self) -> dict:
        """The JSON report of `relpos judge --format json`."""
        return _json.loads(_json.dumps(self._data))

    def plot(self, path: Union[str, "_os.PathLike"]) -> None:
        """Write the chart of error rate against eps, with the float baselines, as a PNG (the C++
        writer of `relpos judge --plot`: no plotting library needed)."""
        if self._png is None:
            cases_text, answers_text, options = self._inputs
            self._png = _relpos._judge(cases_text, answers_text, *options, True)[3]
        with open(path, "wb") as f:
            f.write(self._png)

    def __repr__(self):
        return "relpos.testing.Report(%d cases, error rate %.4g)" % (self.total["cases"], self.error_rate)


def _answer_lines(answers, cases):
    """The answers as JSON Lines text: a function of a Case, positions in case order, or JSON Lines."""
    if isinstance(answers, bytes):
        answers = answers.decode()
    if isinstance(answers, str):  # JSON Lines, as `relpos judge` reads them
        return answers
    if callable(answers):
        out = []
        for c in cases:
            try:
                position = answers(c)
            except (ArithmeticError, ValueError):
                position = None  # the code gave no answer: undecided
            out.append(_json.dumps({"id": c.id, "position": position}))
        return "\n".join(out) + "\n"
    positions = list(answers)
    if len(positions) != len(cases):
        raise ValueError("answers: %d positions for %d cases" % (len(positions), len(cases)))
    return "".join(
        _json.dumps({"id": c.id, "position": None if p is None else str(p)}) + "\n" for c, p in zip(cases, positions)
    )


def judge(
    answers: Union[Callable[[Case], Optional[str]], Sequence[Optional[str]], str],
    cases: Cases,
    truth: str = "exact",
    tolerance: Any = None,
    by: Sequence[str] = ("family", "eps"),
    baselines: bool = True,
) -> Report:
    """Judge a float implementation on the cases (`relpos judge`, the same C++ code).

    answers: a function called with each Case that returns "I", "TI", "C", "TE", "E" or None
    (undecided; an ArithmeticError or ValueError it raises counts as undecided too), or the positions
    in case order (a sequence or numpy array of names, None for undecided), or JSON Lines text of
    {"id", "position"} answers. truth: "exact" (the construction), "double" (the doubles of the
    parameters) or "matrix" (the float code's matrices); tolerance: tau (an exact number: str, int,
    Fraction; a float as its shortest decimal text), answers within the margin are excused."""
    if not isinstance(cases, Cases):
        raise TypeError("cases: expected relpos.testing.Cases, got %s" % type(cases).__name__)
    if truth not in _TRUTH_FIELD:
        raise ValueError("truth: expected 'exact', 'double' or 'matrix', got %r" % (truth,))
    answers_text = _answer_lines(answers, cases)
    options = (truth, None if tolerance is None else _eps_text(tolerance), list(by), bool(baselines))
    cases_text = cases.text()
    return Report(cases_text, answers_text, options, _relpos._judge(cases_text, answers_text, *options, False))


def assert_positions(
    answers: Union[Callable[[Case], Optional[str]], Sequence[Optional[str]], str],
    cases: Cases,
    truth: str = "exact",
    tolerance: Any = None,
    max_misses: int = 10,
) -> None:
    """Raise AssertionError, numpy.testing style, unless every answer is the truth (or excused within
    the tolerance): the counts, the error rate per group that has misses, and the first misses with
    their `relpos classify` commands. Returns None when everything agrees (pytest-friendly)."""
    report = judge(answers, cases, truth=truth, tolerance=tolerance)
    t = report.total
    bad = t["wrong"] + t["undecided"] + t["missing"]
    if bad == 0 and report.unmatched["malformed"] == 0:
        return
    lines = [
        "",
        "Positions not equal (truth: %s, tolerance: %s)" % (truth, "none" if tolerance is None else tolerance),
        "",
        "Mismatched positions: %d / %d (%.3g%%): %d wrong, %d undecided, %d missing, %d excused"
        % (bad, t["cases"], 100.0 * t["error_rate"], t["wrong"], t["undecided"], t["missing"], t["excused"]),
    ]
    u = report.unmatched
    if any(u.values()):
        lines.append("Answers matching no case: %d malformed, %d unknown id, %d duplicate id"
                     % (u["malformed"], u["unknown"], u["duplicate"]))
    groups = [g for g in report.groups if g["wrong"] + g["undecided"] + g["missing"]]
    if groups:
        lines.append("By group: " + ", ".join(
            "%s %d/%d" % (" ".join(str(v) for v in g["key"].values()), g["wrong"] + g["undecided"] + g["missing"],
                          g["cases"] - g["no_truth"]) for g in groups))
    lines.append("First misses:")
    for m in report.misses[:max_misses]:
        lines.append(" %s: truth %s, answer %s" % (m["id"], m["truth"], m["answer"]))
        if m["reproduce"]:
            lines.append("   " + m["reproduce"])
    raise AssertionError("\n".join(lines))


def pairs(families: Sequence[str] = None, eps: Sequence[Any] = DEFAULT_EPS):
    """A hypothesis strategy of Case objects (Debian's python3-hypothesis): a family, an eps, a seed
    and one of the first four cases (inside or outside, closer or farther) drawn by hypothesis, so a
    failure shrinks to a small seed and prints a reproducible case."""
    from hypothesis import strategies as st  # ImportError without hypothesis

    names = [f for f, _ in FAMILIES] if families is None else list(families)
    eps = [_eps_text(e) for e in eps]

    def make(family, e, seed, index):
        return cases([family], n=index + 1, eps=[e], seed=seed, threads=1)[index]

    return st.builds(make, st.sampled_from(names), st.sampled_from(eps), st.integers(0, 2 ** 32 - 1),
                     st.integers(0, 3))
