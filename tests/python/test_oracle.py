"""relpos.testing (doc/oracle.md) and the parts of the package it needs: the cases as numpy arrays
equal to the lines of `relpos cases`, the judge equal to `relpos judge`, assert_positions, the
hypothesis strategy (when python3-hypothesis is installed), decide_positions on parameters (never
refused, equal to the cases' double truth), symmetrize="upper" (the matrix truth), the message of a
refused matrix, and classify's meta."""

import json
import os
import subprocess
import sys

import numpy
import pytest

import relpos
import relpos.testing as rt

CLI = os.environ.get("RELPOS_CLI")
SOURCE_DIR = os.environ.get(
    "RELPOS_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
)
sys.path.insert(0, os.path.join(SOURCE_DIR, "examples", "oracle"))
from paper_rule import position as paper_rule  # noqa: E402  the walkthrough's float code


def float_code(c):
    return paper_rule(c.center, c.axes, c.e_rotation, c.vertex, c.a, c.b, c.p_rotation)


@pytest.fixture(scope="module")
def cases():
    return rt.cases(["offaxis", "rotated", "tiny", "special", "exact"], n=8, eps=["1e-4", "1e-10", 0], seed=3)


def test_cases_arrays_are_the_lines(cases):
    assert len(cases) == 4 * 3 * 8 + 8
    assert cases.center.shape == (len(cases), 3) and cases.E.shape == (len(cases), 4, 4)
    for i, c in enumerate(cases):
        line = json.loads(cases.lines[i])
        d = line["meta"]["double"]
        assert c.id == line["id"] == cases.ids[i]
        assert list(cases.center[i]) == d["ellipsoid"]["center"]
        assert cases.a[i] == d["paraboloid"]["a"]
        assert numpy.array_equal(cases.P[i], numpy.array(d["P"]))
        assert cases.position[i] == line["meta"]["position"]
    assert list(cases.labels) == list(cases.position)
    if CLI:
        out = subprocess.run([CLI, "cases", "offaxis", "rotated", "tiny", "special", "exact", "--n", "8", "--eps",
                              "1e-4,1e-10,0", "--seed", "3"], capture_output=True, text=True, check=True).stdout
        assert out == cases.text()
    with pytest.raises(ValueError, match="unknown family"):
        rt.cases(["nope"])


def test_the_exact_forms_give_the_labels(cases):
    for c in cases[:40]:
        e, p = relpos.Ellipsoid(c.exact_ellipsoid), relpos.Paraboloid(c.exact_paraboloid)
        answer = relpos.classify(e, p, meta={"id": c.id})
        assert answer.position == c.position
        assert answer.meta == {"id": c.id} and answer.as_dict()["meta"] == {"id": c.id}
        relpos.verify(e, p, answer)


def test_decide_positions_on_parameters_and_upper_triangles(cases):
    codes = relpos.decide_positions(cases.ellipsoid_parameters, cases.paraboloid_parameters)
    assert list(numpy.array(relpos.POSITION_NAMES)[codes]) == list(cases.double_position)
    # A shared paraboloid (no leading n) and the rotation left out.
    shared = relpos.decide_positions({"center": cases.center[:3], "axes": cases.axes[:3]},
                                     {"vertex": [0.0, 0.0, 0.0], "a": 1.0, "b": 2.0})
    assert shared.shape == (3,)
    codes = relpos.decide_positions(cases.E, cases.P, errors="code", symmetrize="upper")
    names = [relpos.POSITION_NAMES[k] if k >= 0 else None for k in codes]
    assert names == list(cases.matrix_position)
    with pytest.raises(ValueError, match="unknown key 'radius'"):
        relpos.decide_positions({"center": cases.center, "axes": cases.axes, "radius": 1.0}, cases.P)
    with pytest.raises(ValueError, match=r"P\['a'\]: expected shape"):
        relpos.decide_positions(cases.ellipsoid_parameters, {"vertex": cases.vertex, "a": cases.center, "b": 1.0})
    with pytest.raises(ValueError, match="symmetrize"):
        relpos.decide_positions(cases.E, cases.P, symmetrize="lower")


def test_a_refused_matrix_says_what_it_is_and_what_to_pass(cases):
    P = cases.P.copy()
    refused = [i for i, m in enumerate(cases.matrix_position) if m is None]
    assert refused
    with pytest.raises(ValueError, match="symmetrize='upper'"):
        relpos.decide_positions(cases.E, P)
    for M in (cases.E, P):
        for i in range(4):
            for j in range(i):
                M[:, i, j] = M[:, j, i]
    with pytest.raises(ValueError, match=r"the matrix describes (an?) .*: pass the parameters instead"):
        relpos.decide_positions(cases.E, P)


def test_judge_is_relpos_judge(cases, tmp_path):
    report = rt.judge(float_code, cases, tolerance="1e-9")
    answers = "".join(json.dumps({"id": c.id, "position": float_code(c)}) + "\n" for c in cases)
    # Positions in case order and JSON Lines give the same report.
    assert rt.judge([float_code(c) for c in cases], cases, tolerance="1e-9").to_dict() == report.to_dict()
    assert rt.judge(answers, cases, tolerance="1e-9").to_dict() == report.to_dict()
    if CLI:
        cases.write(tmp_path / "cases.jsonl")
        (tmp_path / "answers.jsonl").write_text(answers)
        for fmt in ("md", "csv", "json"):
            out = subprocess.run([CLI, "judge", str(tmp_path / "cases.jsonl"), str(tmp_path / "answers.jsonl"),
                                  "--tolerance", "1e-9", "--format", fmt], capture_output=True, text=True,
                                 check=True).stdout
            if fmt == "json":
                assert json.loads(out) == report.to_dict()
            else:
                assert out == report.table(fmt)
    assert report.total["cases"] == len(cases)
    report.plot(tmp_path / "chart.png")
    assert (tmp_path / "chart.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_assert_positions(cases):
    rt.assert_positions(list(cases.position), cases)  # the truth itself: no error
    rt.assert_positions(list(cases.double_position), cases, truth="double")
    with pytest.raises(AssertionError, match=r"Mismatched positions: \d+ / 104") as info:
        rt.assert_positions(float_code, cases)
    assert "relpos classify --ellipsoid" in str(info.value)
    wrong = ["C" if p != "C" else "I" for p in cases.position]
    with pytest.raises(AssertionError, match="104 wrong"):
        rt.assert_positions(wrong, cases)
    with pytest.raises(ValueError, match="positions for"):
        rt.assert_positions(["I"], cases)


hypothesis = pytest.importorskip("hypothesis")


@hypothesis.settings(max_examples=25, deadline=None, derandomize=True)
@hypothesis.given(rt.pairs(families=["offaxis", "special", "circular", "far"], eps=["1e-6", "0"]))
def test_hypothesis_cases_are_what_relpos_says(case):
    e, p = relpos.Ellipsoid(case.exact_ellipsoid), relpos.Paraboloid(case.exact_paraboloid)
    assert relpos.classify(e, p, evidence="minimal").position == case.position
