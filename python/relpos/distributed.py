"""Scale-out of `relpos batch` over a Dask cluster (doc/python.md, "Dask").

    from distributed import Client
    import relpos.distributed
    client = Client("tcp://scheduler:8786")          # or None: the current client / a LocalCluster
    written = relpos.distributed.batch(["a.jsonl", "b.jsonl"], "answers/", client=client)

One task per input file; each file is answered by the same code as `relpos batch FILE` and written
to out_dir/<same file name>. Input and output paths must be visible to the workers (a shared file
system on a real cluster), and each worker must be able to run the relpos CLI (relpos._cli.find_cli:
RELPOS_CLI, <prefix>/bin/relpos, the build tree, PATH).
"""

import os
import subprocess

from ._cli import find_cli

__all__ = ["batch", "batch_file"]


def batch_file(path, out_path, cli=None):
    """Answer one JSON Lines file as `relpos batch` does, into out_path; returns out_path.

    Runs on a worker. cli: the relpos executable (default: find_cli() on the worker).
    """
    # For now the CLI answers the file; a library-level batch function will replace the subprocess.
    exe = cli or find_cli()
    tmp = out_path + ".part"
    with open(tmp, "wb") as out:
        proc = subprocess.run([exe, "batch", path], stdout=out, stderr=subprocess.PIPE)
    if proc.returncode != 0:
        os.unlink(tmp)
        raise RuntimeError(
            "relpos batch %s failed (exit %d): %s"
            % (path, proc.returncode, proc.stderr.decode(errors="replace").strip())
        )
    os.replace(tmp, out_path)
    return out_path


def batch(paths, out_dir, client=None, cli=None):
    """Answer JSON Lines files on a Dask cluster, one task per file.

    paths: input files; out_dir: where out_dir/<file name> is written (created if missing; two
    inputs with the same file name are refused). client: a distributed.Client; None uses the
    current client (distributed.get_client()) or starts a LocalCluster for this call. cli: the relpos
    executable on the workers (default: each worker's find_cli()). Returns the written paths, in
    the order of `paths`. Raises the first failing file's error.
    """
    paths = [os.path.abspath(os.fspath(p)) for p in paths]
    out_dir = os.path.abspath(os.fspath(out_dir))
    names = [os.path.basename(p) for p in paths]
    if len(set(names)) != len(names):
        raise ValueError("batch: input files must have distinct names (outputs are out_dir/<name>)")
    os.makedirs(out_dir, exist_ok=True)
    outs = [os.path.join(out_dir, n) for n in names]
    if not paths:
        return []

    own = None
    if client is None:
        import distributed

        try:
            client = distributed.get_client()
        except ValueError:
            own = client = distributed.Client(distributed.LocalCluster())
    try:
        futures = client.map(batch_file, paths, outs, cli=cli, pure=False)
        return client.gather(futures)
    finally:
        if own is not None:
            cluster = own.cluster
            own.close()
            cluster.close()
