# fast_delaunay_3.Triangulation: insertion in batches, removal, moves, queries,
# exports and pickling, each against scipy (Qhull, cKDTree) on points in
# general position or an exact identity.
import pickle

import numpy as np
import pytest

import fast_delaunay_3
from checks import cell_set, check_neighbors, signed_volumes

scipy_spatial = pytest.importorskip("scipy.spatial")


def scipy_cells_of_rows(points, rows):
    """scipy's cells of points[rows], as rows."""
    rows = np.asarray(rows)
    return cell_set(rows[scipy_spatial.Delaunay(points[rows]).simplices])


def test_batches_name_rows_in_order_and_give_the_cells_of_all(rng):
    points = rng.random((2000, 3))
    t = fast_delaunay_3.Triangulation(points[:700], threads=1)
    named = t.insert(points[700:])
    assert named.tolist() == list(range(700, 2000))
    assert t.number_of_vertices == 2000 and t.dimension == 3
    assert cell_set(t.finite_cells()[0]) == cell_set(scipy_spatial.Delaunay(points).simplices)
    assert np.array_equal(t.points, points)
    assert np.array_equal(t.vertices, np.arange(2000))


def test_a_duplicate_row_names_the_older_vertex(rng):
    points = rng.random((100, 3))
    t = fast_delaunay_3.Triangulation(points)
    assert t.insert(points[[5, 7, 5]]).tolist() == [5, 7, 5]
    assert t.number_of_vertices == 100 and len(t.points) == 103


def test_remove_gives_the_cells_of_the_rest(rng):
    points = rng.random((1500, 3))
    t = fast_delaunay_3.Triangulation(points)
    removed = rng.choice(1500, size=300, replace=False)
    t.remove(removed)
    kept = np.setdiff1d(np.arange(1500), removed)
    assert t.number_of_vertices == 1200 and t.is_valid()
    assert np.array_equal(t.vertices, kept)
    assert cell_set(t.finite_cells()[0]) == scipy_cells_of_rows(points, kept)


@pytest.mark.parametrize("indices, words", [([3, 1500], "index 1500 (position 1) names no vertex"),
                                            ([-1], "index -1"),
                                            ([4, 9, 4], "index 4 is given twice")])
def test_bad_removals_raise_and_change_nothing(indices, words, rng):
    points = rng.random((1500, 3))
    t = fast_delaunay_3.Triangulation(points)
    before = t.finite_cells()[0].copy()
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
        t.remove(indices)
    assert t.number_of_vertices == 1500
    assert np.array_equal(t.finite_cells()[0], before)
    t.remove([10])
    with pytest.raises(ValueError, match="index 10"):
        t.remove([10])


def test_move_gives_the_cells_of_the_moved_points(rng):
    points = rng.random((1000, 3))
    t = fast_delaunay_3.Triangulation(points)
    moved = rng.choice(1000, size=100, replace=False)
    targets = rng.random((100, 3))
    assert t.move(moved, targets).tolist() == moved.tolist()
    points[moved] = targets
    assert np.array_equal(t.points, points)
    assert cell_set(t.finite_cells()[0]) == cell_set(scipy_spatial.Delaunay(points).simplices)
    assert t.is_valid()


def test_a_move_onto_a_vertex_merges_into_it(rng):
    points = rng.random((200, 3))
    t = fast_delaunay_3.Triangulation(points)
    assert t.move([3], points[[8]]).tolist() == [8]
    assert t.number_of_vertices == 199 and 3 not in t.vertices
    with pytest.raises(ValueError, match="3 indices but 2 points"):
        t.move([1, 2, 4], points[:2])
    with pytest.raises(ValueError, match="row 0 has a NaN"):
        t.move([1], [[np.nan, 0, 0]])
    assert t.number_of_vertices == 199


def test_locate_finds_the_cell_holding_each_query(rng):
    points = rng.random((2000, 3))
    t = fast_delaunay_3.Triangulation(points)
    tets, _ = t.finite_cells()
    queries = np.vstack([0.05 + 0.9 * rng.random((500, 3)), [[2.0, 2, 2], [-1, 0.5, 0.5]]])
    cells = t.locate(queries)
    assert (cells[-2:] == -1).all() and (cells[:-2] >= 0).all()
    # Barycentric coordinates of each query in its cell are all >= 0.
    v = points[tets[cells[:-2]]]
    for q, corners in zip(queries[:-2], v):
        weights = np.linalg.solve(np.vstack([corners.T, np.ones(4)]), np.append(q, 1.0))
        assert (weights >= -1e-12).all()
    found = scipy_spatial.Delaunay(points).find_simplex(queries[:-2])
    assert cell_set(tets[cells[:-2]]) == cell_set(scipy_spatial.Delaunay(points).simplices[found])


def test_nearest_vertex_is_the_brute_force_one(rng):
    points = rng.random((3000, 3))
    t = fast_delaunay_3.Triangulation(points)
    queries = rng.random((400, 3)) * 1.4 - 0.2
    expected = scipy_spatial.cKDTree(points).query(queries)[1]
    assert np.array_equal(t.nearest_vertex(queries), expected)
    with pytest.raises(ValueError, match="no vertex"):
        fast_delaunay_3.Triangulation().nearest_vertex(queries)


def test_hull_facets_are_qhulls_and_face_outwards(rng):
    points = rng.normal(size=(1000, 3))
    t = fast_delaunay_3.Triangulation(points)
    facets = t.hull_facets()
    assert cell_set(facets) == cell_set(scipy_spatial.ConvexHull(points).simplices)
    corners = points[facets]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    assert (np.einsum("ij,ij->i", normals, corners.mean(axis=1) - points.mean(axis=0)) > 0).all()


def test_circumcenters_and_voronoi(rng):
    points = rng.random((800, 3))
    t = fast_delaunay_3.Triangulation(points)
    tets, neighbors = t.finite_cells()
    centres = t.circumcenters()
    distances = np.linalg.norm(points[tets] - centres[:, None, :], axis=2)
    assert np.allclose(distances, distances[:, :1], rtol=1e-9)
    vertices, adjacency = t.voronoi()
    assert np.array_equal(vertices, centres) and np.array_equal(adjacency, neighbors)
    check_neighbors(tets, adjacency)
    # scipy's Voronoi vertices are the same circumcentres (points in general position).
    ours = np.unique(np.round(centres, 8), axis=0)
    theirs = np.unique(np.round(scipy_spatial.Voronoi(points).vertices, 8), axis=0)
    assert ours.shape == theirs.shape and np.allclose(ours, theirs, atol=1e-7)


def test_pickling_keeps_rows_vertices_and_cells(rng):
    points = rng.random((1000, 3))
    t = fast_delaunay_3.Triangulation(points, threads=2)
    t.remove([1, 2, 3])
    t.insert(points[:5])  # duplicates of rows 0 and 4, new vertices for the removed 1, 2, 3
    copy = pickle.loads(pickle.dumps(t))
    assert copy.threads == 2 and copy.is_valid()
    assert np.array_equal(copy.points, t.points) and np.array_equal(copy.vertices, t.vertices)
    assert cell_set(copy.finite_cells()[0]) == cell_set(t.finite_cells()[0])
    with pytest.raises(ValueError, match="pickled state"):
        fast_delaunay_3.Triangulation.__new__(fast_delaunay_3.Triangulation).__setstate__(
            (points, np.array([3, 2]), 1))


def test_to_meshio_writes_a_file_meshio_reads_back(rng, tmp_path):
    meshio = pytest.importorskip("meshio")
    points = rng.random((500, 3))
    t = fast_delaunay_3.Triangulation(points)
    path = tmp_path / "cells.vtu"
    meshio.write(path, t.to_meshio())
    back = meshio.read(path)
    assert len(back.cells_dict["tetra"]) == t.number_of_finite_cells
    tets, _ = fast_delaunay_3.delaunay(points)
    with_domains = fast_delaunay_3.to_meshio(points, tets, np.ones(len(tets), dtype=int))
    assert with_domains.cell_data["subdomain"][0].shape == (len(tets),)
    with pytest.raises(ValueError, match="one entry per tetrahedron"):
        fast_delaunay_3.to_meshio(points, tets, [1, 2])
    assert (signed_volumes(back.points, back.cells_dict["tetra"]) > 0).all()
