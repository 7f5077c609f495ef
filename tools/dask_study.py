#!/usr/bin/env python3
"""Runs a Zeitner study binary's shards on a Dask cluster and gathers them into one table.

A study binary (for example `target/release/examples/support_study`) plans, runs and gathers a
study in a folder (see `zeitner-study`). This driver plans once here, maps `run --shard i/n`
over the cluster's workers, one single-threaded shard per task, then gathers here. The folder
must be shared by every worker (the same path on every host: NFS, a cluster file system).
A shard retried by Dask, or run again after an interruption, skips the batches it finished.

    # two local worker processes on loopback
    python3 tools/dask_study.py target/release/examples/support_study --folder F --local-workers 2 -- --grid 41
    # a running cluster (`dask scheduler`, `dask worker tcp://HOST:8786 --nworkers 8 --nthreads 1`)
    python3 tools/dask_study.py BINARY --folder F --scheduler tcp://HOST:8786 --shards 64 -- --grid 101

Arguments after `--` go to `plan` (the case source: `--grid`, `--sobol N --seed S`,
`--cases FILE`, `--batch B`). `--binary-arg` (repeatable) passes options of the binary itself
(for example `--binary-arg=--output-dir=target/zeitner`).
"""

import argparse
import subprocess
import sys
import time


def run(command):
    """Runs a command; returns its stderr, raising with it where the command failed."""
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr}{done.stdout}")
    return done.stdout + done.stderr


def run_shard(binary, folder, binary_args, index, count):
    """One task: shard `index` of `count` on one thread, where the worker runs it."""
    started = time.perf_counter()
    command = [binary, "--folder", folder, *binary_args, "run",
               "--shard", f"{index}/{count}", "--threads", "1", "--quiet"]
    text = run(command)
    return index, time.perf_counter() - started, text.strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary", help="the study binary")
    parser.add_argument("--folder", required=True, help="the study's folder, shared by every worker")
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--scheduler", help="address of a running Dask scheduler")
    where.add_argument("--local-workers", type=int, help="start a LocalCluster of this many worker processes")
    parser.add_argument("--shards", type=int, help="shards (default: 4 per worker, so that the slowest do not hold up the rest)")
    parser.add_argument("--binary-arg", action="append", default=[], help="an option of the binary itself")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    plan_args = argv[split + 1:]

    from dask.distributed import Client, LocalCluster

    print(run([args.binary, "--folder", args.folder, *args.binary_arg, "plan", *plan_args]).strip())
    if args.local_workers:
        cluster = LocalCluster(n_workers=args.local_workers, threads_per_worker=1,
                               processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        cluster = None
        client = Client(args.scheduler)
    try:
        workers = len(client.scheduler_info()["workers"])
        shards = args.shards or 4 * max(workers, 1)
        print(f"{workers} workers, {shards} shards")
        started = time.perf_counter()
        futures = [client.submit(run_shard, args.binary, args.folder, args.binary_arg, i, shards,
                                 pure=False, retries=1) for i in range(shards)]
        for index, seconds, text in client.gather(futures):
            print(f"  shard {index}: {seconds:.2f} s: {text.splitlines()[-1] if text else ''}")
        print(f"shards ran in {time.perf_counter() - started:.2f} s on the cluster")
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    print(run([args.binary, "--folder", args.folder, *args.binary_arg, "gather"]).strip())


if __name__ == "__main__":
    try:
        main()
    except RuntimeError as error:
        print(error, file=sys.stderr)
        sys.exit(1)
