#!/usr/bin/python3
"""Answer JSON Lines files on a Dask cluster, as `relpos batch FILE` would (doc/python.md, "Dask").

    PYTHONPATH=build/python /usr/bin/python3 examples/python/dask_batch.py [FILE...] [--out-dir answers] \
        [--scheduler tcp://host:8786] [--workers 2] [--evidence full|minimal]

Without FILE, examples/mixed.jsonl; without --scheduler, a LocalCluster of --workers processes (one
thread each). Writes OUT_DIR/<file name> for each file and says whether it holds one answer per
input line.
"""

import argparse
import os

import distributed

import relpos.distributed

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def lines(path):
    """The lines `relpos batch` reads: one per '\\n', and a last one without it."""
    with open(path, "rb") as f:
        data = f.read()
    return data.count(b"\n") + (not data.endswith(b"\n") and len(data) > 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="*", default=[os.path.join(EXAMPLES, "mixed.jsonl")])
    ap.add_argument("--out-dir", default="answers")
    ap.add_argument("--scheduler", help="address of a running scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    ap.add_argument("--evidence", choices=("full", "minimal"), default="full")
    args = ap.parse_args()

    if args.scheduler:
        cluster = None
        client = distributed.Client(args.scheduler)
    else:
        cluster = distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, dashboard_address=None)
        client = distributed.Client(cluster)
    with client:
        written = relpos.distributed.batch(args.files, args.out_dir, client=client, evidence=args.evidence)
    if cluster is not None:
        cluster.close()
    for src, out in zip(args.files, written):
        verdict = "one answer per input line" if lines(out) == lines(src) else "ANSWER COUNT DIFFERS"
        print("%s: %s" % (os.path.relpath(out), verdict))


if __name__ == "__main__":
    main()
