# fast_delaunay_3.delaunay(): cells against scipy.spatial.Delaunay (Qhull) on
# points in general position, against exact identities on degenerate ones
# (CGAL itself is the oracle of the C++ tests there), and its input checks.
import threading

import numpy as np
import pytest

import fast_delaunay_3
from checks import cell_set, check_neighbors, signed_volumes

scipy_spatial = pytest.importorskip("scipy.spatial")


def test_cells_are_scipys_on_points_in_general_position(rng):
    points = rng.random((3000, 3))
    tets, neighbors = fast_delaunay_3.delaunay(points, threads=1)
    assert tets.dtype == np.int32 and tets.shape[1] == 4
    assert neighbors.dtype == np.int32 and neighbors.shape == tets.shape
    assert cell_set(tets) == cell_set(scipy_spatial.Delaunay(points).simplices)


def test_cells_are_positively_oriented_and_neighbors_match(rng):
    points = rng.normal(size=(1500, 3))
    tets, neighbors = fast_delaunay_3.delaunay(points)
    assert (signed_volumes(points, tets) > 0).all()
    hull_facets = check_neighbors(tets, neighbors)
    assert hull_facets == len(scipy_spatial.ConvexHull(points).simplices)


def test_two_threads_give_the_same_cells(rng):
    # Enough points for the partitioned engine to split them.
    points = rng.random((40000, 3))
    one, _ = fast_delaunay_3.delaunay(points, threads=1)
    two, neighbors = fast_delaunay_3.delaunay(points, threads=2)
    assert cell_set(one) == cell_set(two)
    assert (signed_volumes(points, two) > 0).all()


def test_other_dtypes_and_strides_are_converted(rng):
    points = rng.random((800, 3))
    expected = cell_set(fast_delaunay_3.delaunay(points)[0])
    as_float32 = points.astype(np.float32)
    assert cell_set(fast_delaunay_3.delaunay(as_float32)[0]) == cell_set(
        scipy_spatial.Delaunay(as_float32.astype(np.float64)).simplices)
    assert cell_set(fast_delaunay_3.delaunay(np.asfortranarray(points))[0]) == expected
    wide = np.zeros((800, 6))
    wide[:, ::2] = points
    assert cell_set(fast_delaunay_3.delaunay(wide[:, ::2])[0]) == expected
    assert cell_set(fast_delaunay_3.delaunay(points.tolist())[0]) == expected
    grid = np.stack(np.meshgrid(*[np.arange(4)] * 3), axis=-1).reshape(-1, 3)
    assert len(fast_delaunay_3.delaunay(grid)[0]) == len(fast_delaunay_3.delaunay(grid.astype(float))[0])


def test_duplicates_are_named_by_their_first_row(rng):
    unique = rng.random((500, 3))
    # Rows 500.. repeat rows 0..99; then row 0 once more.
    points = np.vstack([unique, unique[:100], unique[:1]])
    tets, _ = fast_delaunay_3.delaunay(points)
    assert tets.max() < 500
    assert cell_set(tets) == cell_set(scipy_spatial.Delaunay(unique).simplices)
    # The first occurrence may come late: a shuffled order names each vertex by its earliest row.
    order = rng.permutation(len(points))
    shuffled = points[order]
    tets, _ = fast_delaunay_3.delaunay(shuffled)
    first_row = {}
    for row, p in enumerate(map(tuple, shuffled.tolist())):
        first_row.setdefault(p, row)
    assert set(np.unique(tets)) <= set(first_row.values())


def test_degenerate_grid_tiles_its_box_with_empty_spheres():
    # A cubic grid: every cube's 8 corners are cospherical, so the cells depend on the symbolic perturbation
    # (CGAL's, checked cell for cell in the C++ tests); here: they tile the box and their circumspheres are empty.
    grid = np.stack(np.meshgrid(*[np.arange(5.0)] * 3, indexing="ij"), axis=-1).reshape(-1, 3)
    tets, neighbors = fast_delaunay_3.delaunay(grid)
    volumes = signed_volumes(grid, tets)
    assert (volumes > 0).all()
    assert volumes.sum() == pytest.approx(64.0, rel=1e-12)
    check_neighbors(tets, neighbors)
    centres = fast_delaunay_3.Triangulation(grid).circumcenters()
    radius2 = ((grid[tets[:, 0]] - centres) ** 2).sum(axis=1)
    distance2 = ((grid[None, :, :] - centres[:, None, :]) ** 2).sum(axis=2)
    assert (distance2 >= radius2[:, None] - 1e-9).all()


@pytest.mark.parametrize("points", [np.zeros((0, 3)), np.eye(3), np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0],
                                                                          [1, 1, 0], [2, 3, 0.0]])])
def test_fewer_than_four_independent_points_give_no_tetrahedra(points):
    tets, neighbors = fast_delaunay_3.delaunay(points)
    assert tets.shape == (0, 4) and neighbors.shape == (0, 4)


@pytest.mark.parametrize("bad, error, words", [
    (np.array([[0.0, 0, 0], [1, np.nan, 0]]), ValueError, "row 1 has a NaN"),
    (np.array([[0.0, 0, 0], [1, 2, 3], [np.inf, 0, 0]]), ValueError, "row 2 has a infinite"),
    (np.zeros((4, 2)), ValueError, "(n, 3) array, got shape (4, 2)"),
    (np.zeros(12), ValueError, "got shape (12,)"),
    (np.array([["a", "b", "c"]]), (TypeError, ValueError), ""),
])
def test_bad_points_raise_naming_the_problem(bad, error, words):
    with pytest.raises(error) as caught:
        fast_delaunay_3.delaunay(bad)
    assert words in str(caught.value)


@pytest.mark.parametrize("threads", [0, -1, 256])
def test_bad_thread_counts_raise(threads, rng):
    with pytest.raises(ValueError, match="threads"):
        fast_delaunay_3.delaunay(rng.random((10, 3)), threads=threads)


def test_the_gil_is_released_during_the_work(rng):
    points = rng.random((200000, 3))
    counter = [0]
    running = threading.Event()
    stop = threading.Event()

    def count():
        running.set()
        while not stop.is_set():
            counter[0] += 1

    worker = threading.Thread(target=count)
    worker.start()
    running.wait()
    before = counter[0]
    tets, _ = fast_delaunay_3.delaunay(points, threads=1)
    during = counter[0] - before
    stop.set()
    worker.join()
    assert len(tets) > 0
    # With the GIL held through the insertion (about 0.3 s here) the counting thread could not run at all.
    assert during > 10000
