"""Tests of the Python package relpos (doc/python.md), run by CTest (test "python").

Environment: PYTHONPATH holds the built package (build/python), RELPOS_CLI the built `relpos` CLI
(the reference every answer is compared with), RELPOS_SOURCE_DIR the source tree (examples/).
"""

import io
import json
import os
import subprocess
from fractions import Fraction

import numpy
import pytest

import relpos

SOURCE_DIR = os.environ.get(
    "RELPOS_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
)
EXAMPLES = os.path.join(SOURCE_DIR, "examples", "mixed.jsonl")


def cli():
    return relpos._cli.find_cli()


def cli_batch(text):
    """`relpos batch` on the given JSON Lines text: the list of answer objects."""
    out = subprocess.run([cli(), "batch", "-"], input=text.encode(), stdout=subprocess.PIPE, check=True).stdout
    return [json.loads(line) for line in out.decode().splitlines()]


F = Fraction


def sphere_matrix(c, r):
    c = [F(x) for x in c]
    r = F(r)
    return [
        [F(1), F(0), F(0), -c[0]],
        [F(0), F(1), F(0), -c[1]],
        [F(0), F(0), F(1), -c[2]],
        [-c[0], -c[1], -c[2], sum(x * x for x in c) - r * r],
    ]


# ------------------------------------------------------------------------------------------------
# Construction
# ------------------------------------------------------------------------------------------------

UNIT_SPHERE = sphere_matrix((0, 0, 0), 1)


@pytest.mark.parametrize(
    "entries",
    [
        [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]],  # int
        [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, -1.0]],  # float
        [[F(1), F(0), F(0), F(0)], [F(0), F(1), F(0), F(0)], [F(0), F(0), F(1), F(0)], [F(0), F(0), F(0), F(-1)]],
        [["1", "0", "0/7", "0"], ["0", "1.0", "0", "0"], ["0", "0", "2/2", "0"], ["0", "0", "0", "-1e0"]],  # str
        numpy.diag([1.0, 1.0, 1.0, -1.0]),  # numpy float64
        numpy.diag([1, 1, 1, -1]),  # numpy int64
        numpy.diag([1, 1, 1, -1]).astype(numpy.float32),  # numpy float32
        [(1, 0.0, F(0), "0"), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, -1)],  # mixed, tuples
    ],
)
def test_ellipsoid_entry_types(entries):
    assert relpos.Ellipsoid(entries).matrix() == UNIT_SPHERE


def test_entries_are_exact():
    # 0.1 as a float is the dyadic double, as a str 1/10; big ints and fractions stay exact.
    big = 10**40 + 1
    m = relpos.Ellipsoid([[big, 0, 0, 0], [0, "0.1", 0, 0], [0, 0, F(big, 3), 0], [0, 0, 0, -0.1]]).matrix()
    assert m[0][0] == big
    assert m[1][1] == F(1, 10)
    assert m[2][2] == F(big, 3)
    assert m[3][3] == F(-0.1) and m[3][3] != F(-1, 10)
    assert all(isinstance(x, Fraction) for row in m for x in row)


def test_double_matrices_take_the_doubles_path_with_the_readers_answers():
    # A matrix of doubles (float64 array, floats and small ints) is built by from_doubles; the same
    # numbers as a {"matrix": ...} description take the exact reader. Both must give equal objects
    # and byte-identical reports, for both orientations, and the doubles that are not plain floats
    # (2^53 + 1, float32, big-endian float64) must still be read exactly.
    rng = numpy.random.default_rng(5)
    for _ in range(200):
        a, b = rng.uniform(0.5, 2.0, 2)
        x, y = rng.uniform(-1, 1, 2)
        z = x * x / (a * a) + y * y / (b * b) + rng.uniform(-0.3, 0.3)
        r = rng.uniform(0.01, 0.3)
        E = numpy.eye(4)
        E[:3, 3] = E[3, :3] = -numpy.array([x, y, z])
        E[3, 3] = x * x + y * y + z * z - r * r
        P = numpy.zeros((4, 4))
        P[0, 0], P[1, 1] = 1 / (a * a), 1 / (b * b)
        P[2, 3] = P[3, 2] = -0.5
        for s in (1, -1):
            forms_e = (s * E, (s * E).tolist(), {"matrix": (s * E).tolist()})
            forms_p = (s * P, (s * P).tolist(), {"matrix": (s * P).tolist()})
            es = [relpos.Ellipsoid(m) for m in forms_e]
            ps = [relpos.Paraboloid(m) for m in forms_p]
            assert es[0] == es[1] == es[2] and ps[0] == ps[1] == ps[2]
            for full in (False, True):
                texts = {relpos._relpos._classify_json(e, p, full) for e, p in zip(es, ps)}
                assert len(texts) == 1
    big = 2**53 + 1  # not a double: the exact reader
    assert relpos.Ellipsoid([[big, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]).matrix()[0][0] == big
    swapped = numpy.diag([1.0, 1.0, 1.0, -0.1]).astype(">f8")
    assert relpos.Ellipsoid(swapped).matrix()[3][3] == F(-0.1)
    with pytest.raises(ValueError, match="not symmetric"):
        relpos.Ellipsoid(numpy.array([[1.0, 2, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]))
    with pytest.raises(ValueError, match="imaginary"):
        relpos.Ellipsoid(numpy.eye(4))


def test_geometric_constructors():
    assert relpos.Ellipsoid.sphere((0, "1/2", 0.25), "1/4").matrix() == sphere_matrix((0, F(1, 2), F(1, 4)), F(1, 4))
    # Axes (1/4, 1/8, 1/8) without rotation: diag(16, 64, 64) scaled; compare with the coefficients
    # form up to the positive factor the constructor chooses.
    m = relpos.Ellipsoid.from_axes((0, 0, 1), ("1/4", "1/8", "1/8")).matrix()
    expected = [[16, 0, 0, 0], [0, 64, 0, 0], [0, 0, 64, -64], [0, 0, -64, 63]]
    k = m[0][0] / 16
    assert k > 0 and all(m[i][j] == k * expected[i][j] for i in range(4) for j in range(4))
    # A quarter turn about z swaps the x and y axes.
    r = relpos.Ellipsoid.from_axes((0, 0, 0), (1, 2, 3), (1, 0, 0, 1)).matrix()
    assert r[0][0] / r[1][1] == F(1, 4) and r[0][1] == 0
    p = relpos.Paraboloid.standard((0, 0, 0), 1, 2).matrix()
    q = [[1, 0, 0, 0], [0, F(1, 4), 0, 0], [0, 0, 0, F(-1, 2)], [0, 0, F(-1, 2), 0]]
    k = p[0][0]
    assert k > 0 and all(p[i][j] == k * q[i][j] for i in range(4) for j in range(4))
    assert relpos.Paraboloid(p).matrix() == p
    assert relpos.Paraboloid.standard((0, 0, 0), 1, 1, rotation=(0, 1, 0, 0)).matrix()[2][3] > 0  # opens along -z


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: relpos.Ellipsoid([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]), "hyperboloid"),
        (lambda: relpos.Ellipsoid([[1, 0], [0, 1]]), "expected a 4x4 array"),
        (lambda: relpos.Ellipsoid(numpy.zeros((4, 3))), "expected a row of 4 numbers"),
        (lambda: relpos.Ellipsoid([[float("nan"), 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]), "nan"),
        (lambda: relpos.Ellipsoid([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "x"]]), "[3][3]"),
        (lambda: relpos.Ellipsoid([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, None]]), "got null"),
        (lambda: relpos.Ellipsoid.sphere((0, 0, 0), 0), "radius"),
        (lambda: relpos.Paraboloid(UNIT_SPHERE), "paraboloid"),
        (lambda: relpos.Paraboloid.standard((0, 0, 0), 1, -1), "paraboloid"),
    ],
)
def test_bad_input_raises_value_error(make, message):
    with pytest.raises(ValueError) as info:
        make()
    assert message in str(info.value)


def test_hyperboloid_message_is_the_clis():
    h = [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]
    line = json.dumps({"id": 1, "ellipsoid": h, "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}})
    [answer] = cli_batch(line + "\n")
    with pytest.raises(ValueError) as info:
        relpos.Ellipsoid(h)
    assert str(info.value) == answer["error"]


def test_pickle_round_trip():
    import pickle

    e = relpos.Ellipsoid.sphere((0, 0, 1), "1/3")
    p = relpos.Paraboloid.standard((0, 0, 0), "1.2", "1.5")
    assert pickle.loads(pickle.dumps(e)).matrix() == e.matrix()
    assert pickle.loads(pickle.dumps(p)).matrix() == p.matrix()


def test_version():
    out = subprocess.run([cli(), "--version"], stdout=subprocess.PIPE, check=True).stdout.decode()
    assert out.split()[-1] == relpos.__version__


# ------------------------------------------------------------------------------------------------
# classify equals the CLI
# ------------------------------------------------------------------------------------------------


def quadric_from_json(value, role):
    """The pair's quadric from a batch line's JSON value (numbers kept as decimal text): the
    constructors take every JSON form of the CLI."""
    return (relpos.Ellipsoid if role == "ellipsoid" else relpos.Paraboloid)(value)


def reject(constant):
    raise ValueError("not JSON: " + constant)  # NaN, Infinity: invalid JSON for the CLI


def test_classify_equals_cli_on_examples():
    lines = [l for l in open(EXAMPLES, encoding="utf-8").read().splitlines()]
    answers = cli_batch("\n".join(lines) + "\n")
    assert len(answers) == len(lines)
    compared = errors = 0
    for line, answer in zip(lines, answers):
        try:
            doc = json.loads(line, parse_float=str, parse_constant=reject)  # decimal text kept, as the CLI reads it
        except ValueError:
            continue
        if not isinstance(doc, dict) or "ellipsoid" not in doc or "paraboloid" not in doc:
            continue
        if set(doc) - {"id", "ellipsoid", "paraboloid", "comment"}:
            continue  # a line-level error of the batch format, not of the pair
        try:
            e = quadric_from_json(doc["ellipsoid"], "ellipsoid")
            p = quadric_from_json(doc["paraboloid"], "paraboloid")
        except ValueError as err:
            assert answer.get("error") == str(err), line
            errors += 1
            continue
        if "error" in answer:
            with pytest.raises(ValueError):
                relpos.classify(e, p)
            errors += 1
            continue
        expected = {k: v for k, v in answer.items() if k != "id"}
        got = relpos.classify(e, p)
        assert got.as_dict() == expected, line
        assert got.position == expected["position"] and got.small == expected["small"]
        assert got.contact == expected["contact"] and got.rule == expected["rule"] and got.stage == expected["stage"]
        minimal = relpos.classify(e, p, evidence="minimal")
        assert minimal.position == got.position and minimal.rule == got.rule
        compared += 1
    assert compared >= 50, compared  # every pair of the example lines without a line-level error
    assert errors >= 1


def test_classify_readme_example():
    p = relpos.Paraboloid.standard((0, 0, 0), "1.2", "1.5")
    e = relpos.Ellipsoid.sphere((0, "0.5", "92281/129600"), F(1, 4))
    c = relpos.classify(e, p)
    assert c.position == "I" and c.small is True and c.contact is False
    assert "f" in c.as_dict() and "multiple_roots" in c.as_dict()
    with pytest.raises(ValueError):
        relpos.classify(e, p, evidence="some")


# ------------------------------------------------------------------------------------------------
# decide_positions
# ------------------------------------------------------------------------------------------------


def sphere_doubles(c, r):
    cx, cy, cz = c
    return numpy.array(
        [[1, 0, 0, -cx], [0, 1, 0, -cy], [0, 0, 1, -cz], [-cx, -cy, -cz, cx * cx + cy * cy + cz * cz - r * r]],
        dtype=numpy.float64,
    )


def paraboloid_doubles(a, b):
    return numpy.array(
        [[1 / (a * a), 0, 0, 0], [0, 1 / (b * b), 0, 0], [0, 0, 0, -0.5], [0, 0, -0.5, 0]], dtype=numpy.float64
    )


def random_pairs(n, seed):
    """Small spheres near the cup of z = x^2/a^2 + y^2/b^2, plus exact tangencies at the vertex."""
    rng = numpy.random.default_rng(seed)
    E = numpy.empty((n, 4, 4))
    P = numpy.empty((n, 4, 4))
    for i in range(n):
        a, b = rng.uniform(0.5, 2.0, 2)
        if i % 10 == 0:  # vertex tangency from inside (r <= min(a, b)^2 / 2) or from outside
            r = 2.0 ** -int(rng.integers(2, 5))
            E[i] = sphere_doubles((0.0, 0.0, r if i % 20 == 0 else -r), r)
            a, b = 1.0, 1.5
        else:
            x, y = rng.uniform(-1, 1, 2)
            z = x * x / (a * a) + y * y / (b * b) + rng.uniform(-0.3, 0.3)
            E[i] = sphere_doubles((x, y, z), rng.uniform(0.01, 0.3))
        P[i] = paraboloid_doubles(a, b)
    return E, P


def code_of(position):
    return relpos.POSITION_NAMES.index(position) if position in relpos.POSITION_NAMES else -1


def test_decide_positions_equals_classify():
    E, P = random_pairs(2000, seed=13)
    codes = relpos.decide_positions(E, P)
    assert codes.dtype == numpy.int8 and codes.shape == (2000,)
    expected = numpy.array(
        [code_of(relpos.classify(relpos.Ellipsoid(E[i]), relpos.Paraboloid(P[i]), "minimal").position) for i in range(2000)],
        dtype=numpy.int8,
    )
    assert numpy.array_equal(codes, expected)
    counts = {relpos.POSITION_NAMES[k]: int((codes == k).sum()) for k in range(5)}
    assert all(counts[name] > 0 for name in ("I", "TI", "C", "TE", "E")), counts
    # One thread, several threads and a shared paraboloid give the same codes.
    assert numpy.array_equal(relpos.decide_positions(E, P, threads=1), codes)
    assert numpy.array_equal(relpos.decide_positions(E, P, threads=3), codes)
    shared = paraboloid_doubles(1.0, 1.5)
    mask = numpy.all(P == shared, axis=(1, 2))
    assert mask.sum() >= 100
    assert numpy.array_equal(relpos.decide_positions(E[mask], shared), codes[mask])


def test_decide_positions_equals_cli_double_oracle():
    """The float64 API and the CLI's oracle mode (`batch --numbers double --evidence minimal`: each
    JSON number is the double nearest its text) answer the same pairs alike, and so does the exact
    reading when the text is the double's exact value (short dyadics)."""
    E, P = random_pairs(600, seed=29)
    codes = relpos.decide_positions(E, P)
    lines = []
    for i in range(len(E)):
        lines.append(json.dumps({"id": i, "ellipsoid": {"matrix": E[i].tolist()}, "paraboloid": {"matrix": P[i].tolist()}}))
    text = "\n".join(lines) + "\n"
    out = subprocess.run(
        [cli(), "batch", "--numbers", "double", "--evidence", "minimal", "-"],
        input=text.encode(),
        stdout=subprocess.PIPE,
        check=True,
    ).stdout
    answers = [json.loads(line) for line in out.decode().splitlines()]
    assert [a["id"] for a in answers] == list(range(len(E)))
    assert numpy.array_equal(numpy.array([code_of(a["position"]) for a in answers], dtype=numpy.int8), codes)
    # json.dumps writes repr(x), the shortest text that reads back as x; read exactly, that text is
    # another rational when x is not a short dyadic (1/b^2 here). The vertex tangencies keep their
    # position under that change (a sphere on the axis touching the vertex: TE for any b, TI while
    # r < min(a, b)^2 / 2 with room to spare), so the default exact reading must agree on them.
    dyadic = [i for i in range(0, len(E), 10)]
    exact = cli_batch("\n".join(lines[i] for i in dyadic) + "\n")
    assert [code_of(a["position"]) for a in exact] == [int(codes[i]) for i in dyadic]


def test_decide_positions_bad_input():
    E, P = random_pairs(20, seed=1)
    E[7] = numpy.diag([1.0, -1.0, 1.0, -1.0])  # a hyperboloid
    with pytest.raises(ValueError, match=r"E\[7\]: ellipsoid: not an ellipsoid: .*hyperboloid"):
        relpos.decide_positions(E, P)
    E[7, 0, 0] = numpy.nan
    with pytest.raises(ValueError, match=r"E\[7\]"):
        relpos.decide_positions(E, P)
    E, P = random_pairs(20, seed=1)
    P[3] = numpy.diag([1.0, 1.0, 1.0, -1.0])
    with pytest.raises(ValueError, match=r"P\[3\]: paraboloid"):
        relpos.decide_positions(E, P)
    with pytest.raises(ValueError, match=r"P: paraboloid"):
        relpos.decide_positions(E, numpy.diag([1.0, 1.0, 1.0, -1.0]))
    with pytest.raises(ValueError, match="shape"):
        relpos.decide_positions(E[:, :3], P)
    with pytest.raises(ValueError, match="matrices for"):
        relpos.decide_positions(E, P[:5])
    with pytest.raises(TypeError, match="dtype"):
        relpos.decide_positions(E.astype(complex), P)
    assert relpos.decide_positions(numpy.empty((0, 4, 4)), paraboloid_doubles(1, 1)).shape == (0,)


# ------------------------------------------------------------------------------------------------
# plot
# ------------------------------------------------------------------------------------------------


def test_plot_agg():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    e = relpos.Ellipsoid.sphere((0, 0, "1/4"), "1/4")
    p = relpos.Paraboloid.standard((0, 0, 0), 1, 1)
    ax = relpos.plot(e, p)
    assert ax.get_title().startswith("TI")
    buf = io.BytesIO()
    ax.figure.savefig(buf, format="png", dpi=40)
    assert buf.getvalue()[:4] == b"\x89PNG"
    plt.close(ax.figure)
    fig = plt.figure()
    ax2 = fig.add_subplot(projection="3d")
    assert relpos.plot(relpos.Ellipsoid.sphere((0, 0, -3), 1), p, ax=ax2) is ax2
    assert ax2.get_title().startswith("E")
    plt.close(fig)
