"""relpos.classify(e, p, margin=True), relpos.Margin and relpos.verify on margins (doc/python.md):
spheres whose s* is known in closed form, the CLI's member, forged margins rejected."""

import json
import math
import subprocess
from fractions import Fraction as F

import pytest

import relpos


def cup():
    return relpos.Paraboloid.standard((0, 0, 0), 1, 1)


def test_margin_of_spheres_known_in_closed_form():
    # Outside at the surface point (1, 1, 2), normal (2, 2, -1) of length 3: s* = 3 t / r; on the axis,
    # centre (0, 0, 1): the circle z = 1/2 at distance^2 3/4, s*^2 = 3 / (4 r^2).
    e = relpos.Ellipsoid.sphere((F(5, 3), F(5, 3), F(5, 3)), F(1, 2))  # t = 1/3: s* = 2
    c = relpos.classify(e, cup(), margin=True)
    m = c.margin
    assert isinstance(m, relpos.Margin)
    assert m.lo == m.hi == "2" and m.polynomial == ["-2", "1"] and m.approx == 2.0
    assert m.at.kind == "tangent" and m.below is None and m.above is None
    assert relpos.verify(e, cup(), c) is None
    e = relpos.Ellipsoid.sphere((0, 0, 1), 1)
    m = relpos.classify(e, cup(), margin=True).margin
    lo, hi = F(m.lo), F(m.hi)
    assert lo * lo < F(3, 4) < hi * hi
    assert abs(m.approx - math.sqrt(3) / 2) <= 1e-15
    assert m.polynomial == ["-3", "0", "4"]
    assert m.below.kind == "definite" and m.above.kind == "crossing" and m.at is None
    assert (hi - lo) * 2**40 <= lo


def test_margin_bits_and_the_cli_member(tmp_path):
    e = relpos.Ellipsoid.sphere((1, 0, "1/2"), "1/3")
    m = relpos.classify(e, cup(), margin=True, margin_bits=100).margin
    assert (F(m.hi) - F(m.lo)) * 2**100 <= F(m.lo)
    line = {"id": 1, "ellipsoid": {"sphere": {"center": [1, 0, "1/2"], "radius": "1/3"}},
            "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}}
    path = tmp_path / "in.jsonl"
    path.write_text(json.dumps(line) + "\n")
    out = subprocess.run([relpos._cli.find_cli(), "batch", str(path), "--margin"], stdout=subprocess.PIPE, check=True)
    answer = json.loads(out.stdout)
    assert relpos.classify(e, cup(), margin=True).as_dict()["margin"] == answer["margin"]
    assert relpos.classify(e, cup()).margin is None
    with pytest.raises(ValueError, match="margin_bits"):
        relpos.classify(e, cup(), margin=True, margin_bits=0)
    with pytest.raises(TypeError):
        relpos.classify(e, cup(), margin="yes")


def test_forged_margins_are_rejected():
    e = relpos.Ellipsoid.sphere((0, 0, 1), 1)
    good = relpos.classify(e, cup(), margin=True).as_dict()
    m = good["margin"]
    lo, hi = F(m["lo"]), F(m["hi"])
    width = hi - lo

    def text(q):
        return "%d/%d" % (q.numerator, q.denominator)

    forgeries = [
        dict(m, lo=text(hi + width), hi=text(hi + 2 * width)),  # enclosure above s*
        dict(m, lo=text(lo - 2 * width), hi=text(lo - width)),  # below s*
        dict(m, polynomial=["-3", "1", "4"]),  # polynomial changed
        dict(m, below=m["above"], above=m["below"]),  # certificates swapped
        dict(m, approx=float(hi) * (1 + 1e-9)),  # approximation outside
        dict(m, above={"inside": m["above"]["outside"], "outside": m["above"]["outside"]}),  # tampered
    ]
    for forged in forgeries:
        with pytest.raises(relpos.CertificateError, match="margin"):
            relpos.verify(e, cup(), relpos.Classification(dict(good, margin=forged)))
    assert relpos.verify(e, cup(), relpos.Classification(good)) is None


def test_margin_beyond_the_double_range():
    # Centre 2^1025 below the vertex of z = x^2 + y^2, radius 1: the vertex is nearest, s* = 2^1025 >
    # the largest double; approx is math.inf, null in the JSON form, and the margin verifies.
    e = relpos.Ellipsoid.sphere((0, 0, str(-2**1025)), 1)
    c = relpos.classify(e, cup(), margin=True)
    assert c.margin.lo == c.margin.hi == str(2**1025)
    assert c.margin.approx == math.inf
    assert c.as_dict()["margin"]["approx"] is None
    assert relpos.verify(e, cup(), c) is None
    forged = dict(c.as_dict(), margin=dict(c.as_dict()["margin"], approx=1e308))
    with pytest.raises(relpos.CertificateError, match="margin"):
        relpos.verify(e, cup(), relpos.Classification(forged))
