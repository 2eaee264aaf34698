"""Exactness and robustness of the Python package at its edges: numpy dtypes read exactly,
pickling at every protocol, objects made by __new__ alone, ==/hash, a second __init__, the threads
argument, integers of any size, and error messages equal to the CLI's."""

import copy
import json
import pickle
import subprocess
import sys
from decimal import Decimal
from fractions import Fraction as F

import numpy
import pytest

import relpos

# z = x^2 + y^2, and an ellipsoid with semi-axes (a, a, 1/4) resting on the vertex, where a^2 is
# slightly more than 1/8: flatter than the cup at the vertex, so it crosses it (C). Rounded to
# float64 (2^61 - 1 -> 2^61), a^2 = 1/8 exactly: then it lies inside and touches (TI; math.md §3).
CUP = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, F(-1, 2)], [0, 0, F(-1, 2), 0]]
CUP_DOUBLES = numpy.array(CUP, dtype=numpy.float64)
FLAT = [[2**61 - 1, 0, 0, 0], [0, 2**61 - 1, 0, 0], [0, 0, 2**62, -(2**60)], [0, 0, -(2**60), 0]]
C, TI = relpos.POSITION_NAMES.index("C"), relpos.POSITION_NAMES.index("TI")


def cli():
    return relpos._cli.find_cli()


def test_flat_ellipsoid_is_c_exactly_and_ti_rounded():
    cup = relpos.Paraboloid(CUP)
    assert relpos.classify(relpos.Ellipsoid(FLAT), cup).position == "C"
    assert relpos.classify(relpos.Ellipsoid(numpy.array(FLAT, dtype=numpy.float64)), cup).position == "TI"


@pytest.mark.parametrize("dtype", [numpy.int64, numpy.longdouble])
def test_decide_positions_reads_wide_dtypes_exactly(dtype):
    E = numpy.array([FLAT] * 3, dtype=dtype)
    assert numpy.array_equal(relpos.decide_positions(E, CUP_DOUBLES), [C] * 3)
    cups = numpy.array([2 * CUP_DOUBLES] * 3, dtype=dtype)  # integers: the cup times 2
    assert numpy.array_equal(relpos.decide_positions(E, cups), [C] * 3)
    assert numpy.array_equal(relpos.decide_positions(E.astype(numpy.float64), CUP_DOUBLES), [TI] * 3)


def test_decide_positions_longdouble_beyond_double_range():
    # The sphere of centre (0, 0, 1/4) through the vertex, with X^T E X lowered by 2^-1100: it dips
    # below the vertex (C). 2^-1100 is a long double; as a float64 it underflows to 0 (TI).
    E = numpy.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.25], [0, 0, -0.25, 0]], dtype=numpy.longdouble)
    E[3, 3] = -numpy.longdouble(2) ** -1100
    assert E[3, 3] != 0 and E.astype(numpy.float64)[3, 3] == 0
    assert relpos.decide_positions(E[None], CUP_DOUBLES).tolist() == [C]
    assert relpos.classify(relpos.Ellipsoid(E), relpos.Paraboloid(CUP)).position == "C"  # scalars exact too


def test_decide_positions_narrow_dtypes_equal_float64():
    E = numpy.array([[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, -1, 0]]] * 2)
    for dtype in (numpy.int8, numpy.int16, numpy.int32, numpy.uint8, numpy.float16, numpy.float32):
        codes = relpos.decide_positions(numpy.abs(E).astype(dtype) * numpy.sign(E), CUP_DOUBLES.astype(numpy.float32))
        assert codes.tolist() == relpos.decide_positions(E.astype(numpy.float64), CUP_DOUBLES).tolist()


@pytest.mark.parametrize("dtype", [complex, bool, object, str, "datetime64[s]"])
def test_decide_positions_refuses_other_dtypes(dtype):
    E = numpy.zeros((2, 4, 4)).astype(dtype)
    with pytest.raises(TypeError, match="dtype"):
        relpos.decide_positions(E, CUP_DOUBLES)
    with pytest.raises(TypeError, match="dtype"):
        relpos.decide_positions(numpy.zeros((2, 4, 4)), CUP_DOUBLES.astype(dtype))


def test_decide_positions_errors_code():
    E = numpy.array([FLAT, numpy.diag([1, -1, 1, -1]), FLAT, numpy.zeros((4, 4))], dtype=numpy.float64)
    E[2, 0, 0] = numpy.nan
    codes = relpos.decide_positions(E, CUP_DOUBLES, errors="code")
    assert codes.tolist() == [TI, relpos.INVALID, relpos.INVALID, relpos.INVALID]
    assert relpos.INVALID not in range(len(relpos.POSITION_NAMES))
    with pytest.raises(ValueError, match=r"E\[1\]: ellipsoid: not an ellipsoid"):
        relpos.decide_positions(E, CUP_DOUBLES, errors="raise")
    bad_cup = numpy.diag([1.0, 1.0, 1.0, -1.0])
    assert relpos.decide_positions(E[:1], bad_cup, errors="code").tolist() == [relpos.INVALID]
    with pytest.raises(ValueError, match="errors"):
        relpos.decide_positions(E, CUP_DOUBLES, errors="ignore")


@pytest.mark.parametrize("threads, error", [(1.5, TypeError), ("2", TypeError), (True, TypeError), (None, TypeError),
                                            (-1, ValueError)])
def test_threads_must_be_a_non_negative_int(threads, error):
    with pytest.raises(error, match="threads"):
        relpos.decide_positions(numpy.array([FLAT]), CUP_DOUBLES, threads=threads)


def test_threads_accepts_int_like():
    assert relpos.decide_positions(numpy.array([FLAT]), CUP_DOUBLES, threads=numpy.int64(2)).tolist() == [C]


def quadrics():
    return [
        relpos.Ellipsoid.sphere((0, "1/3", 0.1), "1/7"),
        relpos.Ellipsoid(FLAT),
        relpos.Paraboloid.standard((1, 2, 3), "1.2", F(3, 7), (1, 2, 3, 4)),
        relpos.Ellipsoid([[10**5000 + 1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]),
    ]


@pytest.mark.parametrize("protocol", range(pickle.HIGHEST_PROTOCOL + 1))
def test_pickle_every_protocol(protocol):
    for q in quadrics():
        back = pickle.loads(pickle.dumps(q, protocol=protocol))
        assert type(back) is type(q) and back.matrix() == q.matrix()


def test_reduce_and_copies():
    for q in quadrics():
        fn, args = q.__reduce__()
        assert fn(*args).matrix() == q.matrix()
        assert copy.copy(q) == q and copy.deepcopy(q) == q


def test_equality_and_hash():
    a = relpos.Ellipsoid.sphere((0, 0, 1), "1/3")
    b = relpos.Ellipsoid([[3, 0, 0, 0], [0, 3, 0, 0], [0, 0, 3, -3], [0, 0, -3, F(8, 3)]])  # the same, times 3
    same = relpos.Ellipsoid(a.matrix())
    assert a == same and hash(a) == hash(same) and len({a, same}) == 1
    assert a != b  # == compares the exact matrices, not the point sets
    assert a != relpos.Ellipsoid.sphere((0, 0, 1), "1/4")
    assert a != relpos.Paraboloid.standard((0, 0, 0), 1, 1) and a != "x"
    c = relpos.classify(a, relpos.Paraboloid.standard((0, 0, 0), 1, 1))
    assert c == relpos.classify(same, relpos.Paraboloid.standard((0, 0, 0), 1, 1))
    with pytest.raises(TypeError):
        hash(c)


UNBUILT_CALLS = [
    lambda x: x.matrix(),
    repr,
    hash,
    lambda x: x == x,
    lambda x: x.__reduce__(),
    lambda x: pickle.dumps(x),
]


@pytest.mark.parametrize("cls", [relpos.Ellipsoid, relpos.Paraboloid])
@pytest.mark.parametrize("call", UNBUILT_CALLS)
def test_unbuilt_quadric_raises_type_error(cls, call):
    x = cls.__new__(cls)
    with pytest.raises(TypeError, match="not built"):
        call(x)


def test_unbuilt_passed_to_functions_raises_type_error():
    e, p = relpos.Ellipsoid.sphere((0, 0, 1), 1), relpos.Paraboloid.standard((0, 0, 0), 1, 1)
    for args in [(relpos.Ellipsoid.__new__(relpos.Ellipsoid), p), (e, relpos.Paraboloid.__new__(relpos.Paraboloid))]:
        with pytest.raises(TypeError, match="not built"):
            relpos.classify(*args)
    c = relpos.Classification.__new__(relpos.Classification)
    for call in (lambda: c.position, lambda: c.as_dict(), lambda: repr(c), lambda: c == c):
        with pytest.raises(TypeError, match="not built"):
            call()


def test_second_init_is_refused():
    e = relpos.Ellipsoid.sphere((0, 0, 1), 1)
    other = relpos.Ellipsoid.sphere((0, 0, 2), 1)
    with pytest.raises(TypeError, match="already built"):
        e.__init__(other.matrix())
    assert e == relpos.Ellipsoid.sphere((0, 0, 1), 1)
    p = relpos.Paraboloid.standard((0, 0, 0), 1, 1)
    with pytest.raises(TypeError, match="already built"):
        p.__init__(CUP)
    c = relpos.classify(e, p)
    with pytest.raises(TypeError, match="already built"):
        c.__init__({})
    # __new__ then __init__ builds the object once.
    x = relpos.Ellipsoid.__new__(relpos.Ellipsoid)
    x.__init__(other.matrix())
    assert x == other


def test_integers_beyond_python_str_limit():
    limit = sys.get_int_max_str_digits() if hasattr(sys, "get_int_max_str_digits") else 4300
    big = 10 ** (limit + 700) + 1  # str(big) raises under the default limit
    e = relpos.Ellipsoid([[big, 0, 0, 0], [0, 1, 0, 0], [0, 0, F(big, 3), 0], [0, 0, 0, -big]])
    m = e.matrix()
    assert m[0][0] == big and m[2][2] == F(big, 3) and m[3][3] == -big
    assert relpos.Ellipsoid.sphere((numpy.int64(1), 0, -big), big - 1).matrix()[2][3] == big
    # Beyond the parser's limit on one number the CLI's message, as for the same digits in JSON.
    huge = 10**10001
    with pytest.raises(ValueError, match=r"ellipsoid\[0\]\[0\]: .*10000-character limit"):
        relpos.Ellipsoid([[huge, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]])


def test_exact_scalar_types():
    e = relpos.Ellipsoid.sphere((Decimal("0.1"), numpy.float32(0.1), numpy.longdouble(1) / 3), F(1, 9))
    m = e.matrix()
    assert m[0][3] == -F(1, 10) and m[1][3] == -F(float(numpy.float32(0.1)))
    assert m[2][3] == -F(*(numpy.longdouble(1) / 3).as_integer_ratio())
    third = relpos.Ellipsoid.sphere((0, 0, 0), F(1, 3))
    assert relpos.Ellipsoid.sphere((0, 0, 0), numpy.array(F(1, 3), dtype=object)) == third  # 0-d: its scalar
    assert relpos.Ellipsoid.sphere((0, 0, 0), numpy.array(0.5)) == relpos.Ellipsoid.sphere((0, 0, 0), 0.5)
    with pytest.raises(TypeError, match=r"ellipsoid.sphere.radius: expected int, float"):
        relpos.Ellipsoid.sphere((0, 0, 0), object())
    with pytest.raises(ValueError, match=r"ellipsoid.sphere.radius: expected a number, got true"):
        relpos.Ellipsoid.sphere((0, 0, 0), numpy.True_)  # as True: a bool is not a number


# Bad inputs given to the Python API and, as the same JSON, to the CLI: identical messages.
BAD_INPUTS = [
    ("ellipsoid", [[1, 0], [0, 1]]),
    ("ellipsoid", [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]),
    ("ellipsoid", [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "x"]]),
    ("ellipsoid", [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, None]]),
    ("ellipsoid", [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 2], [0, 0, 0, -1]]),
    ("ellipsoid", {"sphere": {"center": [0, 0, "y"], "radius": 1}}),
    ("ellipsoid", {"sphere": {"center": [0, 0, 0], "radius": 0}}),
    ("ellipsoid", {"center": [0, 0, 0], "axes": [1, 1]}),
    ("ellipsoid", {"center": [0, 0, 0], "axes": [1, 1, 1], "rotation": [0, 0, 0, 0]}),
    ("ellipsoid", {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, True]]}),
    ("ellipsoid", {"coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, "u"]}),
    ("ellipsoid", {"radius": 1}),
    ("paraboloid", {"vertex": [0, 0, 0], "a": 1, "b": -1}),
    ("paraboloid", {"vertex": [0, 0, 0], "a": 1, "b": "z"}),
    ("paraboloid", {"vertex": [0, 0, 0], "a": 1, "b": 1, "rotation": [1, 0, 0, "r"]}),
    ("paraboloid", [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]),
]


@pytest.mark.parametrize("role, value", BAD_INPUTS)
def test_error_messages_equal_the_clis(role, value):
    good = {"ellipsoid": {"sphere": {"center": [0, 0, 1], "radius": 1}}, "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}}
    pair = dict(good, **{role: value})
    out = subprocess.run([cli(), "batch", "-"], input=(json.dumps(pair) + "\n").encode(), stdout=subprocess.PIPE,
                         check=True).stdout
    expected = json.loads(out)["error"]
    run = subprocess.run([cli(), "classify", "--json", "--ellipsoid", json.dumps(pair["ellipsoid"]), "--paraboloid",
                          json.dumps(pair["paraboloid"])], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert run.returncode == 1 and json.loads(run.stdout)["error"] == expected
    assert run.stderr.decode().strip().splitlines()[-1] == "relpos: " + expected
    cls = relpos.Ellipsoid if role == "ellipsoid" else relpos.Paraboloid
    with pytest.raises(ValueError) as info:
        cls(value)
    assert str(info.value) == expected


def test_geometric_constructors_errors_equal_the_clis():
    """The keyword constructors build the CLI's JSON forms, so their messages are the CLI's too."""
    cases = [
        (lambda: relpos.Ellipsoid.sphere((0, 0, "y"), 1), {"sphere": {"center": [0, 0, "y"], "radius": 1}}),
        (lambda: relpos.Ellipsoid.sphere((0, 0, 0), "-1"), {"sphere": {"center": [0, 0, 0], "radius": "-1"}}),
        (lambda: relpos.Ellipsoid.from_axes((0, 0, 0), (1, 1, 1), (0, 0, 0, 0)),
         {"center": [0, 0, 0], "axes": [1, 1, 1], "rotation": [0, 0, 0, 0]}),
        (lambda: relpos.Ellipsoid.from_axes((0, 0), (1, 1, 1)), {"center": [0, 0], "axes": [1, 1, 1], "rotation": [1, 0, 0, 0]}),
    ]
    for make, value in cases:
        with pytest.raises(ValueError) as info:
            make()
        with pytest.raises(ValueError) as same:
            relpos.Ellipsoid(value)
        assert str(info.value) == str(same.value)
    with pytest.raises(ValueError) as info:
        relpos.Paraboloid.standard((0, 0, 0), 1, "z")
    assert str(info.value).startswith("paraboloid.b: not an exact number")
