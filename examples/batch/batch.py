#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Cover floor plans and replay laser logs in parallel with Dask distributed.

    PYTHONPATH=build/python examples/batch/batch.py --plans examples/floorplans/*.json \\
        --logs ../shared/data/carmen/aces-corrected.log.gz --out results.csv

Each floor plan is covered at every --angles value (one task each) and each log is
replayed in chunks of --chunk lines (one task each); the results are gathered into one
CSV table. Without --scheduler it starts a LocalCluster of --workers processes on this
machine; with --scheduler tcp://host:8786 the same tasks run on that cluster (its workers
need `import preimage` and the files at the same paths). --serial runs the same tasks in
a plain loop first and prints the speed-up (docs/scale.md).
"""
import argparse
import csv
import gzip
import os
import sys
import time


def cover_task(plan, angle, radius):
    import preimage
    env = preimage.import_plan(plan, "houseexpo").environment
    t = time.perf_counter()
    r = preimage.cover(env, radius=radius, angle=angle)
    return {"kind": "cover", "input": os.path.basename(plan), "part": angle, "items": len(r["path"]),
            "length": round(r["length"], 3), "covered": round(r["covered_fraction"], 5), "seconds": round(time.perf_counter() - t, 3)}


def replay_task(log, first, lines):
    import preimage
    t = time.perf_counter()
    scans = detected = 0
    sde_sum = 0.0
    with (gzip.open(log, "rt") if log.endswith(".gz") else open(log)) as f:
        for k, line in enumerate(f):
            if k < first:
                continue
            if k >= first + lines:
                break
            r = preimage.replay_line(line, where=f"{log}:{k + 1}")
            if r is None:
                continue
            scans += 1
            detected += r["target_rule"] == "detected"
            sde_sum += r["sde"] or 0.0
    return {"kind": "replay", "input": os.path.basename(log), "part": first, "items": scans, "length": round(sde_sum, 3),
            "covered": detected, "seconds": round(time.perf_counter() - t, 3)}


def count_lines(log):
    with (gzip.open(log, "rt") if log.endswith(".gz") else open(log)) as f:
        return sum(1 for _ in f)


def tasks(args):
    out = [(cover_task, (p, a, args.radius)) for p in args.plans for a in args.angles]
    for log in args.logs:
        n = count_lines(log)
        out += [(replay_task, (log, first, args.chunk)) for first in range(0, n, args.chunk)]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--plans", nargs="*", default=[], help="HouseExpo floor plans to cover")
    ap.add_argument("--logs", nargs="*", default=[], help="CARMEN or text laser logs to replay")
    ap.add_argument("--angles", nargs="*", type=float, default=[0, 45, 90, 135], help="sweep angles, one task each")
    ap.add_argument("--radius", type=float, default=0.2, help="robot radius, m")
    ap.add_argument("--chunk", type=int, default=500, help="log lines per replay task")
    ap.add_argument("--workers", type=int, default=os.cpu_count(), help="LocalCluster worker processes")
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    ap.add_argument("--serial", action="store_true", help="also run the tasks in a plain loop and print the speed-up")
    ap.add_argument("--out", default="batch.csv", help="CSV table of the results")
    args = ap.parse_args()
    work = tasks(args)
    if not work:
        sys.exit("batch.py: nothing to do (give --plans and/or --logs)")

    serial_s = None
    if args.serial:
        t = time.perf_counter()
        serial = [f(*a) for f, a in work]
        serial_s = time.perf_counter() - t

    from dask.distributed import Client, LocalCluster
    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    try:
        client.run(lambda: __import__("preimage"))  # fail early if a worker cannot import the module
        t = time.perf_counter()
        rows = client.gather([client.submit(f, *a, pure=False) for f, a in work])
        parallel_s = time.perf_counter() - t
    finally:
        client.close()
        if cluster:
            cluster.close()

    if serial_s is not None and [{k: v for k, v in r.items() if k != "seconds"} for r in rows] != \
            [{k: v for k, v in r.items() if k != "seconds"} for r in serial]:
        sys.exit("batch.py: the parallel results differ from the serial ones")
    with open(args.out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print(f"{len(rows)} tasks on {args.scheduler or f'a LocalCluster of {args.workers} workers'}: {parallel_s:.2f} s; wrote {args.out}")
    if serial_s is not None:
        print(f"serial loop: {serial_s:.2f} s; speed-up {serial_s / parallel_s:.2f}x (results identical)")


if __name__ == "__main__":
    main()
