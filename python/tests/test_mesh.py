# fast_delaunay_3.mesh(), mesh_files() and improve_mesh(): the volumes of the
# meshes against the volumes their surfaces enclose (divergence theorem), the
# boundary triangles kept, the quality measured here, and the errors of bad input.
import os

import numpy as np
import pytest

import fast_delaunay_3
from checks import signed_volumes

if not hasattr(fast_delaunay_3, "mesh"):
    pytest.skip("the module was built without TetGen: no mesher", allow_module_level=True)

# The unit cube, triangles counterclockwise seen from outside.
CUBE_POINTS = np.array([[x, y, z] for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)])
CUBE_TRIANGLES = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                           [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])


def enclosed_volume(points, triangles):
    corners = np.asarray(points)[np.asarray(triangles)]
    return np.einsum("ij,ij->i", corners[:, 0], np.cross(corners[:, 1], corners[:, 2])).sum() / 6.0


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    values = words[4:]
    points = np.array(values[:3 * nv], dtype=float).reshape(nv, 3)
    faces = np.array(values[3 * nv:3 * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    assert (faces[:, 0] == 3).all()
    return points, faces[:, 1:]


def test_the_cube_is_filled_with_positive_tetrahedra():
    points, tets, subdomains = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=0.2, threads=1)
    assert points.shape[1] == 3 and tets.shape[1] == 4 and subdomains.shape == (len(tets),)
    volumes = signed_volumes(points, tets)
    assert (volumes > 0).all()
    assert volumes.sum() == pytest.approx(1.0, rel=1e-12)
    assert set(subdomains.tolist()) == {1}
    assert len(tets) > 100  # refined to size 0.2, not the 5 or 6 tetrahedra of the corners alone
    assert ((points >= 0) & (points <= 1)).all()


def test_threads_give_a_mesh_of_the_same_volume():
    _, tets2, _ = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=0.1, threads=2)
    points, tets1, _ = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=0.1, threads=1)
    assert signed_volumes(points, tets1).sum() == pytest.approx(1.0, rel=1e-12)
    assert abs(len(tets2) - len(tets1)) < 0.2 * len(tets1)


def test_an_open_surface_raises_naming_its_triangles():
    with pytest.raises(ValueError, match="triangle"):
        fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES[:-1])


@pytest.mark.parametrize("triangles, words", [(np.array([[0, 1, 8]]), "triangle 0 has vertex index 8"),
                                              (np.array([[0, 1]]), r"\(m, 3\) integer array")])
def test_bad_triangle_arrays_raise(triangles, words):
    with pytest.raises(ValueError, match=words):
        fast_delaunay_3.mesh(CUBE_POINTS, triangles)


def test_bad_options_raise():
    with pytest.raises(ValueError, match="size must be positive"):
        fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=-1)
    with pytest.raises(ValueError, match="no file"):
        fast_delaunay_3.mesh_files([])


def test_a_remeshed_surface_gives_good_tetrahedra_where_its_large_triangles_did_not():
    as_given = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=0.1, threads=1)
    points, tets, _ = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=0.1, threads=1, remesh_surface=0.1)
    volumes = signed_volumes(points, tets)
    assert (volumes > 0).all() and volumes.sum() == pytest.approx(1.0, rel=1e-9)
    assert ((points >= -1e-12) & (points <= 1 + 1e-12)).all()
    # The twelve triangles (circumradius 0.71, 7 times the size) force flat tetrahedra along them; remeshed, none.
    assert (gamma(*as_given[:2]) < 0.3).sum() > 0
    assert (gamma(points, tets) < 0.3).sum() == 0
    for bad in (0, -1, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="remesh_surface must be a positive"):
            fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, remesh_surface=bad)
    with pytest.raises(ValueError, match="would give about"):
        fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, remesh_surface=1e-6)


def test_the_improvement_keeps_the_volume_and_removes_slivers():
    path = os.path.join(os.environ.get("FDT3_CGAL_DATA_DIR", ""), "fandisk.off")
    if not os.path.exists(path):
        pytest.skip(f"{path} is missing (apt install libcgal-demo, re-run CMake)")
    plain = fast_delaunay_3.mesh_files([path], optimize=False)
    improved = fast_delaunay_3.mesh_files([path])
    v_plain, v_improved = signed_volumes(plain[0], plain[1]), signed_volumes(improved[0], improved[1])
    assert (v_improved > 0).all()
    assert abs(v_improved.sum() - v_plain.sum()) < 1e-9 * v_plain.sum()
    # Interior Steiner points only where no flip or move helps: a handful.
    assert 0 <= len(improved[0]) - len(plain[0]) < 0.01 * len(plain[0])
    # Slivers: volume tiny against the cube of the longest edge.
    def slivers(points, tets, volumes):
        corners = points[tets]
        edges = np.max([np.linalg.norm(corners[:, i] - corners[:, j], axis=1) for i in range(4) for j in range(i)], axis=0)
        return int((volumes < 1e-3 * edges ** 3).sum())
    assert slivers(improved[0], improved[1], v_improved) < slivers(plain[0], plain[1], v_plain) / 10


def test_a_cgal_data_surface_from_its_file():
    path = os.path.join(os.environ.get("FDT3_CGAL_DATA_DIR", ""), "elephant.off")
    if not os.path.exists(path):
        pytest.skip(f"{path} is missing (apt install libcgal-demo, re-run CMake)")
    points, tets, subdomains = fast_delaunay_3.mesh_files([path], threads=2)
    volumes = signed_volumes(points, tets)
    assert (volumes > 0).all()
    surface_points, surface_triangles = read_off(path)
    assert volumes.sum() == pytest.approx(abs(enclosed_volume(surface_points, surface_triangles)), rel=1e-9)
    assert set(subdomains.tolist()) == {1}
    mesh = fast_delaunay_3.to_meshio(points, tets, subdomains)
    assert len(mesh.cells_dict["tetra"]) == len(tets)


def test_a_missing_file_raises():
    with pytest.raises(Exception, match="no_such_surface.off"):
        fast_delaunay_3.mesh_files(["/nonexistent/no_such_surface.off"])


def test_a_size_field_file_refines_and_a_bad_one_raises_naming_its_line(tmp_path):
    coarse = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES)
    field = tmp_path / "sizes.txt"
    field.write_text("# a background point at the centre\n0.5 0.5 0.5 0.1\n")
    fine = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size_field=field)
    assert len(fine[1]) > 10 * len(coarse[1])
    volumes = signed_volumes(fine[0], fine[1])
    assert (volumes > 0).all()
    assert abs(volumes.sum() - 1.0) < 1e-9
    bad = tmp_path / "bad.txt"
    bad.write_text("0.5 0.5 0.5 0.1\nsubdomain x 0.2\n")
    with pytest.raises(ValueError, match="line 2"):
        fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size_field=bad)


def gamma(points, tets):
    """3 r_in / r_circ of each tetrahedron, from its volume, facet areas and
    circumradius (|a^2 (b x c) + b^2 (c x a) + c^2 (a x b)| / 12 V)."""
    v = np.asarray(points)[np.asarray(tets)]
    a, b, c = v[:, 1] - v[:, 0], v[:, 2] - v[:, 0], v[:, 3] - v[:, 0]
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)) / 6.0
    area = sum(np.linalg.norm(np.cross(v[:, j] - v[:, i], v[:, k] - v[:, i]), axis=1) / 2
               for i, j, k in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)))
    def squared(x):
        return np.einsum("ij,ij->i", x, x)
    numerator = (squared(a)[:, None] * np.cross(b, c) + squared(b)[:, None] * np.cross(c, a)
                 + squared(c)[:, None] * np.cross(a, b))
    r_circ = np.linalg.norm(numerator, axis=1) / (12 * volume)
    return 3 * (3 * volume / area) / r_circ


def hull_facets(points, tets):
    """The facets in one tetrahedron only, by their corners' coordinates."""
    count = {}
    for t in np.asarray(tets):
        for i in range(4):
            key = tuple(sorted(np.delete(t, i).tolist()))
            count[key] = count.get(key, 0) + 1
    return {tuple(sorted(tuple(points[v]) for v in key)) for key, n in count.items() if n == 1}


def random_cube_delaunay(n, seed):
    """Delaunay tetrahedra of the cube's corners and n random points inside:
    the slivers of a Delaunay triangulation, and interior points that may move."""
    inside = np.random.default_rng(seed).uniform(0.05, 0.95, (n, 3))
    points = np.vstack([CUBE_POINTS, inside])
    tets, _ = fast_delaunay_3.delaunay(points, threads=1)
    return points, np.ascontiguousarray(tets)


def test_improve_mesh_raises_the_worst_gamma_and_keeps_the_boundary():
    points, tets = random_cube_delaunay(300, 7)
    before = gamma(points, tets)
    assert (before < 0.3).sum() > 50
    out_points, out_tets, subdomains, stats = fast_delaunay_3.improve_mesh(points, tets, threads=2)
    after = gamma(out_points, out_tets)
    assert (signed_volumes(out_points, out_tets) > 0).all()
    assert signed_volumes(out_points, out_tets).sum() == pytest.approx(1.0, rel=1e-12)
    assert set(subdomains.tolist()) == {1}
    assert hull_facets(out_points, out_tets) == hull_facets(points, tets)
    np.testing.assert_array_equal(out_points[:8], CUBE_POINTS)  # on the boundary: never moved
    assert after.min() > 5 * before.min()
    assert stats["bad_before"] == (before < 0.3).sum()
    assert stats["bad_after"] == (after < 0.3).sum() < stats["bad_before"] / 2
    assert stats["min_gamma_after"] == pytest.approx(after.min(), rel=1e-9)
    assert len(out_points) == len(points) + stats["steiner_points"]
    kept = fast_delaunay_3.improve_mesh(points, tets, add_points=False, threads=1)
    assert len(kept[0]) == len(points) and kept[3]["steiner_points"] == 0


def test_improve_mesh_keeps_the_interface_between_subdomains():
    points, tets = random_cube_delaunay(300, 8)
    centres = points[tets].mean(axis=1)
    subdomains = np.where(centres[:, 0] < 0.5, 1, 2)
    out_points, out_tets, out_subdomains, _ = fast_delaunay_3.improve_mesh(points, tets, subdomains)
    volumes = signed_volumes(out_points, out_tets)
    for s in (1, 2):
        assert volumes[out_subdomains == s].sum() == pytest.approx(
            signed_volumes(points, tets)[subdomains == s].sum(), rel=1e-12)


@pytest.mark.parametrize("change, words", [
    (lambda p, t, s: (p, t[:, [1, 0, 2, 3]], s), "not positively oriented"),
    (lambda p, t, s: (p, np.where(t == 5, len(p), t), s), "not a row of points"),
    (lambda p, t, s: (p, t, s[:-1]), "subdomain tags"),
    (lambda p, t, s: (p, t, s * 0), "subdomain 0"),
    (lambda p, t, s: (p, t[:, :3], s), r"\(m, 4\)"),
])
def test_improve_mesh_raises_naming_the_defect(change, words):
    points, tets = random_cube_delaunay(50, 9)
    bad_points, bad_tets, bad_subdomains = change(points, tets, np.ones(len(tets), dtype=np.int32))
    with pytest.raises(ValueError, match=words):
        fast_delaunay_3.improve_mesh(bad_points, bad_tets, bad_subdomains)


def test_improve_mesh_of_nothing_raises():
    with pytest.raises(ValueError, match="no tetrahedra"):
        fast_delaunay_3.improve_mesh(np.zeros((0, 3)), np.zeros((0, 4), dtype=np.int64))


def test_a_size_callable_refines_where_it_is_small_and_its_errors_arrive():
    def finer_to_the_left(x, y, z):
        return 0.04 + 0.4 * x
    points, tets, _ = fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=finer_to_the_left, threads=2)
    volumes = signed_volumes(points, tets)
    assert (volumes > 0).all()
    assert abs(volumes.sum() - 1.0) < 1e-9
    x = points[tets].mean(axis=1)[:, 0]
    assert (x < 0.25).sum() > 10 * (x > 0.75).sum()
    # The tetrahedra near x = 0.1 have edges near the size asked for there.
    corners = points[tets[(x > 0.05) & (x < 0.15)]]
    longest = np.max([np.linalg.norm(corners[:, i] - corners[:, j], axis=1) for i in range(4) for j in range(i)], axis=0)
    assert 0.5 * 0.08 < np.median(longest) < 2 * 0.08

    def broken(x, y, z):
        raise KeyError("no size here")
    with pytest.raises(RuntimeError, match="no size here"):
        fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=broken, threads=2)
    with pytest.raises(ValueError, match="not a positive finite size"):
        fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=lambda x, y, z: -1.0)
    with pytest.raises(ValueError, match="not a number"):
        fast_delaunay_3.mesh(CUBE_POINTS, CUBE_TRIANGLES, size=lambda x, y, z: "small")


def smallest_dihedral_degrees(points, tets):
    """Each tetrahedron's smallest dihedral angle, from its facets' normals."""
    p = points[tets]
    faces = [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)]  # opposite corner 0..3, outward for a positive tetrahedron
    normals = [np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a]) for a, b, c in faces]
    normals = [n / np.linalg.norm(n, axis=1)[:, None] for n in normals]
    cosines = [-(normals[i] * normals[j]).sum(axis=1) for i in range(4) for j in range(i + 1, 4)]
    return np.degrees(np.arccos(np.clip(np.max(cosines, axis=0), -1, 1)))


def test_improve_mesh_reaches_a_dihedral_target_and_refuses_one_out_of_range():
    path = os.path.join(os.environ.get("FDT3_CGAL_DATA_DIR", ""), "elephant.off")
    if not os.path.exists(path):
        pytest.skip(f"{path} is missing (apt install libcgal-demo, re-run CMake)")
    points, tets, subdomains = fast_delaunay_3.mesh_files([path], threads=1, optimize=False)
    by_gamma = fast_delaunay_3.improve_mesh(points, tets, subdomains, min_dihedral_target=0, threads=1)
    by_angle = fast_delaunay_3.improve_mesh(points, tets, subdomains, min_dihedral_target=20, threads=1)
    gamma_alone = smallest_dihedral_degrees(by_gamma[0], by_gamma[1])
    with_target = smallest_dihedral_degrees(by_angle[0], by_angle[1])
    stats = by_angle[3]
    # Under the target: a few (a Steiner point may leave some near it); the statistics count gamma.
    assert stats["bad_after"] == (gamma(by_angle[0], by_angle[1]) < 0.3).sum()
    assert stats["bad_after"] <= 3 and (with_target < 20 - 1e-9).sum() <= 3
    assert (gamma_alone < 20).sum() > 100
    assert stats["min_dihedral_after"] == pytest.approx(with_target.min(), abs=1e-6)
    for bad in (-1, 71, float("nan")):
        with pytest.raises(ValueError, match=r"min_dihedral_target must be in \[0, 70\] degrees"):
            fast_delaunay_3.improve_mesh(points, tets, subdomains, min_dihedral_target=bad)
        with pytest.raises(ValueError, match="min_dihedral_target"):
            fast_delaunay_3.mesh_files([path], min_dihedral_target=bad)
    # The mesher's own improvement takes the target too.
    meshed = fast_delaunay_3.mesh_files([path], threads=1, min_dihedral_target=20)
    assert (smallest_dihedral_degrees(meshed[0], meshed[1]) < 20 - 1e-9).sum() <= 3
