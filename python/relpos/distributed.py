"""`relpos batch` over a Dask cluster (doc/python.md, "Dask").

    from distributed import Client
    import relpos.distributed
    client = Client("tcp://scheduler:8786")          # or None: the current client / a local cluster
    written = relpos.distributed.batch(["a.jsonl", "b.jsonl"], "answers/", client=client)

Each input file is cut into blocks of whole lines (byte ranges ending after a '\\n'); the workers
answer the blocks in-process with the library's batch-line function (relpos._relpos._batch_block),
and out_dir/<file name> receives exactly the bytes `relpos batch FILE` writes. Input and output
paths must be visible under the same names to the caller and the workers (a shared file system on a
real cluster).

Inputs: a regular file is read by the workers where it lies. Anything whose size cannot be trusted
(a named pipe, a character device, a file of /proc or /sys, any file whose size reads 0) is first
read to its end by the caller into a temporary file in out_dir, and that copy is answered: the same
bytes as `relpos batch FILE`, which reads such files to their end too.

Files: the caller creates every file the call writes (unique temporary names in out_dir, made by
tempfile.mkstemp, of a fixed short length whatever the input's name) before any task runs; tasks
only open them, so a cancelled or killed task cannot leave a file behind. The temporaries become
the outputs (os.replace) once every task has succeeded; on any failure the other tasks are
cancelled, every temporary is removed and out_dir holds what it held before.
"""

import os
import shutil
import stat
import tempfile

# Imported with this module, not on first use: a Ctrl-C during the import of `distributed` (seconds on
# a loaded machine) would leave it half-initialised in sys.modules and every later call hanging.
import distributed

from . import _relpos

__all__ = ["batch"]

_PIECE = 1 << 16  # bytes read, and lines answered, at a time in a block: bounds a task's memory and the
# time a task takes to notice that the call was stopped (Ctrl-C)
_BLOCKS_PER_THREAD = 8  # automatic block size: enough blocks to keep every worker thread busy
_MIN_BLOCK = 1 << 18
_MAX_BLOCK = 1 << 26
_TEMPORARY = ".relpos-"  # prefix of every file the call creates in out_dir (then 8 random characters, ".tmp")


def _changed(path):
    return RuntimeError("relpos.distributed.batch: %s changed while it was being answered" % path)


def _stopped(part):
    """A task's file was removed by the caller: the call failed or was interrupted (Ctrl-C), stop."""
    return not os.path.exists(part)


def _scan_block(path, begin, end):
    """The '\\n' bytes of [begin, end) of the file: (their number, the offset of the first one or -1,
    whether the last byte is one) (a task)."""
    count, first, last = 0, -1, False
    with open(path, "rb") as f:
        f.seek(begin)
        pos = begin
        while pos < end:
            piece = f.read(min(_PIECE, end - pos))
            if not piece:
                raise _changed(path)
            if first < 0:
                k = piece.find(b"\n")
                if k >= 0:
                    first = pos + k
            count += piece.count(b"\n")
            pos += len(piece)
            last = piece.endswith(b"\n")
    return count, first, last


def _ranges(size, block, scans):
    """The byte range of whole lines each block answers, and the number of its first line, from the
    blocks' scans: a block answers the lines that start in it, so a line is read by one task only,
    and a block that starts inside a line skips to its end without reading it (the scans located
    every '\\n'). Blocks that start no line are left out. [(start, end, first line number)]."""
    starts = []
    next_newline = -1  # the first '\n' at or after the current block, scanning from the end
    for k in range(len(scans) - 1, -1, -1):
        if scans[k][1] >= 0:
            next_newline = scans[k][1]
        begin = k * block
        if k == 0 or scans[k - 1][2]:
            starts.append((begin, 0))  # the file's start, or just after a '\n' ending the previous block
        elif next_newline >= 0:
            starts.append((next_newline + 1, 1))  # after the first '\n' at or after begin: one '\n' skipped
        else:
            starts.append((size, 0))
    starts.reverse()
    out, before = [], 0  # before: the '\n' bytes in the blocks before k
    for k, (start, skipped) in enumerate(starts):
        end = starts[k + 1][0] if k + 1 < len(starts) else size
        if start < end:
            out.append((start, end, 1 + before + skipped))
        before += scans[k][0]
    return out


def _answer_range(path, start, end, number, part, options):
    """Answer the lines of bytes [start, end) of the file (whole lines, the first one numbered
    `number`) into the existing file `part` (a task). Returns the bytes written."""
    written = 0
    with open(path, "rb") as f:
        # No O_CREAT: after a cancellation the caller removes `part`, and a late task must not re-create it.
        with os.fdopen(os.open(part, os.O_WRONLY | os.O_TRUNC), "wb") as out:
            f.seek(start)
            buf = bytearray()
            pos = start
            while pos < end:
                if _stopped(part):
                    return written
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
    flat = [f for per_file in rounds for f in per_file]
    submitted += flat
    for f in distributed.as_completed(flat):
        if f.status == "error":
            f.result()  # raises the task's error, before the tasks still running finish
    results = iter(client.gather(flat))
    return [[next(results) for _ in per_file] for per_file in rounds]


def _sized(st):
    """Whether the workers can read a file by byte ranges: a regular file whose size is its length.
    Files of /proc and /sys read as size 0 or occupy no block; pipes and devices have no size."""
    return stat.S_ISREG(st.st_mode) and st.st_size > 0 and st.st_blocks > 0


def _check_inputs(paths, out_dir):
    """Absolute input paths, their stat results, and the output paths; refuse what would overwrite or
    mix files, before anything is written."""
    if isinstance(paths, (str, bytes, os.PathLike)):
        paths = [paths]
    try:
        paths = [os.path.abspath(os.fsdecode(p)) for p in paths]
    except TypeError:
        raise TypeError("relpos.distributed.batch: paths: expected a path (str or os.PathLike) or a list of paths")
    try:
        out_dir = os.path.abspath(os.fsdecode(out_dir))
    except TypeError:
        raise TypeError("relpos.distributed.batch: out_dir: expected a path (str or os.PathLike), got %s"
                        % type(out_dir).__name__)
    stats = []
    for p in paths:
        try:
            st = os.stat(p)
        except FileNotFoundError:
            raise FileNotFoundError("relpos.distributed.batch: no such input file: %s" % p) from None
        if stat.S_ISDIR(st.st_mode):
            raise IsADirectoryError("relpos.distributed.batch: the input %s is a directory, not a file" % p)
        if stat.S_ISSOCK(st.st_mode):
            raise ValueError("relpos.distributed.batch: the input %s is a socket, not a file" % p)
        stats.append(st)
    names = [os.path.basename(p) for p in paths]
    if len(set(names)) != len(names):
        raise ValueError("relpos.distributed.batch: input files must have distinct names (outputs are out_dir/<name>)")
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise NotADirectoryError("relpos.distributed.batch: out_dir %s is not a directory" % out_dir)
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
        if os.path.isdir(o):
            raise IsADirectoryError(
                "relpos.distributed.batch: the output %s is a directory; nothing was written" % o)
    return paths, stats, out_dir, outs


def _options(evidence, numbers, contact_only, digits, max_line_bytes, threads, block_bytes, max_bits):
    """The options of `relpos batch`, checked with messages naming the argument, before any work."""

    def integer(name, value, allow_none=False):
        if value is None and allow_none:
            return None
        if isinstance(value, bool) or not hasattr(type(value), "__index__"):
            raise TypeError("relpos.distributed.batch: %s: expected an int, got %s" % (name, type(value).__name__))
        return value.__index__()

    for name, value in (("evidence", evidence), ("numbers", numbers)):
        if not isinstance(value, str):
            raise TypeError("relpos.distributed.batch: %s: expected a str, got %s" % (name, type(value).__name__))
    if not isinstance(contact_only, bool):
        raise TypeError("relpos.distributed.batch: contact_only: expected a bool, got %s" % type(contact_only).__name__)
    options = dict(evidence=evidence, numbers=numbers, contact_only=contact_only, digits=integer("digits", digits),
                   threads=integer("threads", threads), max_bits=integer("max_bits", max_bits))
    max_line_bytes = integer("max_line_bytes", max_line_bytes, allow_none=True)
    if max_line_bytes is not None:  # else the CLI's default
        options["max_line_bytes"] = max_line_bytes
    for name, bits in (("digits", 31), ("threads", 31), ("max_bits", 62)):  # what the binding's integers hold
        if not -(1 << bits) <= options[name] < (1 << bits):
            raise ValueError("relpos.distributed.batch: %s: %d is out of range" % (name, options[name]))
    if max_line_bytes is not None and not 1 <= max_line_bytes <= (1 << 40):
        raise ValueError("relpos.distributed.batch: max_line_bytes: expected 1 to 2^40, got %d" % max_line_bytes)
    try:
        _relpos._batch_block(b"", **options)  # the library's checks of the values
    except ValueError as err:
        raise ValueError("relpos.distributed.batch: %s" % err) from None
    block_bytes = integer("block_bytes", block_bytes, allow_none=True)
    if block_bytes is not None and block_bytes < 1:
        raise ValueError("relpos.distributed.batch: block_bytes: expected >= 1, got %r" % (block_bytes,))
    return options, block_bytes


def _spool(path, out_dir, temporary):
    """Read a file whose size cannot be trusted (a pipe, /proc, a device) to its end into a
    temporary file of out_dir, which the workers then read. Returns its path and size."""
    copy = temporary()
    size = 0
    with open(path, "rb") as src, open(copy, "wb") as dst:
        while True:
            piece = src.read(_PIECE)
            if not piece:
                break
            dst.write(piece)
            size += len(piece)
    return copy, size


def _publish(targets, outs, temporary):
    """Move every finished output into place, all or none: an output that existed is first kept
    under a temporary name (a hard link to it, so that it never disappears meanwhile), and a failure
    half-way puts every output back as it was. The kept copies are temporaries of the call."""
    done = []
    try:
        for tmp, out in zip(targets, outs):
            old = None
            if os.path.lexists(out):
                old = temporary()
                os.unlink(old)
                try:
                    os.link(out, old, follow_symlinks=False)  # a symbolic link is kept as one
                except OSError:  # a file system without hard links: moved aside instead
                    os.rename(out, old)
            done.append((out, old))
            os.replace(tmp, out)
    except BaseException:
        for out, old in reversed(done):
            try:
                if old is not None:
                    os.replace(old, out)
                elif os.path.lexists(out):
                    os.unlink(out)
            except OSError:
                pass
        raise


def _local_client():
    """A client of a local cluster for one call: threads of this process (the work is compiled code
    that releases the GIL), so no process is started and a script without an
    `if __name__ == "__main__":` guard works."""
    cluster = distributed.LocalCluster(processes=False, n_workers=1, threads_per_worker=os.cpu_count() or 1,
                                       dashboard_address=None)
    return distributed.Client(cluster)


def batch(paths, out_dir, client=None, evidence="full", numbers="exact", contact_only=False, digits=12,
          max_line_bytes=None, threads=1, block_bytes=None, max_bits=4096):
    """Answer JSON Lines files on a Dask cluster as `relpos batch` does; returns the written paths.

    paths: one input file (str or os.PathLike) or a list of them. out_dir: out_dir/<file name>
    receives the answers of each file, byte for byte the output of `relpos batch FILE` with the same
    options (created if missing; it must not hold an input, and two inputs must not share a name).
    Named pipes, files of /proc and other files whose size reads 0 are read to their end first.
    evidence ("full" | "minimal"), numbers ("exact" | "double"), contact_only, digits,
    max_line_bytes (None: the CLI's default), max_bits (the pair size limit): the options --evidence,
    --numbers, --contact-only, --digits, --max-line-bytes, --max-bits.
    client: a distributed.Client; None uses the current client (distributed.get_client()) or starts
    a local cluster of threads in this process for the call. threads: library threads per task.
    block_bytes: bytes of a file per task (default: about 8 blocks per worker thread, 256 KiB to
    64 MiB).
    Returns the output paths in the order of `paths` (a list, also for one path). Raises the first
    failing task's error (or KeyboardInterrupt), after cancelling the others and removing every file
    the call created: out_dir then holds what it held before.
    """
    options, block_bytes = _options(evidence, numbers, contact_only, digits, max_line_bytes, threads, block_bytes,
                                    max_bits)
    paths, stats, out_dir, outs = _check_inputs(paths, out_dir)
    os.makedirs(out_dir, exist_ok=True)
    if not paths:
        return []

    temps, futures = [], []
    own = None

    def temporary():
        fd, tmp = tempfile.mkstemp(dir=out_dir, prefix=_TEMPORARY, suffix=".tmp")
        os.close(fd)
        temps.append(tmp)
        return tmp

    try:
        # What the workers read: the file itself, or the caller's copy of a stream.
        sources, sizes = [], []
        for p, st in zip(paths, stats):
            if _sized(st):
                sources.append(p)
                sizes.append(st.st_size)
            else:
                copy, size = _spool(p, out_dir, temporary)
                sources.append(copy)
                sizes.append(size)

        if client is None:
            try:
                client = distributed.get_client()
            except ValueError:
                own = client = _local_client()
        if block_bytes is None:
            worker_threads = max(1, sum(client.nthreads().values()))
            block_bytes = -(-sum(sizes) // (_BLOCKS_PER_THREAD * worker_threads))
            block_bytes = min(max(block_bytes, _MIN_BLOCK), _MAX_BLOCK)

        # Three rounds, each waited for here: no task depends on another's result, so a worker lost
        # in the middle only loses its running task, which Dask runs again elsewhere.
        targets = [temporary() for _ in outs]
        blocks = [-(-size // block_bytes) for size in sizes]
        scans = _run(client, futures, [
            [client.submit(_scan_block, src, k * block_bytes, min(size, (k + 1) * block_bytes), pure=False)
             for k in range(n)] for src, size, n in zip(sources, sizes, blocks)])
        ranges = [_ranges(size, block_bytes, s) for size, s in zip(sizes, scans)]
        parts = [[temporary() for _ in r] for r in ranges]
        _run(client, futures, [
            [client.submit(_answer_range, src, start, end, number, part, options, pure=False)
             for (start, end, number), part in zip(r, file_parts)]
            for src, r, file_parts in zip(sources, ranges, parts)])
        _run(client, futures, [[client.submit(_join, p, t, pure=False)] for p, t in zip(parts, targets)])
        mode = 0o666 & ~_umask()
        for tmp in targets:
            os.chmod(tmp, mode)  # as a file the CLI's output is redirected to (mkstemp makes 0600)
        _publish(targets, outs, temporary)
        return outs
    except BaseException:
        if futures:
            client.cancel(futures)
        raise
    finally:
        for tmp in temps:  # the copies and parts; the targets too on failure
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
