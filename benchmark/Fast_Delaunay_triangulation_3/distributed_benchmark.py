#!/usr/bin/env python3
"""The distributed triangulation (fast_delaunay_3_mpi) under mpirun, ranks x threads side by side: seconds per phase
(the slowest rank's), exchange rounds, bytes sent per point, ghosts as a share of the points, peak memory per rank.
The configurations are interleaved in every round and the table gives medians; the same points (uniform in the
unit cube, fixed seed, written once as .xyz, which every rank reads in parallel, its own byte range) for all.

  distributed_benchmark.py PROGRAM [--n 1e6,1e7] [--rounds 3] [--configs 1x1,1x2,2x1,4x1] [--dir DIR]

A configuration RxT is R ranks with T threads each; ranks are not bound to cores (--bind-to none), so that a
rank's threads may spread, and more ranks than cores are allowed (the 2-core VM runs 4 ranks oversubscribed).
"""

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys


def points_file(directory, n):
    path = os.path.join(directory, "uniform_%d.xyz" % n)
    if not os.path.exists(path):
        import numpy as np
        rng = np.random.default_rng(20261202)
        with open(path + ".part", "w") as out:
            chunk = 1_000_000
            for start in range(0, n, chunk):
                block = rng.random((min(chunk, n - start), 3))
                out.write("\n".join("%.17g %.17g %.17g" % tuple(p) for p in block))
                out.write("\n")
        os.replace(path + ".part", path)
    return path


def run(program, path, ranks, threads):
    env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = ["mpirun", "-np", str(ranks), "--bind-to", "none", program, path, "--threads", str(threads), "--json"]
    out = subprocess.run(command, env=env, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("program")
    parser.add_argument("--n", default="1e6,1e7")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--configs", default="1x1,1x2,2x1,4x1")
    parser.add_argument("--dir", default="/tmp/fdt3_distributed_benchmark")
    a = parser.parse_args()
    os.makedirs(a.dir, exist_ok=True)
    configs = [tuple(int(x) for x in c.split("x")) for c in a.configs.split(",")]
    print("distributed_benchmark: %s, %d cores; medians of %d interleaved rounds; uniform points in a cube"
          % (platform.processor() or platform.machine(), os.cpu_count(), a.rounds))
    keys = ["total_s", "read_s", "partition_s", "local_s", "exchange_s", "finalize_s"]
    for n in [int(float(x)) for x in a.n.split(",")]:
        path = points_file(a.dir, n)
        runs = {c: [] for c in configs}
        for _ in range(a.rounds):
            for c in configs:
                runs[c].append(run(a.program, path, *c))
        base = {c: statistics.median(r["total_s"] for r in runs[c]) for c in configs}
        print()
        print("| n | ranks x threads | total s | read | partition | local | exchange | finalize | rounds | "
              "bytes/point | ghosts | peak GiB/rank (max) | vs 1x1 | tetrahedra |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for c in configs:
            med = {k: statistics.median(r[k] for r in runs[c]) for k in keys}
            last = runs[c][-1]
            print("| %.0e | %dx%d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %d | %.1f | %.2f%% | %.3f | %.2fx | %d |"
                  % (n, c[0], c[1], med["total_s"], med["read_s"], med["partition_s"], med["local_s"],
                     med["exchange_s"], med["finalize_s"], last["rounds"], last["bytes_per_point"],
                     100 * last["ghost_share"], statistics.median(r["peak_gib_max"] for r in runs[c]),
                     base[configs[0]] / med["total_s"], last["tetrahedra"]))
        counts = {runs[c][-1]["tetrahedra"] for c in configs}
        if len(counts) != 1:
            print("distributed_benchmark: the configurations disagree on the number of tetrahedra: %s" % counts)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
