
namespace CGAL {

/*!
\ingroup PkgFastDelaunayTriangulation3TriangulationClasses

The class `Fast_Delaunay_triangulation_3` represents the Delaunay
triangulation of a set of points in \f$ \mathbb{R}^3 \f$, with the interface
of `Delaunay_triangulation_3` for building a triangulation by insertion and
reading it.

For any input without NaN or infinite coordinates, its finite cells are
exactly those of `Delaunay_triangulation_3<Gt>` on the same points, as sets
of four points: both evaluate the predicates exactly and both break
cospherical and coplanar ties with the same symbolic perturbation (the
lexicographic order of the points), so the triangulation is unique and does
not depend on the insertion order. A point given several times is stored
once.

The triangulation is stored in flat arrays (one record per vertex, four vertex
ids, four neighbour codes and a flag byte per tetrahedron) and points are
inserted with the algorithm of Marot, Pellerin and Remacle (2019): a BRIO
order sorted along a Moore curve, then a visibility walk, a cavity search and
a Delaunay ball per point. See the user manual,
Chapter \ref Chapter_Fast_Delaunay_triangulation_3.

\tparam Gt is the geometric traits class, a CGAL kernel:
`Exact_predicates_inexact_constructions_kernel` (the default),
`Exact_predicates_exact_constructions_kernel`, `Simple_cartesian<double>`, ...
It supplies the types `Point_3`, `Segment_3`, `Triangle_3` and
`Tetrahedron_3` and the constructions (`dual()`, `tetrahedron()`, ...).
Insertion runs on the points' double coordinates with the package's own
filtered predicates, whose exact stage is
`Exact_predicates_inexact_constructions_kernel`'s: on points with double
coordinates they decide exactly what any kernel's exact predicates decide.
When `FT` is not `double`, the points inserted are kept, one `Point_3` per
vertex, so `v->point()` is the object inserted (`==` holds, and for EPEC it
is the same lazy value), and an inserted point must have coordinates that
are doubles exactly (see the differences below). In dimension 3 a query at a
point whose coordinates are not doubles (an EPEC circumcenter, a barycenter)
is answered exactly with `Gt`'s own predicates on the kernel points and the
same perturbation: `locate()`, `side_of_cell()`, `side_of_sphere()`,
`side_of_circle()`, `nearest_vertex()`, `is_vertex()`, `find_conflicts()`,
`vertices_on_conflict_zone_boundary()` and the segment traverser between two
points. Below dimension 3 `locate()` (so `is_vertex()`) and
`nearest_vertex()` answer such points exactly too, with the same `lt`, `li`,
`lj` as CGAL (the cell is none outside the affine hull).

\tparam Tds_ is accepted so that the class can be named with the template
arguments of `Delaunay_triangulation_3`; the combinatorics always live in
the package's flat arrays, and only its vertex and cell bases are read: an
info (`Triangulation_vertex_base_with_info_3`,
`Triangulation_cell_base_with_info_3`), a user vertex base with members of its
own, and the concurrency tag. Default: `Default`.

\tparam Location_policy is accepted and ignored (insertion always walks from
the last inserted point or the hint): `Fast_location` or `Compact_location`,
given third or, as in `Delaunay_triangulation_3<K, Fast_location>`, second;
the typedef `Location_policy` names it. Default: `Default`.

\tparam Lock_data_structure_ is accepted, and the typedef
`Lock_data_structure` is CGAL's: with a `Parallel_tag` data structure (and
TBB), `Spatial_lock_grid_3<Tag_priority_blocking>` when the argument is
`Default`, otherwise `void` when `Default`; the argument when given. The
constructors and `set_lock_data_structure()` store a pointer to it, which
`get_lock_data_structure()` returns; nothing is locked (the parallel engine
partitions space instead). Default: `Default`.

<b>Differences from `Delaunay_triangulation_3`</b>

- A user vertex or cell base with members of its own (CGAL's `Rebind_TDS`
  protocol) works, one object per vertex or cell kept beside the flat arrays;
  what CGAL's own bases provide (`point()`, `cell()`, `vertex()`,
  `neighbor()`, `index()`, `info()`, `is_valid()`, `circumcenter()`) is the
  triangulation's, and the setters (`set_point()`, `set_cell()`,
  `set_vertex()`, `set_neighbor()`, ...) are deleted. A cell's base is reset
  when an insertion replaces the cell, as CGAL's cells are new.
- `remove(first, last)` and `remove_cluster()` remove the vertices on the
  threads of the caller's TBB arena with a `Parallel_tag` data structure in
  dimension 3 (as CGAL 5.5 does), one by one otherwise; `move()` and
  `move_if_no_collision()` keep the vertex's handle and info, change only
  its point when its cells stay Delaunay, and keep the cells without the
  vertex that stay in the triangulation, with their infos. The
  triangulations are CGAL's.
- `is_delaunay_after_displacement()` also checks the facets opposite the
  vertex, which CGAL 5.5's test leaves out, and throws
  `std::invalid_argument` below dimension 3 (CGAL's precondition).
- `Simplex` (CGAL's `Triangulation_simplex_3`) is provided; its order sorts
  by dimension then by handles (CGAL's by addresses) and `operator<<` prints
  vertex indices. The segment traverser is provided for two points
  (`segment_traverser_cells_begin(p, q, hint)`, `segment_traverser_cells_end()`,
  `segment_traverser_cell_handles(p, q, hint)`, `segment_traverser_simplices_begin(p, q, hint)`,
  `segment_traverser_simplices_end()`, `segment_traverser_simplices(p, q, hint)`) and for two
  vertices, in dimension 3 (the cells between two points also in dimension 2); it gives CGAL's cells and simplices when the segment meets no
  vertex or edge (but its ends), and otherwise the faces the segment meets (CGAL 5.5's sequence
  there depends on its storage; the user manual says how it differs). A segment that starts
  outside the convex hull is walked as CGAL walks it, from the infinite cell of `locate(p)`
  through infinite cells into the hull; in dimension 2 CGAL's cell traverser between two points
  answers (CGAL 5.5's simplex traverser and its walk from a vertex are broken there).
- Point location, the conflict zone, the incident / adjacent queries and
  the circulators, the Voronoi duals and `is_Gabriel()` are provided in
  dimension 3 (the manual lists them); stream operators read and write
  CGAL's file format.
- Below dimension 3 the cells, counts and iterators are those of
  `Delaunay_triangulation_3` (Section
  \ref Fast_Delaunay_triangulation_3DegenerateDimensions of the manual), but
  the iteration order is that of the slots; the queries CGAL defines there
  are answered by a `Delaunay_triangulation_3` kept beside the arrays. Even
  the empty triangulation has its infinite cell, as in CGAL.
- Handles are a pair (pointer to the triangulation's data, index in the flat
  arrays), and iterators hold such a pair. The data lives on the heap and
  changes hands with `swap()` and the moves, so handles and iterators follow
  it, as those of `Delaunay_triangulation_3` do; a copy has handles of its
  own. Vertex handles stay valid across insertions. A cell handle taken
  before an insertion may name a different cell afterwards, because the
  slots of deleted cells are reused.
- `Vertex::point()` returns the point by value, except for a user vertex
  base (a `Tds` whose vertex base has members of its own, such as
  `Alpha_shape_vertex_base_3`), whose vertex holds a copy of its point and
  returns a reference to it, valid until the vertex moves or the
  triangulation changes; the point of the infinite vertex is `Point(0, 0, 0)`.
  A vertex's point changes through `move()`: `v->point() = p` does not
  compile, and on a vertex object that is not `const`, `v.point() = p` (or
  `v.set_point(p)` for a user base) throws `std::logic_error`, except during
  `tds().copy_tds()`, where the conversion functor sets the copy's points.
- All iterators are bidirectional, as those of `Delaunay_triangulation_3`.
  As there, `Cell_iterator` (`All_cells_iterator`) is `Cell_handle` and
  `Vertex_iterator` (`All_vertices_iterator`) is `Vertex_handle`; the finite
  iterators are other types that convert to handles. CGAL's
  `Unique_hash_map` works on the handles (hashed by index).
  The cell and vertex iterators dereference to a `Vertex` or `Cell` object
  stored inside the iterator, so `&*it` is valid only as long as `it` is
  unchanged, and a `std::reverse_iterator` over them would hand out a
  reference into a temporary copy: walk backwards with `--` (CGAL's facet and
  edge iterators store their `Facet` and `Edge` the same way). A
  `Point_iterator` yields points by value.
- `tds()` returns a view over the flat arrays with the interface of
  `Triangulation_data_structure_3` (counts, raw iterators, adjacency,
  `create_vertex()`, combinatorial `is_valid()`, 2-3 and 3-2 flips,
  `copy_tds()` of another data structure, checked to be a Delaunay
  triangulation of points that are doubles; see the user manual), not a
  `Triangulation_data_structure_3`: the members that build or rewire cells
  one by one (`create_cell`, `set_adjacency`) are not provided.
  `set_infinite_vertex(v)` accepts only the infinite vertex (which
  `copy_tds()` returns) and throws `std::invalid_argument` otherwise.
- Finite vertices are enumerated in the order of the vertex ids, which is the
  insertion order chosen by the spatial sort, not the order of the input.
- A point with a NaN or infinite coordinate makes `insert()` throw
  `std::invalid_argument` and leaves the triangulation unchanged.
- With a kernel whose `FT` is not `double` (EPEC), a point whose coordinates
  are not all doubles exactly (say \f$ x = 1/3 \f$) cannot be inserted, as the
  engine works on doubles: `insert()` throws `std::invalid_argument` naming
  the point's position in the input and saying "coordinates not
  representable as doubles", and the triangulation is unchanged (nothing of
  a range is inserted). The same holds for `insert_in_hole()`, and below
  dimension 3 for the queries other than `locate()`, `is_vertex()` and
  `nearest_vertex()` (CGAL's triangulation of the vertices' doubles answers
  there).
  `Delaunay_triangulation_3<Epeck>` accepts such points. A point made by a
  construction whose value is a double (\f$ (1/3) \cdot 3 \f$) is accepted.
- At most \f$ 2^{32} - 2 \f$ vertices (`std::length_error` beyond).
- `v->cell()` builds, on its first call after an insertion, a table of one
  incident cell per vertex (a pass over all cells); `infinite_cell()` scans
  the cells. Neither may be called concurrently from several threads.

As `Delaunay_triangulation_3` derives from `Triangulation_3`, this class
derives from its triangulation layer (types, handles, iterators, access,
point location, adjacency, the segment traverser),
`Fast_Delaunay_triangulation_3_layers::Flat_triangulation_3`, named `Tr_Base`
as CGAL names the base of `Delaunay_triangulation_3`; it is not built on its
own, and its members are documented here as the class's own. The user
manual's Software Design section draws the layers.

\sa `CGAL::Delaunay_triangulation_3`
*/
template <class Gt = Exact_predicates_inexact_constructions_kernel, class Tds_ = Default,
          class Location_policy = Default, class Lock_data_structure_ = Default>
class Fast_Delaunay_triangulation_3
{
public:

/// \name Types
/// @{

/*!
The geometric traits class.
*/
typedef Gt Geom_traits;

/*!
*/
typedef typename Gt::Point_3 Point;

/*!
*/
typedef typename Gt::Segment_3 Segment;

/*!
*/
typedef typename Gt::Triangle_3 Triangle;

/*!
*/
typedef typename Gt::Tetrahedron_3 Tetrahedron;

/*!
*/
typedef std::size_t size_type;

/*!
*/
typedef std::ptrdiff_t difference_type;

/*!
A vertex, as seen through the triangulation: the value type of the vertex
iterators and the object a `Vertex_handle` points to. Its members are
`Point point() const`, `Cell_handle cell() const` (an incident cell, or a null
handle in dimension -1) and `bool is_valid(bool = false, int = 0) const`.
With a user vertex base (see the manual), `Vertex` derives from that base
rebound to this class's handles, so its members are members of `Vertex`.
Likewise `Cell` with a user cell base; `Cell` also has `Point circumcenter()
const` (dimension 3, finite cell).
*/
typedef unspecified_type Vertex;

/*!
A cell (tetrahedron), as seen through the triangulation: the value type of
the cell iterators and the object a `Cell_handle` points to. Its members are
those of `TriangulationCellBase_3` that read the combinatorics:
`Vertex_handle vertex(int i)`, `Cell_handle neighbor(int i)`,
`int index(Vertex_handle v)`, `int index(Cell_handle c)`,
`bool has_vertex(Vertex_handle v)`, `bool has_vertex(Vertex_handle v, int& i)`,
`bool has_neighbor(Cell_handle c)`, `bool has_neighbor(Cell_handle c, int& i)`
and `bool is_valid(bool = false, int = 0)` (true for a cell that exists), all
`const`. `index()` has the precondition that the vertex (neighbour) belongs to
the cell.
*/
typedef unspecified_type Cell;

/*!
Handle to a vertex. Default constructible (null), constructible from
`nullptr`, comparable with `==`, `!=` and with `nullptr`, totally ordered
(`<`, `>`, `<=`, `>=`), hashable with `std::hash` and `boost::hash`
(`hash_value()`), and explicitly convertible to `bool`, so it works as a key
of `std::map`, `std::set` and `std::unordered_map`.
*/
typedef unspecified_type Vertex_handle;

/*!
Handle to a cell, with the same properties as `Vertex_handle`.
*/
typedef unspecified_type Cell_handle;

/*!
Facet `i` of cell `c`: the facet opposite to `c->vertex(i)`.
*/
typedef std::pair<Cell_handle, int> Facet;

/*!
Edge `(i, j)` of cell `c`: the edge between `c->vertex(i)` and `c->vertex(j)`.
*/
typedef Triple<Cell_handle, int, int> Edge;

/*!
`Tag_false`, as in `Delaunay_triangulation_3`: the points are not weighted.
*/
typedef Tag_false Weighted_tag;

/*!
`Tag_false`, as in `Delaunay_triangulation_3`: the triangulation is not periodic.
*/
typedef Tag_false Periodic_tag;

/*!
The type of the lock data structure, as CGAL chooses it (see the template
parameter `Lock_data_structure_`).
*/
typedef unspecified_type Lock_data_structure;

/*!
The enum of `Triangulation_3`, with its meaning there (`locate()`).
*/
enum Locate_type { VERTEX = 0, EDGE, FACET, CELL, OUTSIDE_CONVEX_HULL, OUTSIDE_AFFINE_HULL };

/*!
Timings and counters of the last call to `insert()`; see
Section \ref Fast_Delaunay_triangulation_3Options of the manual. Fields:
`points` (the size of the inserted range), `sort_seconds`, `init_seconds`,
`insertion_seconds`, `finish_seconds`, and `kernel`, whose fields are the
counters `inserted`, `duplicates`, `walk_steps`, `cavity_tets`, `ball_tets`,
`conflict_tests`, `small_cavities`, `large_cavities` and, when phase timing is
on, `walk_seconds`, `cavity_seconds`, `ball_seconds`; and `rounds`, one row per
attempt of a parallel insertion (the paper's Table 2; empty when sequential):
`points`, `inserted`, `partitions`, `mesh_vertices`, `retried` (cavities
searched again, barrier engine), `plane_cut` (the partitions cut by median
planes instead of the curve) and `seconds`.
*/
typedef unspecified_type Insertion_report;

/// @}

/// \name Iterators and Ranges
/// All iterators are bidirectional, as CGAL's. The cell and vertex iterators
/// dereference to `Cell` and `Vertex` and convert to `Cell_handle` and
/// `Vertex_handle`; the facet and edge iterators dereference to `Facet` and
/// `Edge`; the `*_handles_iterator` types dereference to handles.
/// The ranges are `Iterator_range`s of the corresponding iterators.
/// @{

/*!
All cells, finite and infinite: `Cell_handle`, as in CGAL.
*/
typedef Cell_handle All_cells_iterator;

/*!
*/
typedef unspecified_type Finite_cells_iterator;

/*!
Same as `All_cells_iterator`.
*/
typedef All_cells_iterator Cell_iterator;

/*!
All vertices: the infinite vertex first, then the finite vertices.
`Vertex_handle`, as in CGAL.
*/
typedef Vertex_handle All_vertices_iterator;

/*!
*/
typedef unspecified_type Finite_vertices_iterator;

/*!
Same as `All_vertices_iterator`.
*/
typedef All_vertices_iterator Vertex_iterator;

/*!
All facets; each one is reported once, from the cell of smaller index among
its two cells.
*/
typedef unspecified_type All_facets_iterator;

/*!
Facets that do not contain the infinite vertex. A facet on the convex hull
may be reported from its infinite cell, as `(c, 3)`.
*/
typedef unspecified_type Finite_facets_iterator;

/*!
Same as `All_facets_iterator`.
*/
typedef All_facets_iterator Facet_iterator;

/*!
All edges; each one is reported once, from the cell of smallest index
around it.
*/
typedef unspecified_type All_edges_iterator;

/*!
Edges that do not contain the infinite vertex.
*/
typedef unspecified_type Finite_edges_iterator;

/*!
Same as `All_edges_iterator`.
*/
typedef All_edges_iterator Edge_iterator;

/*!
*/
typedef unspecified_type All_cell_handles_iterator;

/*!
*/
typedef unspecified_type Finite_cell_handles_iterator;

/*!
*/
typedef unspecified_type All_vertex_handles_iterator;

/*!
*/
typedef unspecified_type Finite_vertex_handles_iterator;

/*!
*/
typedef Iterator_range<All_cells_iterator> All_cells;

/*!
*/
typedef Iterator_range<Finite_cells_iterator> Finite_cells;

/*!
*/
typedef Iterator_range<All_vertices_iterator> All_vertices;

/*!
*/
typedef Iterator_range<Finite_vertices_iterator> Finite_vertices;

/*!
*/
typedef Iterator_range<All_facets_iterator> All_facets;

/*!
*/
typedef Iterator_range<Finite_facets_iterator> Finite_facets;

/*!
*/
typedef Iterator_range<All_edges_iterator> All_edges;

/*!
*/
typedef Iterator_range<Finite_edges_iterator> Finite_edges;

/*!
*/
typedef Iterator_range<All_cell_handles_iterator> All_cell_handles;

/*!
*/
typedef Iterator_range<Finite_cell_handles_iterator> Finite_cell_handles;

/*!
*/
typedef Iterator_range<All_vertex_handles_iterator> All_vertex_handles;

/*!
*/
typedef Iterator_range<Finite_vertex_handles_iterator> Finite_vertex_handles;

/*!
The points of the finite vertices, in their order, as `Triangulation_3`'s
`Point_iterator`; bidirectional, its `operator*` returns the point by value.
*/
typedef unspecified_type Point_iterator;

/*!
*/
typedef Iterator_range<Point_iterator> Points;

/// @}

/// \name Creation
/// @{

/*!
Creates an empty triangulation (dimension -1) that stores `gt`.
*/
explicit Fast_Delaunay_triangulation_3(const Geom_traits& gt = Geom_traits());

/*!
Equivalent to constructing an empty triangulation and calling
`insert(first, last)`.
\tparam InputIterator an input iterator with value type `Point`.
*/
template <class InputIterator>
Fast_Delaunay_triangulation_3(InputIterator first, InputIterator last,
                              const Geom_traits& gt = Geom_traits());

/*!
Copies the arrays of `other`. Handles of `other` keep referring to `other`.
*/
Fast_Delaunay_triangulation_3(const Fast_Delaunay_triangulation_3& other);

/*!
Takes the data of `other`, which handles of `other` follow, and leaves
`other` empty (dimension -1, usable, with the default options).
*/
Fast_Delaunay_triangulation_3(Fast_Delaunay_triangulation_3&& other) noexcept;

/*!
*/
Fast_Delaunay_triangulation_3& operator=(const Fast_Delaunay_triangulation_3& other);

/*!
Takes the data of `other`, which handles of `other` follow, and leaves
`other` empty.
*/
Fast_Delaunay_triangulation_3& operator=(Fast_Delaunay_triangulation_3&& other) noexcept;

/*!
Exchanges the contents of the two triangulations in constant time. Handles
and iterators follow the data: one taken from `*this` designates the same
vertex or cell, now in `other`.
*/
void swap(Fast_Delaunay_triangulation_3& other) noexcept;

/*!
Removes all vertices and cells; the dimension becomes -1. The options
(seed, phase timing, sub-determinants, parallel engine) are kept.
*/
void clear();

/// @}

/// \name Options
/// See Section \ref Fast_Delaunay_triangulation_3Options of the manual.
/// @{

/*!
Sets the seed of the insertion order of later insertions (default 0). The
finite cells do not depend on it; the vertex ids, hence the order of the
iterators, do.
*/
void set_seed(std::uint64_t seed);

/*!
Turns the clocks around the walk, the cavity and the Delaunay ball of every
point on or off (default off). The report then fills
`kernel.walk_seconds`, `kernel.cavity_seconds` and `kernel.ball_seconds`.
*/
void set_phase_timing(bool on);

/*!
Timings and counters of the last call to `insert()`, range or single point.
*/
const Insertion_report& last_insertion_report() const;

/*!
Stores (on) or drops (off) the four in-sphere sub-determinants of every
tetrahedron (32 bytes per tetrahedron). Turning them on computes them for all
existing tetrahedra. The default is off unless the macro
`CGAL_FDT3_SUB_DETERMINANTS` is defined to a non-zero value. The
triangulation is the same either way (Section
\ref Fast_Delaunay_triangulation_3Robustness of the manual).
*/
void set_sub_determinants(bool on);

/*!
Whether sub-determinants are stored.
*/
bool sub_determinants() const;

/*!
The parallel engines of a range insertion on several threads.
*/
enum class Parallel_engine {
  partitioned, ///< the paper's Moore partitions, lock-free (the default)
  barrier      ///< the two-level barrier-synchronised kernel of "Multi-threaded mesh generation"
};

/*!
Chooses the engine of later range insertions on several threads (Section
\ref Fast_Delaunay_triangulation_3Barrier of the manual). Both build the same
cells; for the same points and thread count each enumerates them in an order
of its own that does not change from run to run.
*/
void set_parallel_engine(Parallel_engine engine);

/*!
The engine chosen by `set_parallel_engine()`.
*/
Parallel_engine parallel_engine() const;

/// @}

/// \name Insertion
/// @{

/*!
Inserts the points of `[first, last)` and returns the number of new vertices
(points already present, or repeated in the range, add none). The points are
inserted in an order of their own (BRIO rounds sorted along a Moore curve).
If a point has a NaN or infinite coordinate, throws `std::invalid_argument`
whose message gives the position of the first such point in the range, before
anything is changed.
\tparam InputIterator an input iterator with value type `Point`; not
convertible to `Cell_handle`.
*/
template <class InputIterator>
std::ptrdiff_t insert(InputIterator first, InputIterator last);

/*!
Inserts `p` and returns its vertex, or the existing vertex at `p`. Throws
`std::invalid_argument` for a NaN or infinite coordinate, without change.
*/
Vertex_handle insert(const Point& p);

/*!
Same as `insert(p)`; the hint is ignored (the walk starts next to the last
inserted point).
*/
Vertex_handle insert(const Point& p, Cell_handle hint);

/*!
Same as `insert(p)`; the hint is ignored.
*/
Vertex_handle insert(const Point& p, Vertex_handle hint);

/*!
`Triangulation_3::insert_outside_affine_hull()`: `p` raises the dimension by
one, each cell becoming the cone from `p` over it, which is the Delaunay
triangulation of the new point set. Returns the vertex of `p`. Throws
`std::invalid_argument` without change if `dimension() == 3`, if `p` lies in
the affine hull of the vertices (CGAL's preconditions) or has a NaN or
infinite coordinate.
*/
Vertex_handle insert_outside_affine_hull(const Point& p);

/// @}

/// \name Removal and Moves
/// See Section \ref Fast_Delaunay_triangulation_3Removal of the manual.
/// @{

/*!
Removes `v`. The triangulation becomes CGAL's of the remaining points;
handles of the other vertices, and of the cells that did not have `v`, stay
valid with their infos. The dimension may decrease. Throws
`std::invalid_argument`, without change, if `v` is the infinite vertex, a
removed vertex or a vertex of another triangulation.
*/
void remove(Vertex_handle v);

/*!
Removes the vertices of `[first, last)`, one after the other, and returns
how many were removed. All handles are checked first (as `remove(v)`, and
none may appear twice): on a bad one nothing changes.
*/
template <class InputIterator>
size_type remove(InputIterator first, InputIterator last);

/*!
Same as `remove(first, last)`.
*/
template <class InputIterator>
size_type remove_cluster(InputIterator first, InputIterator last);

/*!
If `p` is the point of another vertex `w`, returns `w` and changes nothing.
Otherwise moves `v` to `p` and returns `v`, whose handle and info stay, as
do those of the cells without `v` that stay in the triangulation. Throws
`std::invalid_argument` for a NaN or infinite coordinate, or a bad `v`,
without change.
*/
Vertex_handle move_if_no_collision(Vertex_handle v, const Point& p);

/*!
Same as `move_if_no_collision()`, except that if `p` is the point of another
vertex `w`, `v` is removed and `w` returned.
*/
Vertex_handle move(Vertex_handle v, const Point& p);

/*!
In dimension 3, whether the cells of `v` with `p` for its point are still
the Delaunay triangulation, so that moving `v` to `p` changes nothing else
(exact, with CGAL's perturbation). Throws `std::invalid_argument` below
dimension 3, for a bad `v`, or for a NaN or infinite coordinate.
*/
bool is_delaunay_after_displacement(Vertex_handle v, const Point& p) const;

/// @}

/// \name Access Functions
/// @{

/*!
*/
const Geom_traits& geom_traits() const;

/*!
The dimension of the affine hull of the points: -1 (empty), 0, 1, 2 or 3,
as in `Delaunay_triangulation_3`.
*/
int dimension() const;

/*!
The number of finite vertices.
*/
size_type number_of_vertices() const;

/*!
The number of cells, finite and infinite; 0 if `dimension() < 3` (as in CGAL).
*/
size_type number_of_cells() const;

/*!
0 if `dimension() < 3`.
*/
size_type number_of_finite_cells() const;

/*!
Twice the number of cells; the number of triangles, finite and infinite, in
dimension 2; 0 below.
*/
size_type number_of_facets() const;

/*!
The interior facets plus the convex hull facets; the finite triangles in
dimension 2; 0 below.
*/
size_type number_of_finite_facets() const;

/*!
Computed from Euler's relation on the triangulated ball,
\f$ V - E + F - T = 1 \f$; in dimension 2, 3/2 of the triangles less one per
hull edge; in dimension 1 the finite segments; 0 below.
*/
size_type number_of_finite_edges() const;

/*!
The finite edges plus one infinite edge per convex hull vertex (in dimensions
3 and 2; two in dimension 1); 0 below dimension 1.
*/
size_type number_of_edges() const;

/*!
*/
Vertex_handle infinite_vertex() const;

/*!
An infinite cell (a cell with the infinite vertex below dimension 3); in
dimension -1 the cell that holds only the infinite vertex, as in CGAL.
Scans the cells in dimension 3.
*/
Cell_handle infinite_cell() const;

/*!
The point of vertex `i` of `c`: a `const Point&` with a user vertex base,
a `Point` otherwise (see `Vertex::point()` above).
\pre `c->vertex(i)` is finite.
*/
Point point(Cell_handle c, int i) const;

/*!
As `point(c, i)`.
*/
Point point(Vertex_handle v) const;

/*!
The tetrahedron of the four points of `c`.
\pre `c` is finite.
*/
Tetrahedron tetrahedron(Cell_handle c) const;

/// @}

/// \name Predicates
/// In an infinite cell the infinite vertex is always vertex 3.
/// @{

/*!
*/
bool is_infinite(Vertex_handle v) const;

/*!
Whether `c` has the infinite vertex; also below dimension 3, where
`Delaunay_triangulation_3` requires dimension 3.
*/
bool is_infinite(Cell_handle c) const;

/*!
Whether facet `i` of `c` contains the infinite vertex; in dimension 2, `i` is
3 and the facet is the triangle `c`.
*/
bool is_infinite(Cell_handle c, int i) const;

/*!
*/
bool is_infinite(const Facet& f) const;

/*!
Whether edge `(i, j)` of `c` contains the infinite vertex.
*/
bool is_infinite(Cell_handle c, int i, int j) const;

/*!
*/
bool is_infinite(const Edge& e) const;

/// @}

/// \name Adjacency
/// @{

/*!
The index of `c` in its neighbour `c->neighbor(i)`, read from the neighbour
code without a search.
*/
int mirror_index(Cell_handle c, int i) const;

/*!
The vertex of `c->neighbor(i)` opposite to `c`.
*/
Vertex_handle mirror_vertex(Cell_handle c, int i) const;

/*!
The same facet seen from the other cell.
*/
Facet mirror_facet(const Facet& f) const;

/// @}

/// \name Cell, Vertex, Facet and Edge Iterators
/// `cells_begin()`, `vertices_begin()`, `facets_begin()` and `edges_begin()`
/// (and their `end`) are the same as the `all_` versions.
/// @{

/*!
*/
All_cells_iterator all_cells_begin() const;
/*!
*/
All_cells_iterator all_cells_end() const;
/*!
*/
All_cells_iterator cells_begin() const;
/*!
*/
All_cells_iterator cells_end() const;
/*!
*/
Finite_cells_iterator finite_cells_begin() const;
/*!
*/
Finite_cells_iterator finite_cells_end() const;

/*!
Starts with the infinite vertex, which exists even in the empty
triangulation.
*/
All_vertices_iterator all_vertices_begin() const;
/*!
*/
All_vertices_iterator all_vertices_end() const;
/*!
*/
All_vertices_iterator vertices_begin() const;
/*!
*/
All_vertices_iterator vertices_end() const;
/*!
*/
Finite_vertices_iterator finite_vertices_begin() const;
/*!
*/
Finite_vertices_iterator finite_vertices_end() const;

/*!
*/
All_facets_iterator all_facets_begin() const;
/*!
*/
All_facets_iterator all_facets_end() const;
/*!
*/
All_facets_iterator facets_begin() const;
/*!
*/
All_facets_iterator facets_end() const;
/*!
*/
Finite_facets_iterator finite_facets_begin() const;
/*!
*/
Finite_facets_iterator finite_facets_end() const;

/*!
Each increment turns around the next candidate edge to find out whether the
current cell has the smallest index around it, so a full pass costs about the
sum of the edge degrees.
*/
All_edges_iterator all_edges_begin() const;
/*!
*/
All_edges_iterator all_edges_end() const;
/*!
*/
All_edges_iterator edges_begin() const;
/*!
*/
All_edges_iterator edges_end() const;
/*!
*/
Finite_edges_iterator finite_edges_begin() const;
/*!
*/
Finite_edges_iterator finite_edges_end() const;

/// @}

/// \name Ranges
/// @{

/*!
*/
All_cells all_cells() const;
/*!
*/
Finite_cells finite_cells() const;
/*!
*/
All_vertices all_vertices() const;
/*!
*/
Finite_vertices finite_vertices() const;
/*!
*/
All_facets all_facets() const;
/*!
*/
Finite_facets finite_facets() const;
/*!
*/
All_edges all_edges() const;
/*!
*/
Finite_edges finite_edges() const;
/*!
*/
All_cell_handles all_cell_handles() const;
/*!
*/
Finite_cell_handles finite_cell_handles() const;
/*!
*/
All_vertex_handles all_vertex_handles() const;
/*!
*/
Finite_vertex_handles finite_vertex_handles() const;
/*!
*/
Point_iterator points_begin() const;
/*!
*/
Point_iterator points_end() const;
/*!
*/
Points points() const;

/// @}

/// \name Checking
/// @{

/*!
Checks, with exact predicates: that every cell references existing vertices,
with the infinite vertex only in slot 3; that adjacency is symmetric and
neighbours share the facet; that no infinite cell is adjacent to another
through its finite facet; that finite cells are positively oriented and the
convex hull facets are seen from outside by their infinite cells; that every
finite cell is locally Delaunay across each facet (with the symbolic
perturbation); that the stored counts match; and that every vertex is in a
cell. Below dimension 3 it checks CGAL's conventions for segments and
triangles, collinearity and order along the line, or coplanarity, orientation,
a convex hull and the perturbed local Delaunay property. If `verbose`, the
first problem found is written to `std::cerr`. The `level` argument is
ignored.
*/
bool is_valid(bool verbose = false, int level = 0) const;

/// @}

/// \name Input/Output
/// CGAL's file format for `Triangulation_3`; see also `operator<<()` and
/// `operator>>()` below and the manual's section
/// \ref Fast_Delaunay_triangulation_3IO.
/// @{

/*!
Writes the triangulation as `Triangulation_3`'s `operator<<` writes the same
triangulation (ASCII or binary after the stream's `CGAL::IO` mode; points
with the stream's precision). Below dimension 3 the cells written are those
of a `Delaunay_triangulation_3` built from the vertices. The stream is
flushed at the end, as CGAL's writer leaves it (its last line ends with
`std::endl`), so the file can be read back while it is still open.
*/
void write(std::ostream& os) const;

/*!
Replaces the triangulation by the one in `is`, in linear time, after checking
counts, index ranges, symmetric adjacency, connectivity, orientation and the
Delaunay property. On bad input returns `false`, sets the failbit of `is`,
writes the reason and its position to `*error` (if not null) and leaves the
triangulation unchanged. Below dimension 3 only the vertices are kept. The
format holds doubles (an exact kernel's `operator<<` writes the double of
each coordinate), so with a kernel whose `FT` is not `double` each coordinate
read, a decimal or a quotient, is taken as its nearest double: a file written
with precision 17 gives back the points written.
*/
bool read(std::istream& is, std::string* error = nullptr);

/// @}

/// \name Internal Access
/// Public for the package's own exports (the Python module, the file writers,
/// `convert_to_cgal()`); not part of the interface users should rely on.
/// @{

/*!
The flat arrays.
*/
const Fast_Delaunay_triangulation_3_internal::Flat_storage& flat_storage() const;

/*!
The point of vertex id `v`; `Point(0, 0, 0)` for the infinite vertex.
*/
Point point_of(Fast_Delaunay_triangulation_3_internal::Vertex_id v) const;

/*!
A cell incident to vertex id `v`, or a null handle in dimension -1.
*/
Cell_handle incident_cell_of(Fast_Delaunay_triangulation_3_internal::Vertex_id v) const;

/*!
The storage anchor that handles point at: the arrays, the kernel's points,
the infos and the records of user bases.
*/
const Anchor* storage_anchor() const;

/// @}

}; /* end Fast_Delaunay_triangulation_3 */

/*!
\relates Fast_Delaunay_triangulation_3
Writes `tr` in the file format of `Triangulation_3`: readable by
`Delaunay_triangulation_3`'s `operator>>`, with the same cells.
*/
template <class Gt, class Tds, class Lp, class Lds>
std::ostream& operator<<(std::ostream& os, const Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& tr);

/*!
\relates Fast_Delaunay_triangulation_3
Reads a file written by `Triangulation_3`'s (or this class's) `operator<<`;
see `read()`.
*/
template <class Gt, class Tds, class Lp, class Lds>
std::istream& operator>>(std::istream& is, Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& tr);

/*!
\relates Fast_Delaunay_triangulation_3
Defined in `CGAL/Fast_Delaunay_triangulation_3/convert_to_cgal.h`. Makes
`target` (a `Triangulation_3` or a class derived from it, with any data
structure) a triangulation with the same cells as `source`, in the same order,
by creating its vertices and cells directly: linear time, no point is
re-inserted. Below dimension 3 the points are inserted into `target`.
*/
template <class Gt, class Tds, class Lp, class Lds, class Cgal_triangulation>
void convert_to_cgal(const Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& source, Cgal_triangulation& target);

/*!
\relates Fast_Delaunay_triangulation_3
Defined in `CGAL/Fast_Delaunay_triangulation_3/convert_to_cgal.h`. Replaces
`c3t3` (a `Mesh_complex_3_in_triangulation_3`) by `convert_to_cgal(source,
c3t3.triangulation())`, with every finite cell `c` in the complex with
subdomain `subdomain_of_cell(c)` (a `Cell_handle` of `source`; default 1;
`Subdomain_index()` leaves the cell out) and every facet between two different
subdomains, the outside included, a surface facet with index
`surface_patch(s1, s2)`. Vertices get the Mesh_3 dimension 2 on the surface
and 3 elsewhere.
*/
template <class Gt, class Tds, class Lp, class Lds, class C3t3, class Subdomain_of_cell, class Surface_patch_of_pair>
void convert_to_c3t3(const Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& source, C3t3& c3t3,
                     Subdomain_of_cell subdomain_of_cell, Surface_patch_of_pair surface_patch);

} /* end namespace CGAL */
