# Shared checks of the pytest suite: every test compares with an independent
# oracle (scipy's Qhull on points in general position, brute force, exact
# geometric identities), never with this module's own earlier output.
import numpy as np


def cell_set(tets):
    """The tetrahedra as a set of sorted vertex tuples (orientation and order dropped)."""
    return set(map(tuple, np.sort(np.asarray(tets), axis=1).tolist()))


def signed_volumes(points, tets):
    v = np.asarray(points)[np.asarray(tets)]
    return np.einsum("ij,ij->i", np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]), v[:, 3] - v[:, 0]) / 6.0


def check_neighbors(tets, neighbors):
    """neighbors[c, i] shares the facet of c opposite vertex i, and c is its neighbour back; -1 count returned."""
    tets = np.asarray(tets, dtype=np.int64)
    neighbors = np.asarray(neighbors, dtype=np.int64)
    hull = 0
    for c in range(len(tets)):
        for i in range(4):
            n = neighbors[c, i]
            if n < 0:
                hull += 1
                continue
            facet = set(tets[c]) - {tets[c, i]}
            assert facet <= set(tets[n]), f"cell {c} facet {i}: neighbour {n} does not hold it"
            assert c in neighbors[n], f"cell {n} does not name {c} back"
    return hull

