"""Tests of relpos.distributed and the Dask routes of doc/python.md ("Dask"), on a LocalCluster of two
worker processes. The reference for every output is the `relpos batch` CLI (RELPOS_CLI) on the same
file with the same options.
"""

import json
import os
import re
import subprocess
import sys
import time

import numpy
import pytest

import relpos

distributed = pytest.importorskip("distributed")
import relpos.distributed  # noqa: E402  (after the skip: needs distributed)

SOURCE_DIR = os.environ.get(
    "RELPOS_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
)
CORPUS = [
    os.path.join(SOURCE_DIR, "examples", "mixed.jsonl"),
    os.path.join(SOURCE_DIR, "examples", "scene-container.jsonl"),
    os.path.join(SOURCE_DIR, "tests", "hostile", "hostile.jsonl"),
]


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as c:
        yield c


def cli_batch_file(path, *options):
    return subprocess.run([relpos._cli.find_cli(), "batch", str(path), *options], stdout=subprocess.PIPE,
                          check=True).stdout


def read(path):
    with open(path, "rb") as f:
        return f.read()


@pytest.fixture(scope="module")
def edge_file(tmp_path_factory):
    """What the CLI reads specially, in one file: a BOM on line 1 and mid-file, CRLF, blank lines
    (also "\\r" alone), a NUL byte, invalid UTF-8 in an id, a line over a small --max-line-bytes,
    numbers that differ as doubles, the last line without '\\n'."""
    good = read(CORPUS[0]).split(b"\n")[:12]
    body = [b"\xef\xbb\xbf" + good[0], good[1] + b"\r", b"", b"\r", b"\xef\xbb\xbf" + good[2],
            b'{"id": "nul\x00", "ellipsoid": 1}', b'{"id": "\xff\xfe", "ellipsoid": {}}',
            b'{"id": 7, "ellipsoid": {"sphere": {"center": [0, 0, 1], "radius": 0.1}}, "paraboloid": '
            b'{"vertex": [0, 0, 0], "a": 0.3, "b": 0.3}}', b"x" * 3000]
    body += good[3:] + [b"   ", good[4] + b"\r"]
    path = tmp_path_factory.mktemp("edge") / "edge.jsonl"
    path.write_bytes(b"\n".join(body))
    return path


@pytest.fixture(scope="module")
def quadric_file(tmp_path_factory):
    """Lines with "quadric" in place of "paraboloid" (doc/quadrics.md): a ball against a hyperboloid
    (TI along its waist: the hard case), two ellipsoids (O), a cylinder (C), a half-space (E), a
    degenerate quadric (an error line) and a line with both "paraboloid" and "quadric" (an error)."""
    ball = {"sphere": {"center": [0, 0, 0], "radius": 1}}
    lines = [
        {"id": "h", "ellipsoid": ball, "quadric": {"type": "hyperboloid of one sheet", "center": [0, 0, 0],
                                                  "axes": [1, 1, 1]}},
        {"id": "o", "ellipsoid": ball, "quadric": {"type": "ellipsoid", "center": [0.25, 0, 0],
                                                  "axes": [0.5, 0.25, 0.125], "rotation": [1, 2, 3, 4]}},
        {"id": "c", "ellipsoid": ball, "quadric": {"type": "elliptic cylinder", "center": [1, 0, 0], "a": 0.5, "b": 2}},
        {"id": "e", "ellipsoid": ball, "quadric": {"type": "half-space", "normal": [1, 1, 1], "offset": -2}},
        {"id": "bad", "ellipsoid": ball, "quadric": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]},
        {"id": "both", "ellipsoid": ball, "quadric": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]],
         "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}},
    ]
    path = tmp_path_factory.mktemp("quadric") / "quadric.jsonl"
    path.write_text("".join(json.dumps(x) + "\n" for x in lines * 20))
    return path


# Each evidence level, and the other options of `relpos batch`.
OPTIONS = [
    ({"evidence": "full"}, ["--evidence", "full"]),
    ({"evidence": "minimal"}, ["--evidence", "minimal"]),
    ({"contact_only": True}, ["--contact-only"]),
    ({"numbers": "double", "digits": 5, "max_line_bytes": 2000},
     ["--numbers", "double", "--digits", "5", "--max-line-bytes", "2000"]),
]


@pytest.mark.parametrize("kwargs,flags", OPTIONS, ids=lambda x: str(x) if isinstance(x, dict) else None)
def test_byte_identity_with_cli(client, tmp_path, edge_file, quadric_file, kwargs, flags):
    inputs = CORPUS + [edge_file, quadric_file]
    # Blocks of 1 KiB: every file is cut into several blocks, lines straddle block edges.
    written = relpos.distributed.batch(inputs, tmp_path / "out", client=client, block_bytes=1024, **kwargs)
    assert written == [str(tmp_path / "out" / os.path.basename(p)) for p in inputs]
    for src, out in zip(inputs, written):
        assert read(out) == cli_batch_file(src, *flags), src
    assert sorted(os.listdir(tmp_path / "out")) == sorted(os.path.basename(p) for p in inputs)


def test_one_path_and_block_sizes(client, tmp_path, edge_file):
    expected = cli_batch_file(edge_file)
    # one str path, one os.PathLike; the automatic block size; blocks smaller than a line
    assert relpos.distributed.batch(str(edge_file), str(tmp_path / "a"), client=client) == [str(tmp_path / "a" /
                                                                                                  "edge.jsonl")]
    assert read(tmp_path / "a" / "edge.jsonl") == expected
    for block in (37, 4096):
        out = relpos.distributed.batch(edge_file, tmp_path / ("b%d" % block), client=client, block_bytes=block)
        assert read(out[0]) == expected
    # an empty file and a file of one '\n'
    (tmp_path / "in").mkdir()
    for name, data in (("empty.jsonl", b""), ("newline.jsonl", b"\n")):
        (tmp_path / "in" / name).write_bytes(data)
        out = relpos.distributed.batch(tmp_path / "in" / name, tmp_path / "c", client=client, block_bytes=1)
        assert read(out[0]) == cli_batch_file(tmp_path / "in" / name)


def test_part_suffix_inputs(client, tmp_path):
    """x.jsonl and x.jsonl.part are two inputs with two outputs, whatever the temporaries are called."""
    lines = read(CORPUS[0]).split(b"\n")
    (tmp_path / "in").mkdir()
    a, b = tmp_path / "in" / "x.jsonl", tmp_path / "in" / "x.jsonl.part"
    a.write_bytes(b"\n".join(lines[0::2]))
    b.write_bytes(b"\n".join(lines[1::2]))
    out = relpos.distributed.batch([a, b], tmp_path / "out", client=client, block_bytes=2048)
    assert read(out[0]) == cli_batch_file(a) and read(out[1]) == cli_batch_file(b)
    assert read(out[0]) != read(out[1])
    assert sorted(os.listdir(tmp_path / "out")) == ["x.jsonl", "x.jsonl.part"]


def test_refusals_before_any_task(tmp_path):
    (tmp_path / "in").mkdir()
    src = tmp_path / "in" / "a.jsonl"
    src.write_bytes(read(CORPUS[0]))
    os.symlink(tmp_path / "in", tmp_path / "link")
    no_client = object()  # any use of the client would raise AttributeError
    for out_dir in (tmp_path / "in", str(tmp_path / "in") + "/", tmp_path / "link", tmp_path / "in" / "." / "sub" / ".."):
        with pytest.raises(ValueError, match="holds the input"):
            relpos.distributed.batch([src], out_dir, client=no_client)
    os.symlink(src, tmp_path / "elsewhere.jsonl")  # input by a link; the out_dir holds its target
    with pytest.raises(ValueError, match="holds the input"):
        relpos.distributed.batch(tmp_path / "elsewhere.jsonl", tmp_path / "in", client=no_client)
    with pytest.raises(FileNotFoundError, match="no such input file: .*missing.jsonl"):
        relpos.distributed.batch([src, tmp_path / "missing.jsonl"], tmp_path / "out", client=no_client)
    with pytest.raises(IsADirectoryError):
        relpos.distributed.batch(tmp_path / "in", tmp_path / "out", client=no_client)
    with pytest.raises(ValueError, match="distinct names"):
        relpos.distributed.batch([src, src], tmp_path / "out", client=no_client)
    with pytest.raises(ValueError, match="evidence: expected 'full' or 'minimal', got 'some'"):
        relpos.distributed.batch(src, tmp_path / "out", client=no_client, evidence="some")
    with pytest.raises(ValueError, match="digits"):
        relpos.distributed.batch(src, tmp_path / "out", client=no_client, digits=0)
    assert not os.path.exists(tmp_path / "out")
    assert os.listdir(tmp_path / "in") == ["a.jsonl"]


def test_failure_cancels_and_removes_every_file(client, tmp_path):
    """A block that fails on a worker: the call raises its error, and out_dir holds exactly what it
    held before (no temporary, no partial output), also once the cancelled tasks have stopped."""
    lines = read(CORPUS[0]).split(b"\n")
    (tmp_path / "in").mkdir()
    inputs = []
    for k in range(3):
        path = tmp_path / "in" / ("f%d.jsonl" % k)
        chunk = lines[k::3]
        if k == 1:
            chunk = chunk[:5] + [b'{"id": "FAIL-HERE"}'] + chunk[5:]
        path.write_bytes(b"\n".join(chunk * 4))
        inputs.append(path)
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    (out_dir / "f0.jsonl").write_bytes(b"an earlier output\n")

    def inject():
        import relpos._relpos as r

        real = r._batch_block

        def failing(data, *args, **kwargs):
            if b"FAIL-HERE" in data:
                raise RuntimeError("injected failure")
            return real(data, *args, **kwargs)

        r._real_batch_block = real
        r._batch_block = failing

    def restore():
        import relpos._relpos as r

        r._batch_block = r.__dict__.pop("_real_batch_block", r._batch_block)

    client.run(inject)
    try:
        with pytest.raises(RuntimeError, match="injected failure"):
            relpos.distributed.batch(inputs, out_dir, client=client, block_bytes=512)
        time.sleep(1)  # the cancelled tasks that were running have ended
        assert os.listdir(out_dir) == ["f0.jsonl"]
        assert read(out_dir / "f0.jsonl") == b"an earlier output\n"
    finally:
        client.run(restore)
    # the same files answer once the fault is gone
    written = relpos.distributed.batch(inputs, out_dir, client=client, block_bytes=512)
    assert [read(w) for w in written] == [cli_batch_file(p) for p in inputs]


def test_killed_worker_leaves_no_file(tmp_path):
    """A worker process killed in the middle of a block: no process is left behind (the work is in
    the worker itself), the block is answered again elsewhere, and the output is the CLI's."""
    src = tmp_path / "big.jsonl"
    src.write_bytes(read(CORPUS[0]) * 20)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as c:
        before = set(c.run(os.getpid).values())

        def kill_first():
            import os as _os
            import signal

            import relpos._relpos as r

            real = r._batch_block

            def dying(data, *args, **kwargs):
                try:  # the first block to start, on either worker, kills its worker
                    _os.close(_os.open(str(src) + ".killed", _os.O_CREAT | _os.O_EXCL | _os.O_WRONLY))
                except FileExistsError:
                    return real(data, *args, **kwargs)
                _os.kill(_os.getpid(), signal.SIGKILL)

            r._batch_block = dying

        c.run(kill_first)
        out = relpos.distributed.batch(src, tmp_path / "out", client=c, block_bytes=4096)
        assert os.path.exists(str(src) + ".killed")
        assert read(out[0]) == cli_batch_file(src)
        assert os.listdir(tmp_path / "out") == ["big.jsonl"]
        assert before - set(c.run(os.getpid).values())  # a worker process died (the nanny started another)
    # no process anywhere still reads the input (a subprocess of the killed worker would)
    readers = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                if str(src).encode() in f.read():
                    readers.append(pid)
        except OSError:
            pass
    assert readers == []


def doc_blocks(section):
    """The ```python blocks of a section (## title) of doc/python.md."""
    with open(os.path.join(SOURCE_DIR, "doc", "python.md"), encoding="utf-8") as f:
        text = f.read()
    start = text.index("\n## " + section)
    end = text.find("\n## ", start + 1)
    return re.findall(r"```python\n(.*?)```", text[start:end if end >= 0 else None], re.S)


def test_doc_dask_array_route(client):
    """The dask.array route of doc/python.md, run as written (on this test's cluster), against
    decide_positions on the whole arrays."""
    block = next(b for b in doc_blocks("Dask") if "map_blocks" in b)
    scope = {}
    exec(block, scope)
    codes, E, P = scope["codes"], scope["E"], scope["P"]
    assert isinstance(codes, numpy.ndarray) and codes.dtype == numpy.int8 and codes.shape == (len(E),)
    assert scope["E_d"].numblocks[0] > 1
    assert (codes == relpos.decide_positions(E, P)).all()
    assert set(codes) - {-1} >= {0, 4}  # the block sees both sides of the cup
    # a P per pair, chunked like E, as the text after the block says
    import dask.array as da

    P_d = da.from_array(P[None].repeat(len(E), 0), chunks=scope["E_d"].chunks)
    per_pair = da.map_blocks(relpos.decide_positions, scope["E_d"], P_d, drop_axis=[1, 2], dtype=numpy.int8)
    assert (per_pair.compute() == codes).all()


def test_doc_batch_block(client, tmp_path, monkeypatch):
    """The relpos.distributed.batch block of doc/python.md, run as written with this test's scheduler,
    in a directory holding examples/mixed.jsonl."""
    block = next(b for b in doc_blocks("Dask") if "relpos.distributed.batch(" in b)
    (tmp_path / "examples").mkdir()
    (tmp_path / "examples" / "mixed.jsonl").write_bytes(read(CORPUS[0]))
    monkeypatch.chdir(tmp_path)
    scope = {"scheduler": client.scheduler.address}
    try:
        exec(block, scope)
    finally:
        if "client" in scope:
            scope["client"].close()
    assert scope["written"] == [str(tmp_path / "answers" / "mixed.jsonl")]
    assert read(tmp_path / "answers" / "mixed.jsonl") == cli_batch_file(CORPUS[0])


def test_example_script(client, tmp_path):
    """examples/python/dask_batch.py on this test's cluster (test_examples.py runs it on its own)."""
    script = os.path.join(SOURCE_DIR, "examples", "python", "dask_batch.py")
    out = subprocess.run([sys.executable, script, CORPUS[2], "--out-dir", str(tmp_path), "--scheduler",
                          client.scheduler.address], stdout=subprocess.PIPE, check=True).stdout.decode()
    assert out == "%s: one answer per input line\n" % os.path.relpath(tmp_path / "hostile.jsonl")
    assert read(tmp_path / "hostile.jsonl") == cli_batch_file(CORPUS[2])
