#!/usr/bin/env python3
# Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# fast_mesh_3's three output formats read by an independent reader, meshio
# (Debian's python3-meshio): a cube with a smaller cube inside, meshed
# once per format; each file must give the same points, the 24 input
# triangles, tetrahedra of two subdomains whose volumes are 1 - 0.027 and
# 0.027.  Usage: mesher_files_read_by_meshio.py FAST_MESH_3 WORK_DIR
import os
import subprocess
import sys

import meshio
import numpy as np


def cube_off(path, lo, hi):
    points = [(hi if i & 1 else lo, hi if i & 2 else lo, hi if i & 4 else lo) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    with open(path, "w") as out:
        out.write("OFF\n8 12 0\n")
        for p in points:
            out.write("%r %r %r\n" % p)
        for a, b, c, d in quads:
            out.write("3 %d %d %d\n3 %d %d %d\n" % (a, b, c, a, c, d))


def main():
    program, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    outer, inner = os.path.join(work, "outer.off"), os.path.join(work, "inner.off")
    cube_off(outer, 0.0, 1.0)
    cube_off(inner, 0.35, 0.65)
    failures = []
    for extension, tag_key in ((".mesh", "medit:ref"), (".vtu", "subdomain"), (".msh", "gmsh:physical")):
        path = os.path.join(work, "nested" + extension)
        subprocess.run([program, outer, inner, "-o", path, "--size", "0.15", "--quiet"], check=True)
        mesh = meshio.read(path)
        tets = np.concatenate([c.data for c in mesh.cells if c.type == "tetra"])
        triangles = sum(len(c.data) for c in mesh.cells if c.type == "triangle")
        p = mesh.points[tets]
        volumes = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6
        if triangles != 24:
            failures.append("%s: %d triangles, expected 24" % (extension, triangles))
        if (volumes <= 0).any():
            failures.append("%s: %d tetrahedra with volume <= 0" % (extension, (volumes <= 0).sum()))
        if abs(volumes.sum() - 1.0) > 1e-9:
            failures.append("%s: total volume %r, expected 1" % (extension, volumes.sum()))
        if extension == ".msh":
            # Discrete entities without physical groups: the volume entity is the block.
            tags = np.concatenate([np.full(len(c.data), k) for k, c in enumerate(mesh.cells) if c.type == "tetra"])
        else:
            tags = np.concatenate([mesh.cell_data[tag_key][k] for k, c in enumerate(mesh.cells) if c.type == "tetra"])
        by_tag = sorted(volumes[tags == t].sum() for t in np.unique(tags))
        if len(by_tag) != 2 or abs(by_tag[0] - 0.027) > 1e-9 or abs(by_tag[1] - 0.973) > 1e-9:
            failures.append("%s: subdomain volumes %r, expected 0.027 and 0.973" % (extension, by_tag))
    for f in failures:
        print("FAIL", f)
    if failures:
        sys.exit(1)
    print("all three formats read back by meshio")


if __name__ == "__main__":
    main()
