#!/usr/bin/env python3
# Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The fast_delaunay_3 program on a small generated point cloud: exit status
# 0 and the output written for every output format; an unreadable input and
# an unknown output extension give exit status 1 and 2 lines naming them.
# With meshio (Debian's python3-meshio) the .vtu is read back with the
# number of tetrahedra the program reports, all positively oriented, their
# volume the hull's (scipy's ConvexHull, when scipy imports).
# Usage: fast_delaunay_3_program.py FAST_DELAUNAY_3 WORK_DIR
import os
import random
import re
import subprocess
import sys


def main():
    program, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    rng = random.Random(7)
    points = [(rng.random(), rng.random(), rng.random()) for _ in range(2000)]
    cloud = os.path.join(work, "cloud.xyz")
    with open(cloud, "w") as out:
        out.write("# x y z nx ny nz\n")
        for p in points:
            out.write("%r %r %r 0 0 1\n" % p)
    failures = []
    reported = None
    for extension in (".vtu", ".mesh", ".msh", ".off", ".cgal"):
        path = os.path.join(work, "cloud" + extension)
        if os.path.exists(path):
            os.remove(path)
        run = subprocess.run([program, cloud, "-o", path, "--threads", "2"], capture_output=True, text=True)
        if run.returncode != 0:
            failures.append("%s: exit status %d, %s" % (extension, run.returncode, run.stderr.strip()))
        elif not os.path.getsize(path):
            failures.append("%s: no output" % extension)
        summary = re.search(r"(\d+) points read, (\d+) duplicates, (\d+) vertices, (\d+) finite tetrahedra",
                            run.stdout)
        if not summary or summary.group(1) != "2000":
            failures.append("%s: no summary line with 2000 points read in %r" % (extension, run.stdout))
        elif extension == ".vtu":
            reported = int(summary.group(4))
    quiet = subprocess.run([program, cloud, "-o", os.path.join(work, "q.vtu"), "--quiet"], capture_output=True,
                           text=True)
    if quiet.returncode != 0 or quiet.stdout or quiet.stderr:
        failures.append("--quiet printed %r %r" % (quiet.stdout, quiet.stderr))
    bad = os.path.join(work, "bad.xyz")
    with open(bad, "w") as out:
        out.write("1 2 3\n4 5\n")
    run = subprocess.run([program, bad, "-o", os.path.join(work, "bad.vtu")], capture_output=True, text=True)
    if run.returncode != 1 or "line 2: 2 columns" not in run.stderr:
        failures.append("bad input: exit status %d, %r" % (run.returncode, run.stderr))
    run = subprocess.run([program, cloud, "-o", os.path.join(work, "cloud.vtk")], capture_output=True, text=True)
    if run.returncode != 1 or "unknown output format" not in run.stderr:
        failures.append("unknown extension: exit status %d, %r" % (run.returncode, run.stderr))

    try:
        import meshio
        import numpy as np
    except ImportError:
        meshio = None
    if meshio is not None and reported is not None:
        mesh = meshio.read(os.path.join(work, "cloud.vtu"))
        tets = np.concatenate([c.data for c in mesh.cells if c.type == "tetra"])
        if len(tets) != reported:
            failures.append("meshio reads %d tetrahedra, the program reported %d" % (len(tets), reported))
        p = mesh.points[tets]
        volumes = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6
        if (volumes <= 0).any():
            failures.append("%d tetrahedra with volume <= 0" % (volumes <= 0).sum())
        try:
            from scipy.spatial import ConvexHull
            hull = ConvexHull(np.array(points)).volume
            if abs(volumes.sum() - hull) > 1e-9:
                failures.append("volume %r, the hull's is %r" % (volumes.sum(), hull))
        except ImportError:
            pass
    for f in failures:
        print("FAIL", f)
    if failures:
        sys.exit(1)
    print("fast_delaunay_3 wrote all five formats" + ("; meshio read the .vtu back" if meshio else ""))


if __name__ == "__main__":
    main()
