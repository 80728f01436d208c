#!/usr/bin/env python3
# fast_delaunay_3_mpi as a user runs it, under mpirun with 1 and 3 ranks: the union of the ranks' --write-cells files
# is scipy's Delaunay triangulation of the points (in general position, so any exact Delaunay agrees), each cell once
# and positively oriented; an .npy input (read by rank 0, scattered) gives the same cells as the .xyz (read by every
# rank, its byte range); the .pvtu and .msh pieces hold the owned cells with global ids; a bad line and a NaN are
# reported once, with the line, and every rank exits with status 1.
#
#   fast_delaunay_3_mpi_program.py MPIEXEC PROGRAM WORK_DIRECTORY

import glob
import os
import subprocess
import sys

import numpy as np
from scipy.spatial import Delaunay

mpiexec, program, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
environment = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED:", what)


def run(ranks, *arguments):
    return subprocess.run([mpiexec, "-n", str(ranks), program, *arguments], env=environment, capture_output=True,
                          text=True, timeout=300)


def cells_written(prefix):
    files = sorted(glob.glob(prefix + ".*.txt"))
    rows = [np.loadtxt(f, dtype=np.int64, ndmin=2).reshape(-1, 4) for f in files]
    return files, np.concatenate(rows) if rows else np.zeros((0, 4), dtype=np.int64)


def canonical(cells):
    return np.unique(np.sort(cells, axis=1), axis=0)


rng = np.random.default_rng(5)
points = rng.random((4000, 3))
expected = canonical(Delaunay(points).simplices)

xyz = os.path.join(work, "points.xyz")
with open(xyz, "w") as out:
    out.write("# x y z\n")
    for i, p in enumerate(points):
        out.write("%.17g %.17g %.17g\n" % tuple(p))
        if i == 1000:
            out.write("\n")
npy = os.path.join(work, "points.npy")
np.save(npy, points)

for ranks in (1, 3):
    prefix = os.path.join(work, "cells_%d" % ranks)
    for f in glob.glob(prefix + ".*"):
        os.remove(f)
    r = run(ranks, xyz, "--write-cells", prefix)
    check(r.returncode == 0, "%d ranks: exit status %d: %s" % (ranks, r.returncode, r.stderr))
    check("4000 points on %d ranks" % ranks in r.stdout, "%d ranks: summary line: %s" % (ranks, r.stdout))
    files, cells = cells_written(prefix)
    check(len(files) == ranks, "%d ranks: %d cell files" % (ranks, len(files)))
    check(len(cells) == len(expected), "%d ranks: %d cells, scipy %d" % (ranks, len(cells), len(expected)))
    check(np.array_equal(canonical(cells), expected), "%d ranks: the cells are scipy's" % ranks)
    a, b, c, d = (points[cells[:, k]] for k in range(4))
    volumes = np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))
    check(bool(np.all(volumes > 0)), "%d ranks: every cell positively oriented" % ranks)

prefix = os.path.join(work, "cells_npy")
r = run(2, npy, "--write-cells", prefix, "--quiet")
check(r.returncode == 0 and r.stdout == "", "npy: exit status %d, output %r" % (r.returncode, r.stdout))
check(np.array_equal(canonical(cells_written(prefix)[1]), expected), "npy: the same cells as the .xyz")

pvtu = os.path.join(work, "mesh.pvtu")
r = run(3, xyz, "-o", pvtu, "--json")
check(r.returncode == 0, "pvtu: exit status %d: %s" % (r.returncode, r.stderr))
pieces = sorted(glob.glob(os.path.join(work, "mesh.*.vtu")))
check(len(pieces) == 3 and all(os.path.basename(p) in open(pvtu).read() for p in pieces), "pvtu: 3 pieces named")
try:
    import meshio
    total = 0
    for piece in pieces:
        m = meshio.read(piece)
        ids = m.point_data["global_id"].astype(np.int64)
        check(np.allclose(m.points, points[ids]), "%s: the points are those of their global ids" % piece)
        total += len(m.cells_dict["tetra"])
    check(total == len(expected), "pvtu: %d tetrahedra in the pieces, scipy %d" % (total, len(expected)))
except ImportError:
    print("meshio not found: the .vtu pieces are not read back")

msh = os.path.join(work, "mesh.msh")
r = run(2, xyz, "-o", msh, "--quiet")
check(r.returncode == 0, "msh: exit status %d: %s" % (r.returncode, r.stderr))
for piece in sorted(glob.glob(os.path.join(work, "mesh.*.msh"))):
    lines = open(piece).read().split("\n")
    nodes = lines.index("$Nodes")
    count = int(lines[nodes + 2].split()[3])
    tags = [int(t) for t in lines[nodes + 3:nodes + 3 + count]]
    coordinates = np.array([[float(x) for x in l.split()] for l in lines[nodes + 3 + count:nodes + 3 + 2 * count]])
    check(np.allclose(coordinates, points[np.array(tags) - 1]), "%s: node tags are point numbers + 1" % piece)

def points_then(name, last_line):
    path = os.path.join(work, name)
    with open(path, "w") as out:
        for p in points[:3000]:
            out.write("%.17g %.17g %.17g\n" % tuple(p))
        out.write(last_line + "\n")
    return path


r = run(3, points_then("bad.xyz", "0.5 0.5 x"))
check(r.returncode == 1, "bad line: exit status %d" % r.returncode)
check(r.stderr.count("bad.xyz:3001: 'x' is not a number") == 1, "bad line: reported once, with its line: %r" % r.stderr)

nan = points_then("nan.xyz", "0.5 nan 0.5")
r = run(2, nan)
check(r.returncode == 1, "NaN: exit status %d" % r.returncode)
check(r.stderr.count("point 3000 (on rank 1) has a coordinate that is not a finite number") == 1,
      "NaN: reported once, naming the point and its rank: %r" % r.stderr)

r = run(2, os.path.join(work, "missing.xyz"))
check(r.returncode == 1 and r.stderr.count("cannot open") == 1, "missing file: %r" % r.stderr)

print("%d checks failed" % len(failures) if failures else "all checks passed")
sys.exit(1 if failures else 0)
