#!/usr/bin/python3
"""Answer JSON Lines files on a Dask cluster, as `relpos batch FILE` would (doc/python.md, "Dask").

    PYTHONPATH=build/python /usr/bin/python3 examples/python/dask_batch.py OUT_DIR FILE... \
        [--scheduler tcp://host:8786] [--workers 2] [--evidence full|minimal]

Without --scheduler a LocalCluster of --workers processes (one thread each) answers the files.
Prints each output path and its number of answer lines.
"""

import argparse

import distributed

import relpos.distributed


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir")
    ap.add_argument("files", nargs="+")
    ap.add_argument("--scheduler", help="address of a running scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    ap.add_argument("--evidence", choices=("full", "minimal"), default="full")
    args = ap.parse_args()

    if args.scheduler:
        client = distributed.Client(args.scheduler)
    else:
        cluster = distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, dashboard_address=None)
        client = distributed.Client(cluster)
    with client:
        written = relpos.distributed.batch(args.files, args.out_dir, client=client, evidence=args.evidence)
    for path in written:
        with open(path, "rb") as f:
            print(path, sum(1 for _ in f))
    if not args.scheduler:
        cluster.close()


if __name__ == "__main__":
    main()
