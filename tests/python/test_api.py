"""The typed Python API (doc/python.md): signatures and docstrings of every public name, the
certificate and the independent verifier, the contact-only answer, scenes, motion with exact
instants, and every JSON input form of the CLI."""

import inspect
import json
import subprocess
from fractions import Fraction as F

import numpy
import pytest

import relpos


def cli():
    return relpos._cli.find_cli()


def cli_json(*args):
    return json.loads(subprocess.run([cli(), *args], stdout=subprocess.PIPE, check=True).stdout)


def public_callables():
    """(name, callable) for every public function, class constructor and public method."""
    for name in relpos.__all__:
        obj = getattr(relpos, name)
        if isinstance(obj, type):
            if issubclass(obj, BaseException):
                continue
            if inspect.isfunction(obj.__init__):  # Instant, FirstContact, Timeline: made by relpos only
                yield name + ".__init__", obj.__init__
            for attr, value in vars(obj).items():
                if not attr.startswith("_"):
                    value = getattr(obj, attr)
                    if callable(value) and not isinstance(value, property):
                        yield name + "." + attr, value
        elif callable(obj):
            yield name, obj


CONSTRUCTIBLE = ["Ellipsoid", "Paraboloid", "Classification", "Certificate", "ContactAnswer", "SceneResult"]


def test_signatures_name_real_types():
    seen = set()
    for name, f in public_callables():
        sig = inspect.signature(f)
        text = str(sig)
        assert "handle" not in text and "*args" not in text, (name, text)
        for param in sig.parameters.values():
            if param.name in ("self", "kwargs"):
                continue
            assert param.annotation is not inspect.Parameter.empty, (name, param.name)
        assert sig.return_annotation is not inspect.Signature.empty, name
        seen.add(name)
    for cls in CONSTRUCTIBLE:
        assert cls + ".__init__" in seen
    for name in ("classify", "verify", "contact", "decide_positions", "scene", "first_contact", "timeline",
                 "Ellipsoid.sphere", "Ellipsoid.from_axes", "Ellipsoid.from_map", "Ellipsoid.from_coefficients",
                 "Paraboloid.standard", "Paraboloid.from_map", "Instant.decimal", "Timeline.position_at"):
        assert name in seen, name
    number = str(inspect.signature(relpos.Ellipsoid.sphere).parameters["radius"].annotation)
    for t in ("int", "float", "Fraction", "str"):
        assert t in number


def test_every_public_name_has_a_docstring():
    for name in relpos.__all__:
        obj = getattr(relpos, name)
        if name == "__version__" or not (callable(obj) or inspect.ismodule(obj)):
            continue
        assert (obj.__doc__ or "").strip(), name
        if isinstance(obj, type):
            for attr, value in vars(obj).items():
                if not attr.startswith("_"):
                    assert (getattr(value, "__doc__", None) or "").strip(), name + "." + attr
    for name, f in public_callables():
        assert (f.__doc__ or "").strip(), name


def test_stub_lists_every_public_name():
    import os

    stub = open(os.path.join(os.path.dirname(relpos.__file__), "__init__.pyi"), encoding="utf-8").read()
    assert os.path.exists(os.path.join(os.path.dirname(relpos.__file__), "py.typed"))
    for name in relpos.__all__:
        if name not in ("distributed", "testing"):  # modules
            assert ("class " + name) in stub or ("def " + name) in stub or (name + ":") in stub, name
    for name, _ in public_callables():
        assert "def " + name.split(".")[-1] in stub, name


def test_certificate_and_verify():
    p = relpos.Paraboloid.standard((0, 0, 0), 1, 1)
    cases = {"TI": ((0, 0, "1/4"), "1/4"), "I": ((0, 0, 1), "1/4"), "C": (("1/2", 0, "1/4"), "3/10"),
             "TE": ((0, 0, -1), 1), "E": ((0, 0, "-3/2"), "1/2")}
    kinds = set()
    for position, (centre, radius) in cases.items():
        e = relpos.Ellipsoid.sphere(centre, radius)
        c = relpos.classify(e, p)
        assert c.position == position
        cert = c.certificate
        assert cert.to_json() == c.as_dict()["certificate"]
        kinds.add(cert.kind)
        assert relpos.verify(e, p, c) is None
        # The same certificate does not prove another position.
        wrong = relpos.Classification(dict(c.as_dict(), position="C" if position != "C" else "I"))
        with pytest.raises(relpos.CertificateError):
            relpos.verify(e, p, wrong)
    assert {"definite", "tangent", "crossing"} <= kinds
    # Tampered evidence: the contact point moved.
    e = relpos.Ellipsoid.sphere((0, 0, "1/4"), "1/4")
    c = relpos.classify(e, p)
    bad = c.as_dict()
    bad["certificate"]["contact"] = ["0", "0", "1/8"]
    with pytest.raises(relpos.CertificateError):
        relpos.verify(e, p, relpos.Classification(bad))
    assert relpos.classify(e, p, evidence="minimal").certificate is None
    with pytest.raises(ValueError, match="no certificate"):
        relpos.verify(e, p, relpos.classify(e, p, evidence="minimal"))


def test_contact_equals_cli():
    p = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
    for centre, radius in [((0, 0, "1/4"), "1/4"), ((0, 0, 1), "1/8"), (("1/2", 0, "1/4"), "3/10"), ((0, 0, -5), 4)]:
        e = relpos.Ellipsoid.sphere(centre, radius)
        got = relpos.contact(e, p)
        expected = cli_json("classify", "--json", "--contact-only", "--ellipsoid",
                            json.dumps({"sphere": {"center": list(centre), "radius": radius}}),
                            "--standard-paraboloid", "1,2")
        assert got.as_dict() == expected
        assert got.contact in ("none", "touching", "crossing", "meet", "unknown")
    assert relpos.contact(relpos.Ellipsoid.sphere((0, 0, -5), 4), p).contact == "none"  # not small, still certified


def test_scene_equals_per_pair_classify():
    rng = numpy.random.default_rng(5)
    p = relpos.Paraboloid.standard((0, 0, 0), 1, "3/2")
    bodies = [relpos.Ellipsoid.sphere((0, 0, "1/4"), "1/4"), relpos.Ellipsoid.sphere((0, 0, -1), 1)]
    for _ in range(300):
        x, y = rng.uniform(-1, 1, 2)
        z = x * x + y * y / 2.25 + rng.uniform(-0.4, 0.4)
        bodies.append(relpos.Ellipsoid.sphere((x, y, z), rng.uniform(0.01, 0.3)))
    expected = [relpos.POSITION_NAMES.index(relpos.classify(e, p, "minimal").position) for e in bodies]
    result = relpos.scene(p, bodies)
    assert result.positions.tolist() == expected
    assert result.names().tolist() == [relpos.POSITION_NAMES[k] for k in expected]
    assert sum(result.counts().values()) == len(bodies) and result.counts()["TI"] >= 1
    assert result.contact.tolist() == [1 if relpos.POSITION_NAMES[k] in ("TI", "C", "TE") else 0 for k in expected]
    early = result.stage_counts()["inside-certificate"] + result.stage_counts()["outside-certificate"]
    assert early > 0  # the scene's early-outs settle bodies far from the surface
    plain = relpos.scene(p, bodies, threads=1, early_outs=False)
    assert plain.positions.tolist() == expected and plain.threads == 1
    assert sum(plain.stage_counts()[s] for s in ("inside-certificate", "outside-certificate")) == 0
    # Matrices in, as for decide_positions; the paraboloid also as a description.
    E = numpy.array([[[float(x) for x in row] for row in e.matrix()] for e in bodies[:2]])
    assert relpos.scene(p.matrix(), E).positions.tolist() == expected[:2]
    E[1] = numpy.diag([1.0, -1.0, 1.0, -1.0])
    with pytest.raises(ValueError, match=r"bodies\[1\]: ellipsoid: not an ellipsoid"):
        relpos.scene(p, E)


def test_first_contact_exact_instant_equals_cli():
    e = relpos.Ellipsoid.sphere((0, 0, 0), "1/4")
    p = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
    translation = [[], [], ["-9/4", 0, 1]]  # the centre rises as t^2 - 9/4
    fc = relpos.first_contact(e, p, 0, 2, translation=translation)
    assert fc.kind == "contact" and fc.position == "TE" and fc.start_position == "E"
    t = fc.time
    assert t.exact is None and t.polynomial == [-2, 0, 1]  # t* = sqrt(2), exactly
    lo, hi = t.interval
    assert isinstance(lo, F) and lo < hi and lo * lo < 2 < hi * hi
    assert t.decimal(30) == "1.41421356237309504880168872421" and abs(float(t) - 2**0.5) < 1e-15
    out = cli_json("motion", "--sphere", "0,0,0,1/4", "--standard-paraboloid", "1,2", "--translation",
                   json.dumps(translation), "--t0", "0", "--t1", "2", "--first-contact", "--json")
    expected = out["first_contact"]
    assert (fc.kind, fc.start_position, fc.position, fc.how) == (
        expected["kind"], expected["start_position"], expected["position"], expected["how"])
    assert [str(c) for c in t.polynomial] == expected["time"]["polynomial"]
    assert [str(x) for x in t.interval] == expected["time"]["interval"]
    assert t.decimal(12) == expected["time"]["decimal"]
    none = relpos.first_contact(e, p, 0, 1, translation=translation)
    assert none.kind == "none" and none.time is None
    rational = relpos.first_contact(relpos.Ellipsoid.sphere((0, 0, -2), 1), p, 0, 2, translation=[0, 0, [0, 1]])
    assert rational.kind == "contact" and rational.time.exact == 1 and rational.position == "TE"


def test_timeline():
    e = relpos.Ellipsoid.sphere((0, 0, 0), "1/4")
    p = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
    tl = relpos.timeline(e, p, 0, 2, translation=[[], [], ["-9/4", 0, 1]])
    changes = tl.changes
    assert [(c["before"], c["at"], c["after"]) for c in changes] == [("E", "TE", "C"), ("C", "TI", "I")]
    assert changes[0]["time"].polynomial == [-2, 0, 1]
    assert [s["position"] for s in tl.spans] == ["E", "TE", "C", "TI", "I"]
    assert tl.position_at(0) == "E" and tl.position_at("3/2") == "C" and tl.position_at(2) == "I"
    assert tl.instants[0]["time"].exact == 0 and tl.instants[-1]["time"].exact == 2
    with pytest.raises(ValueError):
        tl.position_at(3)
    with pytest.raises(ValueError, match="degree 13 is beyond the limit"):
        relpos.timeline(e, p, 0, 1, translation=[[], [], [0] * 13 + [1]])
    with pytest.raises(ValueError):
        relpos.timeline(e, p, 1, 0)
    spin = relpos.timeline(relpos.Ellipsoid.from_axes((0, 0, 1), (1, "1/2", "1/2")), p, 0, 1,
                           rotation=[1, [0, 1], 0, 0], pivot="center")
    assert spin.spans and all(s["position"] in relpos.POSITION_NAMES for s in spin.spans)


def test_every_cli_input_form():
    sphere = relpos.Ellipsoid.sphere((1, 2, 3), 2)
    m = sphere.matrix()
    A, B, C = m[0][0], m[1][1], m[2][2]
    coefficients = [A, B, C, 2 * m[0][1], 2 * m[0][2], 2 * m[1][2], 2 * m[0][3], 2 * m[1][3], 2 * m[2][3], m[3][3]]
    assert relpos.Ellipsoid.from_coefficients(coefficients) == sphere
    assert relpos.Ellipsoid({"coefficients": coefficients}) == sphere
    assert relpos.Ellipsoid({"matrix": m}) == sphere
    assert relpos.Ellipsoid.from_map((1, 2, 3), [[2, 0, 0], [0, 2, 0], [0, 0, 2]]).matrix()[0][3] / m[0][3] > 0
    turned = relpos.Ellipsoid.from_axes((0, 0, 0), (1, 2, 3), [[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    assert turned == relpos.Ellipsoid.from_axes((0, 0, 0), (1, 2, 3), (1, 0, 0, 1))
    cup = relpos.Paraboloid.standard((0, 0, 0), 1, 1)
    assert relpos.Paraboloid.from_map([[1, 0, 0], [0, 1, 0], [0, 0, 1]], (0, 0, 0)).matrix()[0][0] > 0
    assert relpos.Paraboloid({"vertex": [0, 0, 0], "a": 1, "b": 1}) == cup
    for q in (sphere, turned):
        assert relpos.classify(q, cup).as_dict() == cli_json(
            "classify", "--json", "--ellipsoid", json.dumps({"matrix": [[str(x) for x in r] for r in q.matrix()]}),
            "--standard-paraboloid", "1,1")


def test_unbuilt_motion_objects():
    for cls in (relpos.Instant, relpos.FirstContact, relpos.Timeline):
        with pytest.raises(TypeError):
            cls()
    t = relpos.Instant.__new__(relpos.Instant)
    with pytest.raises(TypeError, match="not built"):
        t.decimal()
    with pytest.raises(TypeError, match="not built"):
        relpos.Timeline.__new__(relpos.Timeline).position_at(0)


PICKLE_EVERY_RESULT = """
import pickle, relpos
e = relpos.Ellipsoid.sphere((0, 0, 0), "1/4")
p = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
rise = [[], [], ["-9/4", 0, 1]]
fc = relpos.first_contact(e, p, 0, 2, translation=rise)
objects = [relpos.classify(e, p), relpos.classify(e, p).certificate, relpos.contact(e, p),
           relpos.scene(p, [e]), fc, fc.time, relpos.timeline(e, p, 0, 2, translation=rise)]
for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
    for x in objects:
        try:
            back = pickle.loads(pickle.dumps(x, protocol=protocol))
        except TypeError:
            print(protocol, type(x).__name__, "refused")
            continue
        same = back == x if hasattr(type(x), "as_dict") else repr(back) == repr(x)
        print(protocol, type(x).__name__, "round trip" if same else "DIFFERENT")
"""


def test_every_result_pickles_or_refuses():
    """Pickling a result object at any protocol round-trips or raises TypeError (never aborts)."""
    import os
    import sys

    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(relpos.__file__))))
    run = subprocess.run([sys.executable, "-c", PICKLE_EVERY_RESULT], env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, timeout=120)
    assert run.returncode == 0, run.stderr.decode()
    lines = run.stdout.decode().splitlines()
    assert len(lines) == 7 * (__import__("pickle").HIGHEST_PROTOCOL + 1)
    assert not any("DIFFERENT" in line for line in lines), lines
    assert any(line.endswith("Classification round trip") for line in lines)
