"""Exact, parallel 3D Delaunay triangulations and tetrahedral meshes.

The cells are those of CGAL's ``Delaunay_triangulation_3`` (exact predicates,
CGAL's symbolic perturbation for degenerate inputs), computed by the flat-array
engine of Fast_Delaunay_triangulation_3.

    >>> import numpy as np, fast_delaunay_3
    >>> tets, neighbors = fast_delaunay_3.delaunay(np.random.default_rng(1).random((1000, 3)))

``delaunay`` and ``Triangulation`` work on numpy arrays and return index arrays
into them; ``mesh`` and ``mesh_files`` run the Delaunay-refinement mesher,
``improve_mesh`` its improvement on a mesh of your own;
``to_meshio`` hands either on to meshio (``meshio.write("out.vtu", ...)``).
"""

from ._core import Triangulation, delaunay

__all__ = ["Triangulation", "delaunay", "to_meshio"]

try:
    from ._core import improve_mesh, mesh, mesh_files

    __all__ += ["improve_mesh", "mesh", "mesh_files"]
except ImportError:  # built without TetGen: no mesher
    pass

__version__ = "0.1.0"


def to_meshio(points, tets, subdomains=None):
    """A ``meshio.Mesh`` of tetrahedra ``tets`` (indices into ``points``),
    with ``subdomains`` (one integer per tetrahedron) as the cell data
    ``"subdomain"``.  Needs meshio (Debian: python3-meshio)."""
    import numpy as np

    try:
        import meshio
    except ImportError as error:
        raise ImportError("to_meshio needs meshio (Debian: apt install python3-meshio)") from error
    points = np.asarray(points, dtype=np.float64)
    tets = np.asarray(tets)
    cell_data = {}
    if subdomains is not None:
        subdomains = np.asarray(subdomains)
        if subdomains.shape != (len(tets),):
            raise ValueError(f"subdomains must have one entry per tetrahedron ({len(tets)}), got shape {subdomains.shape}")
        cell_data["subdomain"] = [subdomains]
    return meshio.Mesh(points, [("tetra", tets)], cell_data=cell_data)


def _triangulation_to_meshio(self):
    """The finite cells as a ``meshio.Mesh`` over all the rows inserted
    (rows that name no vertex are unused points)."""
    tets, _ = self.finite_cells()
    return to_meshio(self.points, tets)


Triangulation.to_meshio = _triangulation_to_meshio
