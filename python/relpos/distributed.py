"""`relpos batch` over a Dask cluster (doc/python.md, "Dask").

    from distributed import Client
    import relpos.distributed
    client = Client("tcp://scheduler:8786")          # or None: the current client / a LocalCluster
    written = relpos.distributed.batch(["a.jsonl", "b.jsonl"], "answers/", client=client)

Each input file is cut into blocks of whole lines (byte ranges ending after a '\\n'); the workers
answer the blocks in-process with the library's batch-line function (relpos._relpos._batch_block),
and out_dir/<file name> receives exactly the bytes `relpos batch FILE` writes. Input and output
paths must be visible under the same names to the caller and the workers (a shared file system on a
real cluster).

Files: the caller creates every file the call writes (unique temporary names in out_dir, made by
tempfile.mkstemp) before any task runs; tasks only open them, so a cancelled or killed task cannot
leave a file behind. The temporaries become the outputs (os.replace) once every task has succeeded;
on any failure the other tasks are cancelled and every temporary is removed.
"""

import os
import shutil
import tempfile

from . import _relpos

__all__ = ["batch"]

_PIECE = 1 << 20  # bytes read, and lines answered, at a time in a block: bounds a task's memory
_BLOCKS_PER_THREAD = 8  # automatic block size: enough blocks to keep every worker thread busy
_MIN_BLOCK = 1 << 18
_MAX_BLOCK = 1 << 26


def _changed(path):
    return RuntimeError("relpos.distributed.batch: %s changed while it was being answered" % path)


def _count_newlines(path, begin, end):
    """The '\\n' bytes in [begin, end) of the file (a task)."""
    count = 0
    with open(path, "rb") as f:
        f.seek(begin)
        while begin < end:
            piece = f.read(min(_PIECE, end - begin))
            if not piece:
                raise _changed(path)
            count += piece.count(b"\n")
            begin += len(piece)
    return count


def _first_line_numbers(counts):
    """1 + the number of '\\n' before each block: the number of the line that starts at the block's
    first byte, or that would."""
    numbers = [1]
    for c in counts[:-1]:
        numbers.append(numbers[-1] + c)
    return numbers


def _line_start(f, offset, size, path):
    """The first byte at or after offset that starts a line (0, or just after a '\\n'); size if none."""
    if offset == 0 or offset >= size:
        return min(offset, size)
    pos = offset - 1
    f.seek(pos)
    while pos < size:
        piece = f.read(min(_PIECE, size - pos))
        if not piece:
            raise _changed(path)
        nl = piece.find(b"\n")
        if nl >= 0:
            return pos + nl + 1
        pos += len(piece)
    return size


def _answer_block(path, index, block, size, first_number, part, options):
    """Answer the lines that start in bytes [index * block, (index + 1) * block) of the file into the
    existing file `part` (a task); first_number: that of the line starting at index * block, or that
    would. Returns the bytes written."""
    begin = index * block
    written = 0
    with open(path, "rb") as f:
        start = _line_start(f, begin, size, path)
        end = _line_start(f, begin + block, size, path)
        number = first_number + (start > begin)  # a '\n' in [begin, start) ends a line of the previous block
        # No O_CREAT: after a cancellation the caller removes `part`, and a late task must not re-create it.
        with os.fdopen(os.open(part, os.O_WRONLY | os.O_TRUNC), "wb") as out:
            f.seek(start)
            buf = bytearray()
            pos = start
            while pos < end:
                piece = f.read(min(_PIECE, end - pos))
                if not piece:
                    raise _changed(path)
                pos += len(piece)
                buf += piece
                cut = len(buf) if pos == end else buf.rfind(b"\n") + 1  # whole lines; the last one at the end
                if cut == 0:
                    continue
                lines = bytes(memoryview(buf)[:cut])
                del buf[:cut]
                answers = _relpos._batch_block(lines, number, **options)
                out.write(answers)
                written += len(answers)
                number += lines.count(b"\n")
    return written


def _join(parts, target):
    """Concatenate the parts, in order, into the existing file `target` (a task)."""
    with os.fdopen(os.open(target, os.O_WRONLY | os.O_TRUNC), "wb") as out:
        for part in parts:
            with open(part, "rb") as f:
                if hasattr(os, "copy_file_range"):  # in the kernel, without a pass through Python
                    while os.copy_file_range(f.fileno(), out.fileno(), 1 << 30):
                        pass
                else:
                    shutil.copyfileobj(f, out, _PIECE)
    return target


def _run(client, submitted, rounds):
    """Wait for the futures of `rounds` (a list per file) and return their results, list by list;
    the first error is raised as soon as its task fails. `submitted` collects every future (for
    cancellation)."""
    import distributed

    flat = [f for per_file in rounds for f in per_file]
    submitted += flat
    for f in distributed.as_completed(flat):
        if f.status == "error":
            f.result()  # raises the task's error, before the tasks still running finish
    results = iter(client.gather(flat))
    return [[next(results) for _ in per_file] for per_file in rounds]


def _check_inputs(paths, out_dir):
    """Absolute input paths and output paths; refuse what would overwrite or mix files."""
    if isinstance(paths, (str, bytes, os.PathLike)):
        paths = [paths]
    paths = [os.path.abspath(os.fsdecode(p)) for p in paths]
    out_dir = os.path.abspath(os.fsdecode(out_dir))
    for p in paths:
        if not os.path.exists(p):
            raise FileNotFoundError("relpos.distributed.batch: no such input file: %s" % p)
        if os.path.isdir(p):
            raise IsADirectoryError("relpos.distributed.batch: the input %s is a directory, not a file" % p)
    names = [os.path.basename(p) for p in paths]
    if len(set(names)) != len(names):
        raise ValueError("relpos.distributed.batch: input files must have distinct names (outputs are out_dir/<name>)")
    real_out = os.path.realpath(out_dir)
    outs = [os.path.join(out_dir, n) for n in names]
    real_inputs = {os.path.realpath(p) for p in paths}
    for p, o in zip(paths, outs):
        dirs = {os.path.realpath(os.path.dirname(p)), os.path.dirname(os.path.realpath(p))}
        if real_out in dirs or os.path.realpath(o) in real_inputs:
            raise ValueError(
                "relpos.distributed.batch: out_dir %s holds the input %s; answers are written to another directory"
                % (out_dir, p)
            )
    return paths, out_dir, outs


def batch(paths, out_dir, client=None, evidence="full", numbers="exact", contact_only=False, digits=12,
          max_line_bytes=None, threads=1, block_bytes=None):
    """Answer JSON Lines files on a Dask cluster as `relpos batch` does; returns the written paths.

    paths: one input file (str or os.PathLike) or a list of them. out_dir: out_dir/<file name>
    receives the answers of each file, byte for byte the output of `relpos batch FILE` with the same
    options (created if missing; it must not hold an input, and two inputs must not share a name).
    evidence ("full" | "minimal"), numbers ("exact" | "double"), contact_only, digits,
    max_line_bytes (None: the CLI's default): the options --evidence, --numbers, --contact-only,
    --digits, --max-line-bytes.
    client: a distributed.Client; None uses the current client (distributed.get_client()) or starts
    a LocalCluster for this call. threads: library threads per task. block_bytes: bytes of a file
    per task (default: about 8 blocks per worker thread, 256 KiB to 64 MiB).
    Returns the output paths in the order of `paths` (a list, also for one path). Raises the first
    failing task's error, after cancelling the others and removing every file the call created.
    """
    options = dict(evidence=evidence, numbers=numbers, contact_only=contact_only, digits=digits, threads=threads)
    if max_line_bytes is not None:  # else the CLI's default
        options["max_line_bytes"] = max_line_bytes
    _relpos._batch_block(b"", **options)  # the options' errors, before anything is submitted
    paths, out_dir, outs = _check_inputs(paths, out_dir)
    if block_bytes is not None and block_bytes < 1:
        raise ValueError("relpos.distributed.batch: block_bytes: expected >= 1, got %r" % (block_bytes,))
    sizes = [os.path.getsize(p) for p in paths]
    os.makedirs(out_dir, exist_ok=True)
    if not paths:
        return []

    import distributed

    own = None
    if client is None:
        try:
            client = distributed.get_client()
        except ValueError:
            own = client = distributed.Client(distributed.LocalCluster())
    temps, futures = [], []
    try:
        if block_bytes is None:
            worker_threads = max(1, sum(client.nthreads().values()))
            block_bytes = -(-sum(sizes) // (_BLOCKS_PER_THREAD * worker_threads))
            block_bytes = min(max(block_bytes, _MIN_BLOCK), _MAX_BLOCK)

        def temporary(name):
            fd, tmp = tempfile.mkstemp(dir=out_dir, prefix="." + name + ".", suffix=".tmp")
            os.close(fd)
            temps.append(tmp)
            return tmp

        # Three rounds, each waited for here: no task depends on another's result, so a worker lost
        # in the middle only loses its running task, which Dask runs again elsewhere.
        targets = [temporary(os.path.basename(out)) for out in outs]
        blocks = [-(-size // block_bytes) for size in sizes]
        parts = [[temporary(os.path.basename(out)) for _ in range(n)] for out, n in zip(outs, blocks)]
        counts = _run(client, futures, [
            [client.submit(_count_newlines, path, k * block_bytes, min(size, (k + 1) * block_bytes), pure=False)
             for k in range(n)] for path, size, n in zip(paths, sizes, blocks)])
        _run(client, futures, [
            [client.submit(_answer_block, path, k, block_bytes, size, first, part, options, pure=False)
             for k, (first, part) in enumerate(zip(_first_line_numbers(c), file_parts))]
            for path, size, c, file_parts in zip(paths, sizes, counts, parts)])
        _run(client, futures, [[client.submit(_join, p, t, pure=False)] for p, t in zip(parts, targets)])
        mode = 0o666 & ~_umask()
        for tmp, out in zip(targets, outs):
            os.chmod(tmp, mode)  # as a file the CLI's output is redirected to (mkstemp makes 0600)
            os.replace(tmp, out)
        return outs
    except BaseException:
        if futures:
            client.cancel(futures)
        raise
    finally:
        for tmp in temps:  # the parts; the targets too on failure
            try:
                os.unlink(tmp)
            except FileNotFoundError:
                pass
        if own is not None:
            cluster = own.cluster
            own.close()
            cluster.close()


def _umask():
    mask = os.umask(0o022)
    os.umask(mask)
    return mask
