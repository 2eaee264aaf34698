"""A hostile round on the Python surfaces (CTest `python_hostile`; doc/python.md, doc/testing.md): one
test per finding of issue 35 at least. Nothing lost (Dask on streams, all-or-nothing outputs, any
legal name), nothing stalled (Ctrl-C in every long call, the motion time budget, long lines, scripts
without a __main__ guard), no crash (pickled data, plot at any scale, numbers beyond the default
size limit), errors that name the argument and the entry, and answers equal to the CLI's field for
field. Every expectation is known by construction or read from the CLI.

Calls that a signal interrupts run in a child interpreter (a stray KeyboardInterrupt must not reach
pytest), each with a workload many times longer than the time allowed after the signal.
"""

import json
import math
import os
import pickle
import pydoc
import random
import signal
import subprocess
import sys
import textwrap
import threading
import time
from decimal import Decimal
from fractions import Fraction as F

import numpy
import pytest

import relpos

SOURCE_DIR = os.environ.get(
    "RELPOS_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
)
MIXED = os.path.join(SOURCE_DIR, "examples", "mixed.jsonl")
CUP = relpos.Paraboloid.standard((0, 0, 0), 1, 1)  # z = x^2 + y^2
INTERNALS = ("incompatible function arguments", "Unable to cast", "pybind11", "Invoked with", "KeyError",
             "dictionary update sequence", "_relpos")


def cli(*args, data=None):
    return subprocess.run([relpos._cli.find_cli(), *args], input=data, stdout=subprocess.PIPE, check=False).stdout


def read(path):
    with open(path, "rb") as f:
        return f.read()


def clean(err):
    """The error's message names no binding internals."""
    text = "%s: %s" % (type(err).__name__, err)
    assert not any(s in text for s in INTERNALS), text
    assert len(text) < 600, text  # no array or answer printed in full
    return str(err)


def child(code, timeout=120):
    """Runs `code` in a fresh interpreter (the environment's PYTHONPATH); returns its last output
    line, parsed as JSON."""
    out = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, timeout=timeout, text=True)
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


# ------------------------------------------------------------------------------------------------
# Ctrl-C and the time budget: each long call stops soon after SIGINT, the interpreter stays usable.

INTERRUPT = """
import json, os, signal, threading, time, numpy, relpos
stopped = {}
def interrupt(after):
    def fire():
        time.sleep(after)
        stopped["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)
    threading.Thread(target=fire, daemon=True).start()
def run(call, after=0.5):
    interrupt(after)
    start = time.monotonic()
    try:
        call()
        result = {"interrupted": False, "seconds": time.monotonic() - start}
    except KeyboardInterrupt:
        result = {"interrupted": True, "after_signal": time.monotonic() - stopped["at"]}
    # the interpreter is usable: a classification right after
    e, p = relpos.Ellipsoid.sphere((0, 0, 1), "1/4"), relpos.Paraboloid.standard((0, 0, 0), 1, 1)
    result["then"] = relpos.classify(e, p).position
    return result
# Spheres through the vertex of z = x^2 + y^2 touching it from inside, with a radius that is a long
# double but not a double: each pair is exact work (a multiple root), ~10^5 of them take many seconds.
n = 120000
r = numpy.longdouble(0.25) + numpy.longdouble(2) ** -60
E = numpy.zeros((n, 4, 4), dtype=numpy.longdouble)
E[:, 0, 0] = E[:, 1, 1] = E[:, 2, 2] = 1
E[:, 2, 3] = E[:, 3, 2] = -r
P = numpy.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, -0.5], [0, 0, -0.5, 0]])
"""

SLOW_MOTION = """
e = relpos.Ellipsoid.from_axes((0, 0, 1), ("1/4", "1/5", "1/7"))
rotation = [[1] + [0] * 11 + [1], [0, 1], [0, 0, 1], [0, 0, 0, 1]]   # degree 12
translation = [[0, "1/3"], [], ["-1/2", 0, 1]]
from_below = [[0, "1/3"], ["1/5", 0, "1/7"], ["-3", "1/11", 1]]   # exterior at t0 = 0, contact near t = 1.39
rotation_2 = [[1, "1/3"] + [0] * 10 + [1], [0, 1, "2/7"], [0, 0, 1], ["1/5", 0, 0, 1]]
cup = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
"""

# The time allowed after the signal: the calls check every 50 ms; a loaded machine is slower.
STOP_WITHIN = 5.0


@pytest.mark.parametrize("call", [
    "relpos.decide_positions(E, P)",
    "relpos.decide_positions(E, P, threads=2)",
    "relpos.scene(relpos.Paraboloid(P), E, early_outs=False)",
])
def test_ctrl_c_stops_numpy_batches_and_scenes(call):
    r = child(INTERRUPT + "print(json.dumps(run(lambda: %s)))" % call)
    assert r["interrupted"], r
    assert r["after_signal"] < STOP_WITHIN and r["then"] == "I"


@pytest.mark.parametrize("function", ["timeline", "first_contact"])
def test_ctrl_c_stops_motion(function):
    motion = "0, 1, translation=translation, rotation=rotation" if function == "timeline" else \
        "0, 3, translation=from_below, rotation=rotation_2"
    r = child(INTERRUPT + SLOW_MOTION + "print(json.dumps(run(lambda: relpos.%s(e, cup, %s), after=1.0)))"
              % (function, motion))
    assert r["interrupted"] and r["after_signal"] < STOP_WITHIN and r["then"] == "I", r


def test_motion_time_budget():
    r = child("""
        import json, time, relpos
        %s
        start = time.monotonic()
        try:
            relpos.timeline(e, cup, 0, 1, translation=translation, rotation=rotation, max_seconds=0.5)
            out = {"error": None}
        except TimeoutError as err:
            out = {"error": str(err), "seconds": time.monotonic() - start}
        print(json.dumps(out))
    """ % textwrap.indent(SLOW_MOTION, "        ").strip())
    assert r["error"] and "time budget of 0.5 s (max_seconds)" in r["error"], r
    assert r["seconds"] < 0.5 + STOP_WITHIN
    with pytest.raises(ValueError, match="max_seconds"):
        relpos.timeline(relpos.Ellipsoid.sphere((0, 0, 1), 1), CUP, 0, 1, max_seconds=0)
    with pytest.raises(TypeError, match="max_seconds"):
        relpos.timeline(relpos.Ellipsoid.sphere((0, 0, 1), 1), CUP, 0, 1, max_seconds="1")


def test_cli_motion_budget_stops_the_work():
    """`relpos motion --max-seconds` through the same mechanism: exit code 5, its message."""
    start = time.monotonic()
    out = subprocess.run([relpos._cli.find_cli(), "motion", "--ellipsoid",
                          '{"center": [0, 0, 1], "axes": ["1/4", "1/5", "1/7"]}', "--standard-paraboloid", "1,2",
                          "--rotation", "[[1,0,0,0,0,0,0,0,0,0,0,0,1],[0,1],[0,0,1],[0,0,0,1]]",
                          "--translation", '[[0, "1/3"], [], ["-1/2", 0, 1]]', "--t0", "0", "--t1", "1",
                          "--max-seconds", "1", "--no-progress"], stderr=subprocess.PIPE, stdout=subprocess.PIPE)
    assert out.returncode == 5 and b"exceeded its time budget of 1 s (--max-seconds)" in out.stderr
    assert time.monotonic() - start < 1 + STOP_WITHIN


DASK_CHILD = """
import json, os, signal, threading, time, relpos.distributed
def main():
    src, out_dir = %r, %r
    os.makedirs(out_dir)
    with open(os.path.join(out_dir, "big.jsonl"), "w") as f:
        f.write("OLD\\n")
    state = {}
    def fire():
        time.sleep(%r)
        state["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)
    threading.Thread(target=fire, daemon=True).start()
    try:
        relpos.distributed.batch(src, out_dir)
        result = {"interrupted": False}
    except KeyboardInterrupt:
        result = {"interrupted": True, "after_signal": time.monotonic() - state["at"]}
    time.sleep(1)  # a task still running would write now
    result["out_dir"] = sorted(os.listdir(out_dir))
    result["old"] = open(os.path.join(out_dir, "big.jsonl")).read()
    result["again"] = relpos.distributed.batch(%r, out_dir + "2")  # usable afterwards
    print(json.dumps(result))
main()
"""


def test_ctrl_c_stops_dask_batch(tmp_path):
    src = tmp_path / "big.jsonl"
    src.write_bytes(read(MIXED) * 400)
    r = child(DASK_CHILD % (str(src), str(tmp_path / "out"), 2.0, MIXED))
    assert r["interrupted"] and r["after_signal"] < STOP_WITHIN, r
    assert r["out_dir"] == ["big.jsonl"] and r["old"] == "OLD\n"
    assert r["again"] == [str(tmp_path / "out2" / "mixed.jsonl")]


# ------------------------------------------------------------------------------------------------
# relpos.distributed: what the CLI reads, all or nothing, any name, linear long lines, no guard.


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as c, \
            distributed.Client(c) as cl:
        yield cl


def test_dask_named_pipe_answered_in_full(client, tmp_path):
    data = read(MIXED)
    fifo = tmp_path / "pipe.jsonl"
    os.mkfifo(fifo)

    def writer():
        with open(fifo, "wb") as f:
            f.write(data)

    t = threading.Thread(target=writer)
    t.start()
    out = relpos.distributed.batch(fifo, tmp_path / "out", client=client, block_bytes=1000)
    t.join()
    assert read(out[0]) == cli("batch", "-", data=data)
    assert os.listdir(tmp_path / "out") == ["pipe.jsonl"]


def test_dask_files_whose_size_reads_zero(client, tmp_path):
    """/proc files read as size 0: answered in full, as `relpos batch` reads them (each line is an
    error line: they are not JSON)."""
    out = relpos.distributed.batch("/proc/self/status", tmp_path / "out", client=client)
    answers = read(out[0]).splitlines()
    assert len(answers) > 10 and all(b'"error"' in a for a in answers)
    assert len(answers) == len(cli("batch", "/proc/self/status").splitlines())


def test_dask_failure_leaves_out_dir_as_it_was(client, tmp_path):
    (tmp_path / "in").mkdir()
    for name in ("a.jsonl", "b.jsonl"):
        (tmp_path / "in" / name).write_bytes(read(MIXED))
    out = tmp_path / "out"
    (out / "b.jsonl").mkdir(parents=True)  # an output path that is a directory
    (out / "a.jsonl").write_text("OLD")
    with pytest.raises(IsADirectoryError) as err:
        relpos.distributed.batch([tmp_path / "in" / "a.jsonl", tmp_path / "in" / "b.jsonl"], out, client=client)
    assert "b.jsonl" in clean(err.value)
    assert (out / "a.jsonl").read_text() == "OLD" and sorted(os.listdir(out)) == ["a.jsonl", "b.jsonl"]


def test_dask_outputs_published_all_or_none(client, tmp_path, monkeypatch):
    """A failure while the outputs are moved into place (here: the second os.replace) puts the first
    output back as it was."""
    import relpos.distributed as rd

    (tmp_path / "in").mkdir()
    inputs = []
    for name in ("a.jsonl", "b.jsonl"):
        (tmp_path / "in" / name).write_bytes(read(MIXED))
        inputs.append(tmp_path / "in" / name)
    out = tmp_path / "out"
    out.mkdir()
    (out / "a.jsonl").write_text("OLD a")
    real = os.replace
    moved = []

    def failing(src, dst):
        if str(dst).endswith("b.jsonl"):
            raise PermissionError("injected")
        moved.append(dst)
        return real(src, dst)

    monkeypatch.setattr(rd.os, "replace", failing)
    with pytest.raises(PermissionError):
        relpos.distributed.batch(inputs, out, client=client)
    monkeypatch.undo()
    assert str(out / "a.jsonl") in map(str, moved)  # it was replaced, then put back
    assert (out / "a.jsonl").read_text() == "OLD a" and os.listdir(out) == ["a.jsonl"]


def test_dask_longest_legal_file_name(client, tmp_path):
    name = "n" * (255 - len(".jsonl")) + ".jsonl"  # NAME_MAX
    (tmp_path / "in").mkdir()
    (tmp_path / "in" / name).write_bytes(read(MIXED))
    out = relpos.distributed.batch(tmp_path / "in" / name, tmp_path / "out", client=client, block_bytes=4096)
    assert read(out[0]) == cli("batch", MIXED) and os.listdir(tmp_path / "out") == [name]


def test_dask_block_ranges_read_each_line_once():
    """The plan of the blocks against a direct computation, on random files with long lines: the
    ranges are whole lines, cover the file once, start with the right line numbers, and a line is
    in one range only (blocks inside a line get none: the long line costs linear time)."""
    import relpos.distributed as rd

    rng = random.Random(35)
    for _ in range(300):
        lines = [b"x" * rng.choice([0, 1, 5, 40, 300]) for _ in range(rng.randrange(0, 12))]
        data = b"\n".join(lines) + (b"\n" if rng.random() < 0.5 else b"")
        block = rng.choice([1, 2, 3, 7, 16, 64, 1000])
        n = -(-len(data) // block)
        scans = []
        for k in range(n):
            piece = data[k * block:(k + 1) * block]
            first = piece.find(b"\n")
            scans.append((piece.count(b"\n"), k * block + first if first >= 0 else -1, piece.endswith(b"\n")))
        ranges = rd._ranges(len(data), block, scans)
        starts = ([0] if data else []) + [i + 1 for i, c in enumerate(data) if c == 10 and i + 1 < len(data)]
        if data:
            assert ranges[0][0] == 0 and ranges[-1][1] == len(data)
        assert all(b == c for (_, b, _), (c, _, _) in zip(ranges, ranges[1:]))  # contiguous, in order
        for a, b, number in ranges:
            assert a < b and a in starts and (b == len(data) or b in starts)
            assert number == 1 + data[:a].count(b"\n")
        assert len(ranges) <= len(starts)  # a block inside a line answers nothing


def test_dask_long_line_costs_one_read(client, tmp_path):
    """A line of 4 MB in blocks of 12345 bytes: the output is the CLI's, and only the block where
    the line starts answers it (a count of the bytes the tasks answered)."""
    line = b'{"id": "' + b"x" * (4 << 20) + b'", "ellipsoid": 1}'
    src = tmp_path / "long.jsonl"
    src.write_bytes(read(MIXED) + line + b"\n" + read(MIXED))
    out = relpos.distributed.batch(src, tmp_path / "out", client=client, block_bytes=12345)
    assert read(out[0]) == cli("batch", str(src))
    import relpos.distributed as rd

    size = os.path.getsize(src)
    scans = [rd._scan_block(str(src), k * 12345, min(size, (k + 1) * 12345)) for k in range(-(-size // 12345))]
    ranges = rd._ranges(size, 12345, scans)
    assert sum(b - a for a, b, _ in ranges) == size  # every byte answered once
    assert len(ranges) < len(scans) - (4 << 20) // 12345 + 2  # the blocks inside the line answer nothing


def test_dask_script_without_main_guard(tmp_path):
    """No client: a cluster of threads in this process, so a script without the guard finishes."""
    script = tmp_path / "script.py"
    script.write_text("import relpos.distributed\nprint(relpos.distributed.batch(%r, %r))\n"
                      % (MIXED, str(tmp_path / "out")))
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(relpos.__file__))))
    out = subprocess.run([sys.executable, str(script)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120,
                         cwd=tmp_path, env=env)
    assert out.returncode == 0, out.stderr[-2000:]
    assert read(tmp_path / "out" / "mixed.jsonl") == cli("batch", MIXED)


@pytest.mark.parametrize("kwargs, name", [({"digits": "12"}, "digits"), ({"threads": 1.5}, "threads"),
                                          ({"evidence": 3}, "evidence"), ({"contact_only": "yes"}, "contact_only"),
                                          ({"max_line_bytes": 2**70}, "max_line_bytes"),
                                          ({"digits": 2**40}, "digits"), ({"block_bytes": "big"}, "block_bytes"),
                                          ({"max_bits": 100}, "max_bits"), ({"threads": 0}, "threads")])
def test_dask_options_name_the_argument(tmp_path, kwargs, name):
    with pytest.raises((TypeError, ValueError)) as err:
        relpos.distributed.batch(MIXED, tmp_path / "out", client=object(), **kwargs)
    assert name in clean(err.value)
    assert not os.path.exists(tmp_path / "out")


# ------------------------------------------------------------------------------------------------
# Crashes: pickled data, plots at any scale, numbers beyond the default limit.


@pytest.mark.parametrize("old, new", [(b"V15/16", b"V15/0"), (b"V15/16", b"V15/-16"), (b"V15/16", b"V1e5"),
                                      (b"V15/16", b"V"), (b"V15/16", b"V0x10")])
def test_pickled_numbers_are_validated(old, new):
    data = pickle.dumps(relpos.Ellipsoid.sphere((0, 0, 1), "1/4"), 0)
    assert old in data
    # in a child: a crash (SIGFPE) must show as a crash, not take pytest down
    r = child("""
        import json, pickle, relpos
        try:
            pickle.loads(%r)
            print(json.dumps({"error": None}))
        except ValueError as err:
            print(json.dumps({"error": str(err)}))
    """ % data.replace(old, new))
    assert r["error"] and r["error"].startswith("pickled quadric[3][3]: not an exact number"), r


def test_pickled_matrix_is_validated():
    e = relpos.Ellipsoid.sphere((0, 0, 1), "1/4")
    texts = [str(x) for row in e.matrix() for x in row]
    texts[3] = "5"  # no longer symmetric
    with pytest.raises(ValueError, match="pickled ellipsoid: .*symmetric"):
        relpos._rebuild(relpos.Ellipsoid, tuple(texts))
    with pytest.raises(ValueError, match="pickled quadric"):
        relpos._rebuild(relpos.Ellipsoid, tuple(texts[:15]))
    with pytest.raises(ValueError, match=r"pickled quadric\[0\]\[1\]: expected an exact number as text, got int"):
        relpos._rebuild(relpos.Ellipsoid, ("1", 0) + tuple(texts[2:]))


@pytest.mark.parametrize("centre, radius", [
    ((0, 0, "1e-80"), "1e-80"), ((0, 0, "1e-160"), "1e-160"), ((0, 0, "1e-170"), "1e-170"),
    ((0, 0, "1e-300"), "1e-300"), (("3/10", "1/5", "1e160"), 1), ((0, 0, "1e300"), 1), (("1e200", 0, "1e400"), 1),
    ((0, 0, 1), "1/4"),
])
def test_plot_draws_any_scale(centre, radius):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    e = relpos.Ellipsoid.sphere(centre, radius)
    ax = relpos.plot(e, CUP)
    ax.figure.canvas.draw()  # renders: shading, colours
    position = relpos.classify(e, CUP).position
    assert ax.get_title().startswith(position + ":")
    for lim in (ax.get_xlim(), ax.get_ylim(), ax.get_zlim()):
        assert all(map(math.isfinite, lim)) and lim[1] > lim[0]
    assert len(ax.collections) >= 1
    plt.close(ax.figure)


def test_plot_says_why_not():
    e = relpos.Ellipsoid.from_axes((0, 0, 1), ("1e-200", 1, 1))
    with pytest.raises(ValueError, match="plot: the ellipsoid's axes are too unequal"):
        relpos.plot(e, CUP)


def long_sphere(digits):
    """A sphere inside the cup whose centre has a fraction of `digits` digits: beyond the default limit
    at 700 digits."""
    q = 10**digits + 7
    return relpos.Ellipsoid.sphere((0, F(1, q), 1), "1/4")


def test_size_limit_can_be_raised():
    e = long_sphere(700)
    for call in (lambda **k: relpos.classify(e, CUP, **k), lambda **k: relpos.classify(e, CUP, "minimal", **k),
                 lambda **k: relpos.contact(e, CUP, **k), lambda **k: relpos.scene(CUP, [e], **k)):
        with pytest.raises(ValueError, match="beyond the limit of 4096 bits"):
            call()
        call(max_bits=8000)
    assert relpos.classify(e, CUP, max_bits=8000).position == "I"
    with pytest.raises(ValueError, match=r"bodies\[1\]: numbers too large"):
        relpos.scene(CUP, [relpos.Ellipsoid.sphere((0, 0, 1), "1/4"), e])
    with pytest.raises(ValueError, match="max_bits: expected an int from 4096"):
        relpos.classify(e, CUP, max_bits=100)
    with pytest.raises(TypeError, match="max_bits"):
        relpos.classify(e, CUP, max_bits=5000.0)
    # the CLI's option: the same answer
    line = json.dumps({"id": 1, "ellipsoid": {"sphere": {"center": [0, "1/%d" % (10**700 + 7), 1], "radius": "1/4"}},
                       "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}}).encode()
    assert b"beyond the limit of 4096 bits" in cli("batch", data=line)
    answer = json.loads(cli("batch", "--max-bits", "8000", data=line))
    del answer["id"]
    assert answer == relpos.classify(e, CUP, max_bits=8000).as_dict()


def test_size_limit_of_a_general_pair_can_be_raised():
    # The same limit for a Quadric (a batch line with "quadric"): refused by default, answered with
    # max_bits raised, by classify and decide_positions, as by the CLI.
    e = long_sphere(700)
    ring = relpos.Quadric.hyperboloid_one_sheet((0, 0, 0), (10, 10, 10))
    ball = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, -1, 1 - 1 / 16]]  # centre (0, 0, 1), radius 1/4
    E = numpy.array([ball, ball], dtype=float)
    for call in (lambda **k: relpos.classify(e, ring, **k), lambda **k: relpos.classify(e, ring, "minimal", **k)):
        with pytest.raises(ValueError, match="beyond the limit of 4096 bits"):
            call()
        with pytest.raises(ValueError, match="beyond the limit of 4500 bits"):
            call(max_bits=4500)
    # answered with the verdict alone: the full evidence of so large a general pair takes seconds
    assert relpos.classify(e, ring, "minimal", max_bits=8000).position == "I"
    wide = relpos.Quadric.hyperboloid_one_sheet((0, 0, F(1, 10**700 + 7)), (10, 10, 10))
    with pytest.raises(ValueError, match="beyond the limit of 4096 bits"):
        relpos.decide_positions(E, wide)
    assert list(relpos.decide_positions(E, wide, max_bits=8000)) == [0, 0]  # I
    line = json.dumps({"id": 1, "ellipsoid": {"sphere": {"center": [0, "1/%d" % (10**700 + 7), 1], "radius": "1/4"}},
                       "quadric": {"type": "hyperboloid of one sheet", "center": [0, 0, 0], "axes": [10, 10, 10]}})
    assert b"beyond the limit of 4096 bits" in cli("batch", data=line.encode())
    answer = json.loads(cli("batch", "--max-bits", "8000", "--evidence", "minimal", data=line.encode()))
    del answer["id"]
    assert answer == relpos.classify(e, ring, "minimal", max_bits=8000).as_dict()


def test_beyond_the_default_limit_on_a_small_stack(tmp_path):
    """A pair of ~40 000 bits whose roots are 10^-1000 apart: the root isolation recurses deeper than
    a small thread stack holds; the library gives such pairs a stack of their own."""
    r = child("""
        import json, threading, relpos
        from fractions import Fraction as F
        tiny = F(1, 10**1500)
        e = relpos.Ellipsoid.sphere((tiny / 3, tiny / 7, 1 + tiny / 11), F(1, 4) + tiny / 13)
        p = relpos.Paraboloid.standard((0, 0, 0), 1, 1)
        threading.stack_size(256 << 10)    # the calling thread's stack: 256 KiB
        out = []
        t = threading.Thread(target=lambda: out.append(relpos.classify(e, p, max_bits=1 << 20).position))
        t.start(); t.join()
        print(json.dumps(out))
    """, timeout=300)
    assert r == ["I"]


# ------------------------------------------------------------------------------------------------
# Errors that name the argument and the entry, never a binding's internals.


def test_scene_bodies_errors():
    e = relpos.Ellipsoid.sphere((0, 0, 1), "1/4")
    with pytest.raises(TypeError) as err:
        relpos.scene(CUP, [e, "x"])
    assert clean(err.value).startswith("bodies[1]: expected a relpos.Ellipsoid, got str")
    assert relpos.scene(CUP, []).positions.tolist() == []
    assert relpos.scene(CUP, ()).counts() == {name: 0 for name in relpos.POSITION_NAMES}
    with pytest.raises(TypeError) as err:
        relpos.scene(CUP, [[[1, 0], [0, 1]], [[1]]])  # ragged
    assert clean(err.value).startswith("bodies: expected an array (n, 4, 4)")
    with pytest.raises(TypeError) as err:
        relpos.scene(CUP, [e, relpos.Ellipsoid.__new__(relpos.Ellipsoid)])
    assert "not built" in clean(err.value)


@pytest.mark.parametrize("threads", [2**40, -1, 1025])
def test_threads_out_of_range(threads):
    E = numpy.zeros((2, 4, 4))
    with pytest.raises(ValueError) as err:
        relpos.decide_positions(E, numpy.eye(4), threads=threads)
    assert clean(err.value).startswith("threads: expected an int from 0 to 1024")
    with pytest.raises(ValueError, match="threads"):
        relpos.scene(CUP, [], threads=threads)


MALFORMED = [
    {}, {"position": "I"}, {"position": "X", "certificate": {"lambda": "1"}}, {"position": 5, "certificate": {}},
    {"position": "I", "certificate": [1]}, {"position": "I", "certificate": "x"},
    {"position": "I", "certificate": {"lambda": [1]}}, {"position": "I", "certificate": {"lambda": float("nan")}},
    {"position": "TI", "certificate": {"lambda": "-1/2", "contact": [0, 0]}},
    {"position": "C", "certificate": {"inside": None, "outside": [0, 0, 0]}},
    {"position": "I", "certificate": {"lambda": {"a": 1}}}, {"position": "I", "certificate": {"unknown": 1}},
]


@pytest.mark.parametrize("fields", MALFORMED, ids=range(len(MALFORMED)))
def test_verify_malformed_answers(fields):
    e = relpos.Ellipsoid.sphere((0, 0, "1/4"), "1/4")
    with pytest.raises(ValueError) as err:
        relpos.verify(e, CUP, relpos.Classification(fields))
    clean(err.value)
    if "certificate" in fields and fields.get("position") in relpos.POSITION_NAMES:
        assert isinstance(err.value, relpos.CertificateError)


def test_answers_built_from_junk():
    for junk in ([("position", "I")], "I", 5, None, {1: "I"}):
        with pytest.raises(TypeError) as err:
            relpos.Classification(junk)
        assert "fields: expected a mapping" in clean(err.value)
    c = relpos.Classification({"position": "I"})
    with pytest.raises(AttributeError) as err:
        c.rho
    assert "has no 'rho'" in clean(err.value)


def test_result_classes_not_made_directly():
    for cls in (relpos.Instant, relpos.FirstContact, relpos.Timeline):
        with pytest.raises(TypeError) as err:
            cls()
        assert "objects are made by relpos." in clean(err.value)


def probe_arguments():
    """Every public call with a wrong value in each argument."""
    e, p = relpos.Ellipsoid.sphere((0, 0, 1), "1/4"), CUP
    E = numpy.zeros((1, 4, 4))
    bad = [object(), "x", [1, 2], {"a": 1}, 1.5, None, -1, 2**70, numpy.zeros(3)]
    calls = {
        "classify.e": lambda x: relpos.classify(x, p), "classify.evidence": lambda x: relpos.classify(e, p, x),
        "classify.max_bits": lambda x: relpos.classify(e, p, max_bits=x),
        "contact.p": lambda x: relpos.contact(e, x), "contact.max_bits": lambda x: relpos.contact(e, p, max_bits=x),
        "decide_positions.E": lambda x: relpos.decide_positions(x, numpy.eye(4)),
        "decide_positions.P": lambda x: relpos.decide_positions(E, x),
        "decide_positions.threads": lambda x: relpos.decide_positions(E, numpy.eye(4), threads=x),
        "decide_positions.errors": lambda x: relpos.decide_positions(E, numpy.eye(4), errors=x),
        "scene.bodies": lambda x: relpos.scene(p, x), "scene.p": lambda x: relpos.scene(x, [e]),
        "first_contact.t0": lambda x: relpos.first_contact(e, p, x, 1),
        "first_contact.translation": lambda x: relpos.first_contact(e, p, 0, 1, translation=x),
        "timeline.rotation": lambda x: relpos.timeline(e, p, 0, 1, rotation=x),
        "timeline.pivot": lambda x: relpos.timeline(e, p, 0, 1, rotation=[1, 0, 0, 0], pivot=x),
        "timeline.max_seconds": lambda x: relpos.timeline(e, p, 0, 1, max_seconds=x),
        "Ellipsoid": lambda x: relpos.Ellipsoid(x), "Ellipsoid.sphere": lambda x: relpos.Ellipsoid.sphere(x, 1),
        "Paraboloid.standard": lambda x: relpos.Paraboloid.standard((0, 0, 0), x, 1),
        "verify.answer": lambda x: relpos.verify(e, p, x),
        "Instant.decimal": lambda x: relpos.first_contact(e, p, 0, 1, translation=[[], [], [0, -1]]).time.decimal(x),
        "Timeline.position_at": lambda x: relpos.timeline(e, p, 0, 1).position_at(x),
    }
    for name, call in calls.items():
        for x in bad:
            yield name, call, x


def test_errors_never_show_binding_internals():
    for name, call, x in probe_arguments():
        try:
            call(x)
        except (TypeError, ValueError, AttributeError) as err:
            text = "%s: %s" % (type(err).__name__, err)
            assert not any(s in text for s in INTERNALS), (name, repr(x)[:40], text[:300])
            assert len(text) < 600, (name, text[:300])


# ------------------------------------------------------------------------------------------------
# Paths that agree with the CLI field for field.


def test_first_contact_none_position_is_none():
    e = relpos.Ellipsoid.sphere((0, 0, 0), "1/4")
    cup = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
    fc = relpos.first_contact(e, cup, 0, "1/2", translation=[[], [], ["-9/4", 0, 1]])
    out = json.loads(cli("motion", "--sphere", "0,0,0,1/4", "--standard-paraboloid", "1,2", "--translation",
                         '[[], [], ["-9/4", 0, 1]]', "--t0", "0", "--t1", "1/2", "--first-contact", "--json"))
    assert out["first_contact"]["kind"] == fc.kind == "none"
    assert out["first_contact"]["position"] is None and fc.position is None and fc.time is None


def test_pivot_centre_and_center_alike():
    e = relpos.Ellipsoid.from_axes((0, 0, 1), ("1/4", "1/5", "1/7"))
    turn = [[1, 0, 1], [0, 1], [], []]
    a = relpos.timeline(e, CUP, 0, 1, rotation=turn, pivot="center")
    b = relpos.timeline(e, CUP, 0, 1, rotation=turn, pivot="centre")
    assert [s["position"] for s in a.spans] == [s["position"] for s in b.spans]
    assert [float(i["time"]) for i in a.instants] == [float(i["time"]) for i in b.instants]


def test_instants_compare_exactly():
    e = relpos.Ellipsoid.sphere((0, 0, 0), "1/4")
    cup = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
    rise = [[], [], ["-9/4", 0, 1]]
    a = relpos.first_contact(e, cup, 0, 2, translation=rise).time  # sqrt(2) from two computations
    b = relpos.first_contact(e, cup, "1/2", 3, translation=rise).time
    c = relpos.timeline(e, cup, 0, 2, translation=rise).changes[0]["time"]
    assert a.exact is None and a == b == c and not (a != b) and hash(a) == hash(b) == hash(c)
    assert len({a, b, c}) == 1
    half = relpos.timeline(e, cup, 0, 2, translation=rise).instants[0]["time"]  # t0 = 0
    assert half < a and a > half and half <= a and a >= b and not (a < b) and half == 0 and half == F(0)
    assert a > F(1414, 1000) and a < F(1415, 1000) and a > 1 and a < Decimal("1.5") and a > 1.4142
    assert (a == "x") is False and a != None  # noqa: E711
    with pytest.raises(TypeError):
        a < "x"
    assert sorted([b, half, c]) == [half, b, c]


def test_minimal_answer_fields_equal_the_cli():
    lines = read(MIXED).decode().splitlines()[:40]
    answers = [json.loads(a) for a in cli("batch", "--evidence", "minimal", MIXED).decode().splitlines()[:40]]
    for line, answer in zip(lines, answers):
        d = json.loads(line, parse_float=str)  # each decimal as its text, read exactly
        if "error" in answer:
            continue
        c = relpos.classify(relpos.Ellipsoid(d["ellipsoid"]), relpos.Paraboloid(d["paraboloid"]), "minimal")
        del answer["id"]
        assert list(c.as_dict().items()) == list(answer.items())
        with pytest.raises(AttributeError, match="evidence='minimal'"):
            c.rho
        assert c.certificate is None


def test_rho_none_only_when_irrational():
    """rho = 1/4 for a sphere of radius 1/4 in a cup whose curvature radius is 1/2 at its vertex
    (rho = (r / (1/2))^2): a string with full evidence, absent (not None) with minimal evidence."""
    e = relpos.Ellipsoid.sphere((0, 0, 1), "1/4")
    assert F(relpos.classify(e, CUP).rho) == F(1, 4)
    with pytest.raises(AttributeError):
        relpos.classify(e, CUP, "minimal").rho


def test_decimal_read_as_its_text():
    for text in ("1e-12000", "2.5E+3999", "0.000001", "123456789.987654321"):
        assert relpos.Ellipsoid.sphere((0, 0, 1), Decimal(text)) == relpos.Ellipsoid.sphere((0, 0, 1), text)
    assert relpos.Ellipsoid.sphere((0, 0, Decimal("-1e-12000")), 1) == relpos.Ellipsoid.sphere((0, 0, "-1e-12000"), 1)
    for bad in ("NaN", "sNaN", "Infinity", "1e-20000"):
        with pytest.raises(ValueError) as err:
            relpos.Ellipsoid.sphere((0, 0, Decimal(bad)), 1)
        assert "ellipsoid.sphere.center[2]" in clean(err.value)


# ------------------------------------------------------------------------------------------------
# Stale words.


def test_help_shows_public_names():
    for cls in (relpos.Ellipsoid, relpos.Paraboloid):
        text = pydoc.render_doc(cls, renderer=pydoc.plaintext)
        for private in ("_sphere", "_from_axes", "_ellipsoid_from_map", "_standard", "_paraboloid_from_map"):
            assert " = %s(" % private not in text, (cls, private)
    assert relpos.Ellipsoid.from_axes.__name__ == "from_axes"


def test_docs_do_not_say_the_package_runs_the_cli():
    import relpos._cli

    for path in (os.path.join(SOURCE_DIR, "doc", "install.md"), relpos._cli.__file__,
                 os.path.join(SOURCE_DIR, "python", "relpos", "distributed.py")):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        assert "relpos.distributed` runs" not in text and "relpos.distributed runs" not in text, path
    with open(os.path.join(SOURCE_DIR, ".gitignore"), encoding="utf-8") as f:
        assert "*.egg-info/" in f.read().split()
