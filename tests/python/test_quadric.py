"""relpos.Quadric and the general pair in Python (doc/python.md, "Any real quadric"): balls whose
position against each type is known by elementary geometry get it from classify, decide_positions and
`relpos scene --quadric`; every answer equals the line `relpos batch` writes for the same input,
every certificate passes relpos.verify and `relpos verify`, tampered ones are refused; constructors,
errors, pickling and equality as for Ellipsoid and Paraboloid."""

import json
import os
import pickle
import subprocess
import tempfile
from fractions import Fraction as F

import numpy
import pytest

import relpos

H = {"type": "hyperboloid of one sheet", "center": [0, 0, 0], "axes": [1, 1, 1]}
SPHERE3 = {"type": "sphere", "center": [0, 0, 0], "radius": 3}
CYLINDER = {"type": "elliptic cylinder", "center": [0, 0, 0], "a": 1, "b": 1}
HALF = {"type": "half-space", "normal": [0, 0, 1], "offset": 0}
SLAB = {"type": "slab", "normal": [0, 0, 1], "low": 0, "high": 4}
CONE = {"type": "elliptic cone", "apex": [0, 0, 0], "a": 1, "b": 1}


def ball(center, radius2):
    """The ball |x - center|^2 <= radius2 as the CLI's coefficients form (radius2 need not be a square)."""
    cx, cy, cz = (F(c) for c in center)
    return {"coefficients": ["1", "1", "1", "0", "0", "0", str(-2 * cx), str(-2 * cy), str(-2 * cz),
                             str(cx * cx + cy * cy + cz * cz - F(radius2))]}


# (quadric, ellipsoid, position): each by elementary geometry (doc/quadrics.md).
CASES = [
    # x^2 + y^2 - z^2 <= 1: its waist is the unit circle.
    (H, ball((0, 0, 0), "1/4"), "I"),
    (H, ball((0, 0, 0), 1), "TI"),  # along the waist circle: the hard case
    (H, ball((2, 0, 0), 1), "TE"),  # at (1, 0, 0): q = 2(u + 1)^2 + 2v^2 >= 0 on the ball
    (H, ball((1, 0, 0), "1/4"), "C"),  # centre on the surface
    (H, ball((4, 0, 0), 1), "E"),
    # the ball of radius 3: also O, TO and EQ
    (SPHERE3, ball((0, 0, 0), 1), "I"),
    (SPHERE3, ball((2, 0, 0), 1), "TI"),
    (SPHERE3, ball((3, 0, 0), 1), "C"),
    (SPHERE3, ball((4, 0, 0), 1), "TE"),
    (SPHERE3, ball((5, 0, 0), 1), "E"),
    (SPHERE3, ball((0, 0, 0), 16), "O"),
    (SPHERE3, ball((1, 0, 0), 16), "TO"),  # (-3, 0, 0) is 4 from (1, 0, 0)
    (SPHERE3, ball((0, 0, 0), 9), "EQ"),
    # the tube x^2 + y^2 <= 1
    (CYLINDER, ball((0, 0, 5), "1/4"), "I"),
    (CYLINDER, ball((0, 0, 5), 1), "TI"),
    (CYLINDER, ball((2, 0, 0), 1), "TE"),
    (CYLINDER, ball((1, 0, 0), "1/4"), "C"),
    (CYLINDER, ball((3, 0, 0), 1), "E"),
    # z <= 0 and 0 <= z <= 4
    (HALF, ball((0, 0, -2), 1), "I"),
    (HALF, ball((0, 0, -1), 1), "TI"),
    (HALF, ball((0, 0, 0), 1), "C"),
    (HALF, ball((0, 0, 1), 1), "TE"),
    (HALF, ball((0, 0, 2), 1), "E"),
    (SLAB, ball((0, 0, 2), 1), "I"),
    (SLAB, ball((0, 0, 2), 4), "TI"),  # touches both planes
    (SLAB, ball((0, 0, 4), 1), "C"),
    (SLAB, ball((0, 0, 6), 4), "TE"),
    (SLAB, ball((0, 0, 7), 4), "E"),
    # x^2 + y^2 <= z^2: the lines z = +-x are sqrt(2) from (0, 0, 2) and from (2, 0, 0)
    (CONE, ball((0, 0, 2), 1), "I"),
    (CONE, ball((0, 0, 2), 2), "TI"),  # along a circle
    (CONE, ball((0, 0, 0), 1), "C"),  # around the apex
    (CONE, ball((2, 0, 0), 2), "TE"),  # at the two points (1, 0, +-1)
    (CONE, ball((2, 0, 0), 1), "E"),
]


def cli():
    return relpos._cli.find_cli()


def cli_batch(lines, *options):
    text = "".join(json.dumps(line) + "\n" for line in lines)
    out = subprocess.run([cli(), "batch", *options], input=text.encode(), stdout=subprocess.PIPE, check=True).stdout
    return [json.loads(x) for x in out.decode().splitlines()]


def lines():
    return [{"id": k, "ellipsoid": e, "quadric": q} for k, (q, e, _) in enumerate(CASES)]


def test_positions_by_construction_equal_the_cli_and_verify():
    full, minimal = cli_batch(lines()), cli_batch(lines(), "--evidence", "minimal")
    kinds = set()
    for k, (q, e, expected) in enumerate(CASES):
        quadric, ellipsoid = relpos.Quadric(q), relpos.Ellipsoid(e)
        c = relpos.classify(ellipsoid, quadric)
        assert isinstance(c, relpos.QuadricClassification)
        assert c.position == expected, (k, q, e)
        assert c.quadric_type == quadric.type
        assert c.contact == {"I": "none", "E": "none", "O": "none", "C": "crossing"}.get(expected, "touching")
        assert c.as_dict() == {key: v for key, v in full[k].items() if key != "id"}
        m = relpos.classify(ellipsoid, quadric, evidence="minimal")
        assert m.as_dict() == {key: v for key, v in minimal[k].items() if key != "id"}
        assert relpos.verify(ellipsoid, quadric, c) is None
        kinds.add(c.certificate.kind)
        # The certificate does not prove another position.
        wrong = relpos.QuadricClassification(dict(c.as_dict(), position="C" if expected != "C" else "I"))
        with pytest.raises(relpos.CertificateError):
            relpos.verify(ellipsoid, quadric, wrong)
    assert kinds == {"definite", "tangent", "hard-tangent", "crossing", "equal"}
    # `relpos verify` accepts the answers Python gave.
    answers = [dict(relpos.classify(relpos.Ellipsoid(e), relpos.Quadric(q)).as_dict(), id=k)
               for k, (q, e, _) in enumerate(CASES)]
    with tempfile.TemporaryDirectory() as tmp:
        given, got = os.path.join(tmp, "in.jsonl"), os.path.join(tmp, "answers.jsonl")
        with open(given, "w") as f:
            f.writelines(json.dumps(x) + "\n" for x in lines())
        with open(got, "w") as f:
            f.writelines(json.dumps(x) + "\n" for x in answers)
        v = subprocess.run([cli(), "verify", given, got], stdout=subprocess.PIPE, text=True)
        assert v.returncode == 0 and v.stdout.startswith("verified %d, failed 0" % len(CASES)), v.stdout


def test_tampered_certificates_are_refused():
    for q, e, expected in CASES:
        quadric, ellipsoid = relpos.Quadric(q), relpos.Ellipsoid(e)
        fields = relpos.classify(ellipsoid, quadric).as_dict()
        cert = fields["certificate"]
        if isinstance(cert.get("t"), str):
            cert["t"] = cert["t"][1:] if cert["t"].startswith("-") else "-" + cert["t"]
        elif "ratio" in cert:
            cert["ratio"] = str(2 * F(cert["ratio"]))
        elif "inside" in cert:
            cert["inside"], cert["outside"] = cert["outside"], cert["inside"]
        else:
            cert["contact_set"]["radius2"]["a"] = "-1"
        with pytest.raises(relpos.CertificateError):
            relpos.verify(ellipsoid, quadric, relpos.QuadricClassification(fields))


def test_decide_positions_against_one_quadric():
    by_quadric = {}
    for q, e, expected in CASES:
        by_quadric.setdefault(json.dumps(q), []).append((e, expected))
    for q, bodies in by_quadric.items():
        quadric = relpos.Quadric(json.loads(q))
        matrices = numpy.array([[[float(x) for x in row] for row in relpos.Ellipsoid(e).matrix()] for e, _ in bodies])
        codes = relpos.decide_positions(matrices, quadric, threads=2)
        assert codes.dtype == numpy.int8
        assert [relpos.QUADRIC_POSITION_NAMES[c] for c in codes] == [p for _, p in bodies]
    # Parameters as a float code holds them, against a rotated ellipsoid: 200 random balls, each as
    # classify decides it.
    rng = numpy.random.default_rng(36)
    centers = rng.uniform(-3, 3, (200, 3))
    axes = rng.uniform(0.2, 2, (200, 3))
    rotation = rng.integers(-3, 4, (200, 4)).astype(float)
    rotation[:, 0] += 10  # never the zero quaternion
    q = relpos.Quadric.ellipsoid((0, 0, "1/2"), (2, 1, "3/2"), (1, 2, 0, 1))
    codes = relpos.decide_positions({"center": centers, "axes": axes, "rotation": rotation}, q)
    for i in range(200):
        e = relpos.Ellipsoid.from_axes(centers[i], axes[i], rotation[i])
        assert relpos.QUADRIC_POSITION_NAMES[codes[i]] == relpos.classify(e, q, evidence="minimal").position
    # A matrix that is not an ellipsoid: named, or the code INVALID.
    bad = numpy.array([numpy.eye(4), numpy.diag([1.0, 1.0, 1.0, 1.0])])
    bad[0, 3, 3] = -1
    with pytest.raises(ValueError, match=r"^E\[1\]: ellipsoid: "):
        relpos.decide_positions(bad, q)
    first = relpos.QUADRIC_POSITION_NAMES.index(relpos.classify(relpos.Ellipsoid(bad[0]), q).position)
    assert list(relpos.decide_positions(bad, q, errors="code")) == [first, relpos.INVALID]


def test_scene_cli_equals_classify():
    bodies = [{"id": k, "ellipsoid": e} for k, (q, e, _) in enumerate(CASES) if q is H]
    text = "".join(json.dumps(b) + "\n" for b in bodies)
    for threads in ("1", "2"):
        run = subprocess.run([cli(), "scene", "--quadric", json.dumps(H), "--threads", threads, "--no-progress"],
                             input=text.encode(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, check=True)
        answers = [json.loads(x) for x in run.stdout.decode().splitlines()]
        assert [a["id"] for a in answers] == [b["id"] for b in bodies]
        for a, b in zip(answers, bodies):
            c = relpos.classify(relpos.Ellipsoid(b["ellipsoid"]), relpos.Quadric(H), evidence="minimal")
            assert (a["position"], a["stage"]) == (c.position, c.stage)
            assert a["contact"] == (c.contact != "none")
        summary = json.loads(run.stderr.decode().splitlines()[-1])["summary"]
        assert summary["positions"] == {"I": 1, "TI": 1, "C": 1, "TE": 1, "E": 1}
        assert summary["bodies"] == len(bodies)


def test_constructors_and_values():
    assert relpos.Quadric(H).type == "hyperboloid of one sheet"
    forms = {
        "sphere": relpos.Quadric.sphere((0, 0, 0), 1),
        "ellipsoid": relpos.Quadric.ellipsoid((0, 0, 0), (1, 2, 3), (1, 1, 0, 0)),
        "hyperboloid of one sheet": relpos.Quadric.hyperboloid_one_sheet((0, 0, 0), (1, 1, 1)),
        "hyperboloid of two sheets": relpos.Quadric.hyperboloid_two_sheets((0, 0, 0), (1, 1, 1)),
        "elliptic cone": relpos.Quadric.cone((0, 0, 0), 1, 2),
        "elliptic paraboloid": relpos.Quadric.elliptic_paraboloid((0, 0, 0), 1, 2),
        "hyperbolic paraboloid": relpos.Quadric.hyperbolic_paraboloid((0, 0, 0), 1, 2),
        "elliptic cylinder": relpos.Quadric.elliptic_cylinder((0, 0, 0), 1, 2),
        "hyperbolic cylinder": relpos.Quadric.hyperbolic_cylinder((0, 0, 0), 1, 2),
        "parabolic cylinder": relpos.Quadric.parabolic_cylinder((0, 0, 0), 1),
        "slab": relpos.Quadric.slab((0, 0, 1), 0, 1),
        "half-space": relpos.Quadric.half_space((0, 0, 1), 0),
    }
    for name, q in forms.items():
        assert q.type == ("ellipsoid" if name == "sphere" else name)
        assert relpos.Quadric(q.matrix()) == q  # the exact matrix reads back
        assert pickle.loads(pickle.dumps(q)) == q and hash(pickle.loads(pickle.dumps(q))) == hash(q)
        assert repr(q).startswith("relpos.Quadric([[")
    assert set(q.type for q in forms.values()) == set(relpos.QUADRIC_TYPES)
    e = relpos.Ellipsoid.sphere((0, 0, 0), 1)
    assert relpos.Quadric.of(e) == relpos.Quadric.sphere((0, 0, 0), 1)
    assert relpos.Quadric.of(relpos.Paraboloid.standard((0, 0, 0), 1, 1)).type == "elliptic paraboloid"
    assert relpos.Quadric.from_coefficients([1, 1, 1, 0, 0, 0, 0, 0, 0, -1]) == relpos.Quadric.sphere((0, 0, 0), 1)
    # float64 matrices take from_doubles: the same quadric as the exact reader's
    m = numpy.diag([1.0, 1.0, -1.0, -1.0])
    assert relpos.Quadric(m) == relpos.Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]])


def test_errors_are_the_clis():
    bad = [
        [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]],  # a line
        {"type": "sphere", "center": [0, 0, 0], "radius": -1},
        {"type": "torus"},
        {"type": "slab", "normal": [0, 0, 1], "low": 1, "high": 1},
        {"matrix": [[1, 0], [0, 1]]},
    ]
    e = {"sphere": {"center": [0, 0, 0], "radius": 1}}
    answers = cli_batch([{"id": k, "ellipsoid": e, "quadric": q} for k, q in enumerate(bad)])
    for q, a in zip(bad, answers):
        with pytest.raises(ValueError) as err:
            relpos.Quadric(q)
        assert str(err.value) == a["error"]
    # The pair size limit (doc/cli.md, Limits): a ball of radius 10^-2000 has a primitive integer form of
    # about 13 000 bits; classify, decide_positions and `relpos scene --quadric` refuse it as the batch
    # line does.
    tiny = {"type": "sphere", "center": [0, 0, 0], "radius": "1e-2000"}
    line = cli_batch([{"id": 0, "ellipsoid": e, "quadric": tiny}])[0]
    assert line["error"].startswith("numbers too large: ")
    with pytest.raises(ValueError) as err:
        relpos.classify(relpos.Ellipsoid(e), relpos.Quadric(tiny))
    assert str(err.value) == line["error"]
    with pytest.raises(ValueError) as err:
        relpos.decide_positions(numpy.array([numpy.diag([1.0, 1.0, 1.0, -1.0])]), relpos.Quadric(tiny))
    assert str(err.value) == "E[0]: ellipsoid: " + line["error"]
    # ... and a tiny ellipsoid (long doubles, read exactly) against an ordinary quadric.
    small = numpy.diag(numpy.array([1, 1, 1, "-1e-4000"], dtype=numpy.longdouble))
    with pytest.raises(ValueError) as err:
        relpos.classify(relpos.Ellipsoid(small), relpos.Quadric(H))
    assert str(err.value).startswith("numbers too large: ")
    with pytest.raises(ValueError) as by_array:
        relpos.decide_positions(small[None], relpos.Quadric(H))
    assert str(by_array.value) == "E[0]: ellipsoid: " + str(err.value)
    run = subprocess.run([cli(), "scene", "--quadric", json.dumps(tiny), "--no-progress"],
                         input=json.dumps({"ellipsoid": e}) + "\n", capture_output=True, text=True, check=True)
    assert json.loads(run.stdout)["error"] == line["error"]
    ellipsoid, q = relpos.Ellipsoid(e), relpos.Quadric(H)
    with pytest.raises(ValueError, match="margin"):
        relpos.classify(ellipsoid, q, margin=True)
    with pytest.raises(TypeError, match="p must be a relpos.Paraboloid or relpos.Quadric"):
        relpos.classify(ellipsoid, H)
    with pytest.raises(TypeError, match="answer must be a relpos.QuadricClassification"):
        relpos.verify(ellipsoid, q, relpos.classify(ellipsoid, relpos.Paraboloid.standard((0, 0, 0), 1, 1)))
    with pytest.raises(TypeError):
        relpos.contact(ellipsoid, q)  # the contact-only predicate is the paraboloid's
    with pytest.raises(TypeError, match="decide_positions"):
        relpos.scene(q, [ellipsoid])
    with pytest.raises(TypeError, match="not built"):
        relpos.classify(ellipsoid, relpos.Quadric.__new__(relpos.Quadric))
    with pytest.raises(TypeError, match="already built"):
        q.__init__(H)


# ------------------------------------------------------------------------------------------------
# plot: every type drawn (doc/python.md, "Any real quadric"; doc/quadrics.md, "Figures")
# ------------------------------------------------------------------------------------------------

# (ellipsoid, quadric, position) known by elementary geometry, one pair per type.
DRAWN = [
    (relpos.Ellipsoid.sphere((0, 0, 0), 2), relpos.Quadric.ellipsoid((0, 0, 0), (1, "1/2", "1/3")), "O"),
    (relpos.Ellipsoid.sphere((0, 0, 0), 1), relpos.Quadric.hyperboloid_one_sheet((0, 0, 0), (1, 1, 1)), "TI"),
    (relpos.Ellipsoid.sphere((0, 0, 0), 1), relpos.Quadric.hyperboloid_two_sheets((0, 0, 0), (1, 1, 1)), "TE"),
    (relpos.Ellipsoid.sphere((0, 0, 2), "1/2"), relpos.Quadric.cone((0, 0, 0), 1, 1), "I"),
    (relpos.Ellipsoid.sphere((0, 0, -1), "1/2"), relpos.Quadric.elliptic_paraboloid((0, 0, 0), 1, 1), "E"),
    # rotated; its vertex, a point of the surface, strictly inside the ball
    (relpos.Ellipsoid.sphere((0, 0, 0), "1/2"), relpos.Quadric.hyperbolic_paraboloid((0, 0, "1/4"), 2, 3, (1, 2, 3, 4)),
     "C"),
    (relpos.Ellipsoid.sphere((1, 0, 0), "1/2"), relpos.Quadric.elliptic_cylinder((0, 0, 0), 1, 1), "C"),
    (relpos.Ellipsoid.sphere((0, 0, 0), "1/2"), relpos.Quadric.hyperbolic_cylinder((0, 0, 0), 1, 1), "I"),
    (relpos.Ellipsoid.sphere((0, 0, -1), 1), relpos.Quadric.parabolic_cylinder((0, 0, 0), 1), "TE"),
    (relpos.Ellipsoid.sphere((0, 0, 0), 1), relpos.Quadric.slab((0, 0, 1), -1, 1), "TI"),
    (relpos.Ellipsoid.from_axes((0, 0, 0), (1, "1/2", "1/3"), (1, 1, 0, 0)), relpos.Quadric.half_space((1, 1, 1), 0),
     "C"),
]


def on_surface(q, X, Y, Z):
    """|q(x)| of the drawn points over the size of q's terms there (a float cross-check)."""
    Q = numpy.array([[float(x) for x in row] for row in q.matrix()])
    pts = numpy.stack([X.ravel(), Y.ravel(), Z.ravel(), numpy.ones(X.size)])
    pts = pts[:, numpy.isfinite(pts).all(axis=0)]
    value = numpy.einsum("ik,ij,jk->k", pts, Q, pts)
    size = numpy.einsum("ik,ij,jk->k", numpy.abs(pts), numpy.abs(Q), numpy.abs(pts))
    return pts.shape[1], numpy.max(numpy.abs(value) / size)


def test_plot_draws_every_type_on_its_surface():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from relpos import _plot, _quadric_surface

    assert sorted(q.type for _, q, _ in DRAWN) == sorted(relpos.QUADRIC_TYPES)
    for e, q, expected in DRAWN:
        position = relpos.classify(e, q).position
        assert position == expected, q.type
        ax = relpos.plot(e, q)
        ax.figure.canvas.draw()
        assert ax.get_title().startswith("%s: %s, " % (position, q.type))
        assert len(ax.collections) >= 2  # the quadric's sheets and the ellipsoid
        plt.close(ax.figure)
        frame = _plot._Frame(e, None)
        width = 3.0 * float(frame.semi.max())
        sheets = _quadric_surface.surfaces(q.type, frame.local(q.matrix()), width)
        assert len(sheets) == (2 if q.type in ("hyperbolic cylinder", "slab") else 1)
        offset, unit = frame.world()
        for X, Y, Z in sheets:
            drawn = numpy.isfinite(X)
            assert drawn.any(), q.type
            assert numpy.abs(numpy.stack([X[drawn], Y[drawn], Z[drawn]])).max() <= width
            count, worst = on_surface(q, *(offset[i] + unit * a for i, a in enumerate((X, Y, Z))))
            assert count > 100 and worst < 1e-12, (q.type, count, worst)


def test_plot_quadric_at_any_scale_and_its_errors():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # The unit picture of the hyperboloid's waist scaled by 10^-150: still TI, drawn in units of s.
    tiny = "1e-150"
    e = relpos.Ellipsoid.sphere((0, 0, 0), tiny)
    h = relpos.Quadric.hyperboloid_one_sheet((0, 0, 0), (tiny, tiny, tiny))
    ax = relpos.plot(e, h)
    ax.figure.canvas.draw()
    assert ax.get_title() == "%s: hyperboloid of one sheet, touching" % relpos.classify(e, h).position
    plt.close(ax.figure)
    # A quadric ellipsoid 10^-150 the size of the ball inside it: its sheet drawn (unshaded), not a crash.
    ball, speck = relpos.Ellipsoid.sphere((0, 0, 0), 1), relpos.Quadric.ellipsoid((0, 0, 0), (tiny, tiny, tiny))
    ax = relpos.plot(ball, speck)
    ax.figure.canvas.draw()
    assert ax.get_title() == "%s: ellipsoid, none" % relpos.classify(ball, speck).position
    plt.close(ax.figure)
    # A plane 10^300 radii away: out of the view, and the title says so.
    far = relpos.Quadric.half_space((1, 0, 0), "1e150")
    ax = relpos.plot(e, far)
    assert ax.get_title().endswith("(the half-space lies outside this view of the ellipsoid)")
    assert ax.get_title().startswith(relpos.classify(e, far).position + ": half-space, none")
    plt.close(ax.figure)
    # Not drawable: the same error, and the same message, as with a paraboloid.
    flat = relpos.Ellipsoid.from_axes((0, 0, 1), ("1e-200", 1, 1))
    with pytest.raises(ValueError, match="plot: the ellipsoid's axes are too unequal") as by_quadric:
        relpos.plot(flat, h)
    with pytest.raises(ValueError) as by_paraboloid:
        relpos.plot(flat, relpos.Paraboloid.standard((0, 0, 0), 1, 1))
    assert type(by_quadric.value) is type(by_paraboloid.value) and str(by_quadric.value) == str(by_paraboloid.value)
    with pytest.raises(TypeError, match="plot: p must be a relpos.Paraboloid or relpos.Quadric"):
        relpos.plot(e, h.matrix())
