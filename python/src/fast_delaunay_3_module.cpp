// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module fast_delaunay_3 (compiled part, `_core`): numpy arrays in,
// index arrays out.  Points are rows of the caller's arrays; a vertex is
// named by the row of the first input point at its position (later equal
// rows are its duplicates), so the tetrahedra index the caller's own array,
// as scipy.spatial.Delaunay's simplices do.
//
// The work runs with the GIL released; the arrays handed back are allocated
// once and filled in place (one copy of the tetrahedra, from the flat arrays
// into numpy's).  C++ exceptions become Python's: std::invalid_argument
// (NaN, bad index, bad surface) -> ValueError.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#ifdef FDT3_PYTHON_WITH_MESHER
#include <CGAL/Fast_Delaunay_triangulation_3/Surface_remeshing.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace py = pybind11;

namespace fast_delaunay_3_python {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Fast_Delaunay_triangulation_3<Kernel> Delaunay;
typedef Delaunay::Point Point;
typedef Delaunay::Vertex_handle Vertex_handle;
typedef Delaunay::Cell_handle Cell_handle;
typedef CGAL::Fast_Delaunay_triangulation_3_internal::Flat_storage Flat_storage;
typedef CGAL::Fast_Delaunay_triangulation_3_internal::Tet_id Tet_id;
typedef CGAL::Fast_Delaunay_triangulation_3_internal::Vertex_id Vertex_id;

// A row of the caller's arrays (or of all the arrays inserted so far).
typedef std::int64_t Row;
constexpr Row no_row = -1;

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;

// ---------------------------------------------------------------- input checks

// The (n, 3) float64 C-ordered array of `points`: other dtypes and strides
// are converted here, once.
Double_array point_rows(const py::handle& points, const char* what)
{
  Double_array rows = Double_array::ensure(points);
  if(!rows) throw py::type_error(std::string(what) + " must be an array of numbers");
  if(rows.ndim() != 2 || rows.shape(1) != 3) {
    std::ostringstream message;
    message << what << " must be an (n, 3) array, got shape (";
    for(py::ssize_t k = 0; k < rows.ndim(); ++k) message << (k ? ", " : "") << rows.shape(k);
    message << (rows.ndim() == 1 ? ",)" : ")");
    throw py::value_error(message.str());
  }
  const double* xyz = rows.data();
  for(py::ssize_t i = 0; i < 3 * rows.shape(0); ++i)
    if(!std::isfinite(xyz[i]))
      throw py::value_error(std::string(what) + ": row " + std::to_string(i / 3) + " has a " +
                            (std::isnan(xyz[i]) ? "NaN" : "infinite") + " coordinate");
  return rows;
}

// None: every hardware thread; else at least 1.
int thread_count(const py::object& threads)
{
  if(threads.is_none()) return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const long k = threads.cast<long>();
  if(k < 1 || k > 255) throw py::value_error("threads must be between 1 and 255, got " + std::to_string(k));
  return static_cast<int>(k);
}

// Vertex indices fit int32 below 2^31 rows, uint32 below 2^32.
py::array index_array(std::size_t rows, std::size_t columns, Row largest)
{
  const std::vector<py::ssize_t> shape = {static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)};
  if(largest <= std::numeric_limits<std::int32_t>::max()) return py::array_t<std::int32_t>(shape);
  if(largest <= std::numeric_limits<std::uint32_t>::max()) return py::array_t<std::uint32_t>(shape);
  return py::array_t<std::int64_t>(shape);
}

// The buffer of an index_array(), read with the GIL held so that the filling
// can run without it; with_buffer(f) calls f with the typed pointer.
class Index_buffer
{
public:
  explicit Index_buffer(py::array& a) : data_(a.mutable_data())
  {
    if(py::isinstance<py::array_t<std::int32_t>>(a)) kind_ = Kind::int32;
    else if(py::isinstance<py::array_t<std::uint32_t>>(a)) kind_ = Kind::uint32;
    else kind_ = Kind::int64;
  }
  template <class F>
  void with_buffer(F f) const
  {
    switch(kind_) {
    case Kind::int32: f(static_cast<std::int32_t*>(data_)); break;
    case Kind::uint32: f(static_cast<std::uint32_t*>(data_)); break;
    case Kind::int64: f(static_cast<std::int64_t*>(data_)); break;
    }
  }

private:
  enum class Kind { int32, uint32, int64 };
  void* data_;
  Kind kind_;
};

// Calls f(begin, end) on `threads` threads for consecutive ranges covering
// [0, n); one range, on this thread, for small n.
template <class F>
void for_each_range(std::size_t n, int threads, F f)
{
  const std::size_t ranges = std::min<std::size_t>(std::max(1, threads), 1 + n / 65536);
  std::vector<std::thread> workers;
  for(std::size_t k = 1; k < ranges; ++k) workers.emplace_back(f, n * k / ranges, n * (k + 1) / ranges);
  f(0, n / ranges);
  for(std::thread& w : workers) w.join();
}

// ---------------------------------------------------------------- the triangulation of rows

// A Fast_Delaunay_triangulation_3 whose vertices are named by rows.
class Row_triangulation
{
public:
  explicit Row_triangulation(int threads, bool keeps_rows = true) : keeps_rows_(keeps_rows)
  {
    set_threads(threads);
  }

  int threads() const { return threads_; }
  void set_threads(int k)
  {
    threads_ = k;
    delaunay_.set_number_of_threads(k);
  }

  const Delaunay& delaunay() const { return delaunay_; }
  std::size_t number_of_rows() const { return row_count_; }
  const std::vector<double>& rows() const { return rows_; }

  // Appends the rows and inserts them; returns for each the row naming its
  // vertex (itself, or an earlier equal row).  Checked before anything changes.
  py::array_t<Row> insert(const py::handle& points)
  {
    const Double_array input = point_rows(points, "points");
    const std::size_t n = static_cast<std::size_t>(input.shape(0));
    py::array_t<Row> named(static_cast<py::ssize_t>(n));
    Row* out = named.mutable_data();
    {
      py::gil_scoped_release unlocked;
      std::vector<Vertex_handle> vertices;
      vertices.reserve(n);
      delaunay_.insert_coordinates_and_give_vertices(input.data(), n, std::back_inserter(vertices));
      const Row first = static_cast<Row>(row_count_);
      row_count_ += n;
      if(keeps_rows_) {
        rows_.insert(rows_.end(), input.data(), input.data() + 3 * n);
        vertex_of_row_.resize(row_count_);
      }
      for(std::size_t i = 0; i < n; ++i) out[i] = name(vertices[i], first + static_cast<Row>(i));
    }
    changed();
    return named;
  }

  void remove(const py::handle& indices)
  {
    const std::vector<Row> rows = checked_vertex_rows(indices, "remove");
    {
      py::gil_scoped_release unlocked;
      for(Row r : rows) {
        const Vertex_handle v = vertex_of_row_[r];
        delaunay_.remove(v);
        forget(v, r);
      }
    }
    changed();
  }

  // Moves the vertices of `indices` to `points`; returns for each the row
  // naming its vertex afterwards: its own, or, when it landed on another
  // vertex (which then stays and it goes, as in CGAL's move), that vertex's.
  py::array_t<Row> move(const py::handle& indices, const py::handle& points)
  {
    const std::vector<Row> rows = checked_vertex_rows(indices, "move");
    const Double_array targets = point_rows(points, "points");
    if(static_cast<std::size_t>(targets.shape(0)) != rows.size())
      throw py::value_error("move: " + std::to_string(rows.size()) + " indices but " +
                            std::to_string(targets.shape(0)) + " points");
    py::array_t<Row> named(static_cast<py::ssize_t>(rows.size()));
    Row* out = named.mutable_data();
    const double* xyz = targets.data();
    {
      py::gil_scoped_release unlocked;
      for(std::size_t k = 0; k < rows.size(); ++k) {
        const Row r = rows[k];
        const Vertex_handle v = vertex_of_row_[r];
        const Vertex_handle w = delaunay_.move(v, Point(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]));
        if(w == v) {
          std::copy(xyz + 3 * k, xyz + 3 * k + 3, rows_.begin() + 3 * r);
          out[k] = r;
          continue;
        }
        const Row w_row = row_of(w);
        forget(v, r);
        if(w_row != no_row) {
          out[k] = w_row; // landed on another vertex: r is gone
        } else {
          std::copy(xyz + 3 * k, xyz + 3 * k + 3, rows_.begin() + 3 * r);
          out[k] = name(w, r);
        }
      }
    }
    changed();
    return named;
  }

  // The rows of the vertices, increasing.
  py::array_t<Row> vertex_rows() const
  {
    std::vector<Row> rows;
    rows.reserve(delaunay_.number_of_vertices());
    for(std::size_t r = 0; r < vertex_of_row_.size(); ++r)
      if(vertex_of_row_[r] != Vertex_handle()) rows.push_back(static_cast<Row>(r));
    return py::array_t<Row>(static_cast<py::ssize_t>(rows.size()), rows.data());
  }

  // (tets, neighbors): the finite cells as rows, positively oriented;
  // neighbors[c][i] is the finite cell across the facet opposite vertex i, -1
  // on the convex hull.  Empty below dimension 3.
  py::tuple finite_cells() const
  {
    const Cell_numbering& numbering = cell_numbering();
    const Flat_storage& mesh = delaunay_.flat_storage();
    const std::size_t m = numbering.cells.size();
    py::array tets = index_array(m, 4, static_cast<Row>(number_of_rows()) - 1);
    py::array neighbors = index_array(m, 4, static_cast<Row>(m));
    const Index_buffer tets_buffer(tets), neighbors_buffer(neighbors);
    {
      py::gil_scoped_release unlocked;
      // Each thread fills a range of cells of both arrays: the writes, into
      // pages the kernel must first zero, are most of the time.
      for_each_range(m, threads_, [&](std::size_t begin, std::size_t end) {
        tets_buffer.with_buffer([&](auto* out) {
          typedef std::remove_pointer_t<decltype(out)> Index;
          for(std::size_t c = begin; c < end; ++c) {
            const Vertex_id* v = mesh.vertex_ids(numbering.cells[c]);
            for(int i = 0; i < 4; ++i) out[4 * c + i] = static_cast<Index>(row_of_slot_[v[i]]);
          }
        });
        neighbors_buffer.with_buffer([&](auto* out) {
          typedef std::remove_pointer_t<decltype(out)> Index;
          for(std::size_t c = begin; c < end; ++c)
            for(int i = 0; i < 4; ++i)
              out[4 * c + i] = static_cast<Index>(numbering.number_of(mesh.neighbor(numbering.cells[c], i)));
        });
      });
    }
    return py::make_tuple(tets, neighbors);
  }

  // finite_cells() for a triangulation used no more (delaunay()): the
  // tetrahedron records become the output in place, each record's slot
  // holding its cell's 4 rows and 4 neighbours as int32, and numpy takes
  // the block over.  No page is written twice, and none is new: at 1e6
  // points a fresh (m, 4) + (m, 4) pair cost 0.4 to 0.9 s of page faults in
  // a new process, against 1.7 s for the whole insertion.  tets and
  // neighbors are the two halves of one (m, 8) array: views with a row
  // stride of one record.  Falls back to finite_cells() where int32 does
  // not hold the indices.  Leaves the triangulation empty.
  py::tuple take_finite_cells()
  {
    const Cell_numbering& numbering = cell_numbering();
    const std::size_t m = numbering.cells.size();
    const std::int64_t largest = std::max<std::int64_t>(static_cast<std::int64_t>(number_of_rows()),
                                                        static_cast<std::int64_t>(m));
    if(m == 0 || largest > std::numeric_limits<std::int32_t>::max()) return finite_cells();
    typedef CGAL::Fast_Delaunay_triangulation_3_internal::Tet_record Tet_record;
    static_assert(sizeof(Tet_record) >= 8 * sizeof(std::int32_t), "a record holds a row of the output");
    Flat_storage& mesh = delaunay_.flat_storage_to_take_apart();
    {
      py::gil_scoped_release unlocked;
      char* records = reinterpret_cast<char*>(mesh.tets.data());
      // Each finite record becomes its row in its own slot, on the
      // triangulation's threads (the lookups miss the caches: the work)...
      for_each_range(m, threads_, [&](std::size_t begin, std::size_t end) {
        for(std::size_t c = begin; c < end; ++c) {
          const Tet_record record = mesh.tets[numbering.cells[c]];
          std::int32_t row[8];
          for(int i = 0; i < 4; ++i) {
            row[i] = static_cast<std::int32_t>(row_of_slot_[record.v[i]]);
            row[4 + i] = static_cast<std::int32_t>(
                numbering.number_of(CGAL::Fast_Delaunay_triangulation_3_internal::tet_of(record.n[i])));
          }
          std::memcpy(records + numbering.cells[c] * sizeof(Tet_record), row, sizeof(row));
        }
      });
      // ... then row c moves down to slot c.  Cells are numbered in slot
      // order (c <= cells[c]), so nothing is overwritten before it moves.
      for(std::size_t c = 0; c < m; ++c)
        if(numbering.cells[c] != c)
          std::memcpy(records + c * sizeof(Tet_record), records + numbering.cells[c] * sizeof(Tet_record),
                      8 * sizeof(std::int32_t));
    }
    Tet_record* data = nullptr;
    char* block = mesh.tets.release(data);
    delaunay_.clear();
    changed();
    const py::capsule owner(block, [](void* p) { std::free(p); });
    const py::ssize_t stride = static_cast<py::ssize_t>(sizeof(Tet_record));
    const py::array_t<std::int32_t> cells({static_cast<py::ssize_t>(m), py::ssize_t(8)},
                                          {stride, static_cast<py::ssize_t>(sizeof(std::int32_t))},
                                          reinterpret_cast<std::int32_t*>(data), owner);
    const py::object all = py::slice(py::none(), py::none(), py::none());
    return py::make_tuple(cells[py::make_tuple(all, py::slice(0, 4, 1))],
                          cells[py::make_tuple(all, py::slice(4, 8, 1))]);
  }

  // The facets of the convex hull as rows, counterclockwise seen from
  // outside (their normals point out).  Empty below dimension 3.
  py::array hull_facets() const
  {
    std::vector<std::array<Row, 3>> facets;
    if(delaunay_.dimension() == 3) {
      const Vertex_handle infinite = delaunay_.infinite_vertex();
      for(Cell_handle c : delaunay_.all_cell_handles()) {
        int i;
        if(!c->has_vertex(infinite, i)) continue;
        // An infinite cell is positively oriented with its infinite vertex
        // outside the hull: its other three are counterclockwise seen from
        // there in CGAL's facet order.
        std::array<Row, 3> f;
        for(int k = 0; k < 3; ++k) f[k] = row_of(c->vertex(Delaunay::vertex_triple_index(i, k)));
        facets.push_back(f);
      }
    }
    py::array out = index_array(facets.size(), 3, static_cast<Row>(number_of_rows()) - 1);
    Index_buffer(out).with_buffer([&](auto* index) {
      for(std::size_t k = 0; k < 3 * facets.size(); ++k)
        index[k] = static_cast<std::remove_pointer_t<decltype(index)>>(facets[k / 3][k % 3]);
    });
    return out;
  }

  // The circumcentres of the finite cells, in finite_cells() order.
  py::array_t<double> circumcenters() const
  {
    const Cell_numbering& numbering = cell_numbering();
    const Flat_storage& mesh = delaunay_.flat_storage();
    py::array_t<double> out({static_cast<py::ssize_t>(numbering.cells.size()), py::ssize_t(3)});
    double* xyz = out.mutable_data();
    {
      py::gil_scoped_release unlocked;
      for(std::size_t k = 0; k < numbering.cells.size(); ++k) {
        const Point corner[4] = {point_of(mesh, numbering.cells[k], 0), point_of(mesh, numbering.cells[k], 1),
                                 point_of(mesh, numbering.cells[k], 2), point_of(mesh, numbering.cells[k], 3)};
        const Point c = CGAL::circumcenter(corner[0], corner[1], corner[2], corner[3]);
        xyz[3 * k] = c.x();
        xyz[3 * k + 1] = c.y();
        xyz[3 * k + 2] = c.z();
      }
    }
    return out;
  }

  // For each query, the finite cell (finite_cells() order) that contains it,
  // -1 outside the convex hull; a query on a shared face gets one of the cells.
  py::array_t<std::int64_t> locate(const py::handle& queries) const
  {
    const Double_array q = point_rows(queries, "queries");
    const Cell_numbering& numbering = cell_numbering();
    py::array_t<std::int64_t> out(q.shape(0));
    std::int64_t* cell = out.mutable_data();
    {
      py::gil_scoped_release unlocked;
      const double* xyz = q.data();
      Cell_handle hint;
      for(py::ssize_t i = 0; i < q.shape(0); ++i) {
        hint = delaunay_.locate(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), hint);
        cell[i] = delaunay_.dimension() == 3 ? numbering.number_of(hint) : -1;
      }
    }
    return out;
  }

  // For each query, the row of the nearest vertex.
  py::array_t<Row> nearest_vertex(const py::handle& queries) const
  {
    const Double_array q = point_rows(queries, "queries");
    if(delaunay_.number_of_vertices() == 0) throw py::value_error("nearest_vertex: the triangulation has no vertex");
    py::array_t<Row> out(q.shape(0));
    Row* row = out.mutable_data();
    {
      py::gil_scoped_release unlocked;
      const double* xyz = q.data();
      Vertex_handle hint;
      for(py::ssize_t i = 0; i < q.shape(0); ++i) {
        hint = delaunay_.nearest_vertex(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]),
                                        hint == Vertex_handle() ? Cell_handle() : hint->cell());
        row[i] = row_of(hint);
      }
    }
    return out;
  }

  // Pickled state: every row, the rows of the vertices, the thread count.
  py::tuple state() const
  {
    py::array_t<double> rows({static_cast<py::ssize_t>(number_of_rows()), py::ssize_t(3)});
    std::copy(rows_.begin(), rows_.end(), rows.mutable_data());
    return py::make_tuple(rows, vertex_rows(), threads_);
  }

  static Row_triangulation from_state(const py::tuple& state)
  {
    if(state.size() != 3) throw py::value_error("Triangulation: not a pickled state");
    Row_triangulation t(state[2].cast<int>());
    const Double_array rows = point_rows(state[0], "pickled rows");
    const auto vertices = py::array_t<Row, py::array::c_style | py::array::forcecast>::ensure(state[1]);
    if(!vertices || vertices.ndim() != 1) throw py::value_error("Triangulation: not a pickled state (vertex rows)");
    const std::size_t n = static_cast<std::size_t>(rows.shape(0));
    std::vector<Point> points;
    for(py::ssize_t k = 0; k < vertices.size(); ++k) {
      const Row r = vertices.data()[k];
      if(r < 0 || static_cast<std::size_t>(r) >= n || (k > 0 && r <= vertices.data()[k - 1]))
        throw py::value_error("Triangulation: not a pickled state (vertex rows)");
      points.emplace_back(rows.data()[3 * r], rows.data()[3 * r + 1], rows.data()[3 * r + 2]);
    }
    std::vector<Vertex_handle> handles;
    t.delaunay_.insert_and_give_vertices(points.begin(), points.end(), std::back_inserter(handles));
    t.rows_.assign(rows.data(), rows.data() + 3 * n);
    t.vertex_of_row_.resize(n);
    t.row_count_ = n;
    for(py::ssize_t k = 0; k < vertices.size(); ++k)
      if(t.name(handles[k], vertices.data()[k]) != vertices.data()[k])
        throw py::value_error("Triangulation: not a pickled state (two vertex rows are equal)");
    return t;
  }

private:
  // The finite cells in the order of the exports, and their numbers by cell slot.
  // Read from the flat arrays (the class's flat_storage()), slot by slot, not
  // through cell handles: at 1e6 points (6.7e6 cells) the handle loops took
  // 0.36 s, a quarter of the insertion's time, against the issue's bound of
  // 15% for the whole binding.  In dimension 3 a cell handle's vertex(i) and
  // neighbor(i) are the record's, so both readings agree.
  struct Cell_numbering
  {
    // 32-bit slots and numbers: half the memory traffic of Tet_id's 64 bits.
    typedef std::uint32_t Slot;
    static constexpr Slot none = std::numeric_limits<Slot>::max();
    std::vector<Slot> cells;          // slots of the finite cells
    std::vector<Slot> number_of_slot; // `none` for free slots and infinite cells
    std::int64_t number_of(Tet_id t) const
    {
      return number_of_slot[t] == none ? std::int64_t(-1) : std::int64_t(number_of_slot[t]);
    }
    std::int64_t number_of(Cell_handle c) const { return number_of(static_cast<Tet_id>(c.index())); }
  };

  const Cell_numbering& cell_numbering() const
  {
    if(numbering_valid_) return numbering_;
    numbering_ = Cell_numbering();
    if(delaunay_.dimension() == 3) {
      const Flat_storage& mesh = delaunay_.flat_storage();
      if(mesh.number_of_slots() >= Cell_numbering::none)
        throw std::length_error("fast_delaunay_3: more than 2^32 - 1 cell slots to number");
      numbering_.number_of_slot.assign(mesh.number_of_slots(), Cell_numbering::none);
      numbering_.cells.reserve(delaunay_.number_of_finite_cells());
      for(Tet_id t = 0; t < mesh.number_of_slots(); ++t) {
        if(!mesh.is_live(t) || mesh.is_ghost(t)) continue;
        numbering_.number_of_slot[t] = static_cast<Cell_numbering::Slot>(numbering_.cells.size());
        numbering_.cells.push_back(static_cast<Cell_numbering::Slot>(t));
      }
    }
    numbering_valid_ = true;
    return numbering_;
  }

  static Point point_of(const Flat_storage& mesh, Tet_id t, int i)
  {
    const double* xyz = mesh.point(mesh.vertex(t, i));
    return Point(xyz[0], xyz[1], xyz[2]);
  }

  void changed() { numbering_valid_ = false; }

  Row row_of(Vertex_handle v) const
  {
    return v.index() < row_of_slot_.size() ? row_of_slot_[v.index()] : no_row;
  }

  // The row naming v: `r` if v has none yet.
  Row name(Vertex_handle v, Row r)
  {
    if(v.index() >= row_of_slot_.size()) row_of_slot_.resize(v.index() + 1, no_row);
    Row& named = row_of_slot_[v.index()];
    if(named == no_row) {
      named = r;
      if(keeps_rows_) vertex_of_row_[r] = v;
    }
    return named;
  }

  void forget(Vertex_handle v, Row r)
  {
    row_of_slot_[v.index()] = no_row;
    vertex_of_row_[r] = Vertex_handle();
  }

  // The rows of `indices`, each naming a vertex, none twice.
  std::vector<Row> checked_vertex_rows(const py::handle& indices, const char* what) const
  {
    const auto a = py::array_t<Row, py::array::c_style | py::array::forcecast>::ensure(indices);
    if(!a || a.ndim() != 1) throw py::value_error(std::string(what) + ": indices must be a 1-d array of integers");
    std::vector<Row> rows(a.data(), a.data() + a.size());
    std::vector<char> seen(number_of_rows(), 0);
    for(std::size_t k = 0; k < rows.size(); ++k) {
      const Row r = rows[k];
      if(r < 0 || static_cast<std::size_t>(r) >= number_of_rows() || vertex_of_row_[r] == Vertex_handle())
        throw py::value_error(std::string(what) + ": index " + std::to_string(r) + " (position " +
                              std::to_string(k) + ") names no vertex");
      if(seen[r]++)
        throw py::value_error(std::string(what) + ": index " + std::to_string(r) + " is given twice");
    }
    return rows;
  }

  Delaunay delaunay_;
  int threads_ = 1;
  // delaunay() keeps only the rows' vertices (row_of_slot_), not the rows.
  bool keeps_rows_ = true;
  std::size_t row_count_ = 0;
  std::vector<double> rows_;                 // x, y, z of every row inserted
  std::vector<Vertex_handle> vertex_of_row_; // the vertex a row names, or null
  std::vector<Row> row_of_slot_;             // the row naming each vertex slot
  mutable Cell_numbering numbering_;
  mutable bool numbering_valid_ = false;
};

// ---------------------------------------------------------------- the mesher

#ifdef FDT3_PYTHON_WITH_MESHER
CGAL::Fast_mesher_3::Mesher_options mesher_options(const py::object& size, const py::object& threads, bool optimize,
                                                   const py::object& size_field, double min_dihedral_target)
{
  CGAL::Fast_mesher_3::Mesher_options options;
  options.optimize = optimize;
  options.min_dihedral_target = min_dihedral_target;
  if(!size.is_none() && PyCallable_Check(size.ptr())) {
    // h(x, y, z), called from the mesher's threads while mesh() has let the
    // GIL go: each call takes it back.  The handle does not own the
    // callable (copies of the std::function die without the GIL); the
    // caller's argument keeps it alive for the whole call.  What it raises
    // ends the meshing as RuntimeError with its text.
    const py::handle h = size;
    options.size_function = [h](double x, double y, double z) {
      py::gil_scoped_acquire gil;
      try {
        return h(x, y, z).cast<double>();
      } catch(py::error_already_set& e) {
        throw std::runtime_error(std::string("mesh: the size function raised ") + e.what());
      } catch(const py::cast_error&) {
        throw std::invalid_argument("mesh: the size function returned something that is not a number");
      }
    };
  } else if(!size.is_none()) {
    options.maximum_size = size.cast<double>();
    if(!(options.maximum_size > 0)) throw py::value_error("mesh: size must be positive");
  }
  options.threads = thread_count(threads);
  // The file's std::invalid_argument (naming the line) arrives as ValueError.
  if(!size_field.is_none()) CGAL::Fast_mesher_3::read_size_field(py::str(size_field).cast<std::string>(), options);
  return options;
}

py::tuple mesh_arrays(const CGAL::Fast_mesher_3::Tetrahedral_mesh& mesh)
{
  py::array_t<double> points({static_cast<py::ssize_t>(mesh.points.size()), py::ssize_t(3)});
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
    std::copy(mesh.points[i].begin(), mesh.points[i].end(), points.mutable_data() + 3 * i);
  py::array tets = index_array(mesh.tetrahedra.size(), 4, static_cast<Row>(mesh.points.size()) - 1);
  Index_buffer(tets).with_buffer([&](auto* index) {
    for(std::size_t k = 0; k < 4 * mesh.tetrahedra.size(); ++k)
      index[k] = static_cast<std::remove_pointer_t<decltype(index)>>(mesh.tetrahedra[k / 4][k % 4]);
  });
  py::array_t<std::int32_t> subdomains(static_cast<py::ssize_t>(mesh.subdomain.size()));
  std::copy(mesh.subdomain.begin(), mesh.subdomain.end(), subdomains.mutable_data());
  return py::make_tuple(points, tets, subdomains);
}

// How index_rows names an array in its messages: "<function>: <array> must
// be ...", "<function>: <row> K has vertex index I, not a row of <rows_of>".
struct Index_array_names
{
  const char* function;
  const char* array;
  const char* row;
  const char* rows_of;
};

// The rows of an (m, K) integer array, each an index into `rows` rows.
template <class Index, std::size_t K>
std::vector<std::array<Index, K>> index_rows(const py::handle& given, std::size_t rows, const Index_array_names& names)
{
  const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(given);
  if(!a || a.ndim() != 2 || a.shape(1) != static_cast<py::ssize_t>(K))
    throw py::value_error(std::string(names.function) + ": " + names.array + " must be an (m, " + std::to_string(K) +
                          ") integer array");
  std::vector<std::array<Index, K>> out(static_cast<std::size_t>(a.shape(0)));
  for(std::size_t k = 0; k < out.size(); ++k)
    for(std::size_t i = 0; i < K; ++i) {
      const std::int64_t index = a.data()[K * k + i];
      if(index < 0 || static_cast<std::uint64_t>(index) >= rows)
        throw py::value_error(std::string(names.function) + ": " + names.row + " " + std::to_string(k) +
                              " has vertex index " + std::to_string(index) + ", not a row of " + names.rows_of +
                              " (" + std::to_string(rows) + " rows)");
      out[k][i] = static_cast<Index>(index);
    }
  return out;
}

// remesh_surface: None, or the edge length the surfaces are remeshed to
// before they are meshed (Surface_remeshing.h).
CGAL::Fast_mesher_3::Surface_remeshing_options remeshing_options(const py::object& remesh_surface)
{
  CGAL::Fast_mesher_3::Surface_remeshing_options remeshing; // target_edge_length 0: no remeshing
  if(!remesh_surface.is_none()) {
    remeshing.target_edge_length = remesh_surface.cast<double>();
    if(!(remeshing.target_edge_length > 0) || std::isinf(remeshing.target_edge_length))
      throw py::value_error("mesh: remesh_surface must be a positive, finite edge length");
  }
  return remeshing;
}

py::tuple mesh(const py::handle& vertices, const py::handle& triangles, const py::object& size,
               const py::object& threads, bool optimize, const py::object& size_field, double min_dihedral_target,
               const py::object& remesh_surface)
{
  const CGAL::Fast_mesher_3::Mesher_options options =
      mesher_options(size, threads, optimize, size_field, min_dihedral_target);
  const CGAL::Fast_mesher_3::Surface_remeshing_options remeshing = remeshing_options(remesh_surface);
  const Double_array v = point_rows(vertices, "vertices");
  std::vector<std::array<double, 3>> points(static_cast<std::size_t>(v.shape(0)));
  if(!points.empty()) std::copy(v.data(), v.data() + 3 * v.shape(0), &points[0][0]);
  const auto tris =
      index_rows<std::size_t, 3>(triangles, points.size(), {"mesh", "triangles", "triangle", "vertices"});
  CGAL::Fast_mesher_3::Tetrahedral_mesh result;
  {
    py::gil_scoped_release unlocked;
    if(remeshing.target_edge_length > 0) {
      result = CGAL::Fast_mesher_3::mesh_remeshed_surfaces(points, tris, remeshing, options);
    } else {
      result = CGAL::Fast_mesher_3::mesh_surfaces(points, tris, options);
    }
  }
  return mesh_arrays(result);
}

// improve_mesh(points, tets, subdomains, triangles, ...): the mesher's
// improvement on a mesh of the caller's; (points, tets, subdomains, statistics).
py::tuple improve_mesh(const py::handle& points, const py::handle& tets, const py::object& subdomains,
                       const py::object& triangles, double quality_threshold, const py::object& threads,
                       bool add_points, int passes, double min_dihedral_target)
{
  CGAL::Fast_mesher_3::Mesher_options options;
  options.quality_threshold = quality_threshold;
  options.min_dihedral_target = min_dihedral_target;
  options.threads = thread_count(threads);
  options.improvement_adds_points = add_points;
  if(passes < 1) throw py::value_error("improve_mesh: passes must be at least 1, got " + std::to_string(passes));
  options.max_improvement_passes = passes;
  const Double_array v = point_rows(points, "improve_mesh: points");
  CGAL::Fast_mesher_3::Tetrahedral_mesh m;
  m.points.resize(static_cast<std::size_t>(v.shape(0)));
  if(!m.points.empty()) std::copy(v.data(), v.data() + 3 * v.shape(0), &m.points[0][0]);
  m.tetrahedra = index_rows<std::uint32_t, 4>(tets, m.points.size(), {"improve_mesh", "tets", "tets row", "points"});
  if(subdomains.is_none()) {
    m.subdomain.assign(m.tetrahedra.size(), 1);
  } else {
    const auto s = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>::ensure(subdomains);
    if(!s || s.ndim() != 1) throw py::value_error("improve_mesh: subdomains must be a 1-d integer array");
    m.subdomain.assign(s.data(), s.data() + s.shape(0)); // the count and the values are checked below
  }
  if(!triangles.is_none())
    m.triangles = index_rows<std::uint32_t, 3>(triangles, m.points.size(),
                                               {"improve_mesh", "triangles", "triangles row", "points"});
  CGAL::Fast_mesher_3::Improvement_statistics stats;
  {
    py::gil_scoped_release unlocked;
    stats = CGAL::Fast_mesher_3::improve_mesh(m, options);
  }
  py::dict report;
  report["bad_before"] = stats.bad_before;
  report["bad_after"] = stats.bad_after;
  report["min_gamma_before"] = stats.min_gamma_before;
  report["min_gamma_after"] = stats.min_gamma_after;
  report["min_dihedral_before"] = stats.min_dihedral_before;
  report["min_dihedral_after"] = stats.min_dihedral_after;
  report["steiner_points"] = stats.steiner_points;
  report["passes"] = stats.passes;
  report["seconds"] = stats.seconds;
  const py::tuple arrays = mesh_arrays(m);
  return py::make_tuple(arrays[0], arrays[1], arrays[2], report);
}

py::tuple mesh_files(const std::vector<std::string>& paths, const py::object& size, const py::object& threads,
                     bool optimize, const py::object& size_field, double min_dihedral_target,
                     const py::object& remesh_surface)
{
  const CGAL::Fast_mesher_3::Mesher_options options =
      mesher_options(size, threads, optimize, size_field, min_dihedral_target);
  const CGAL::Fast_mesher_3::Surface_remeshing_options remeshing = remeshing_options(remesh_surface);
  if(paths.empty()) throw py::value_error("mesh_files: no file given");
  CGAL::Fast_mesher_3::Tetrahedral_mesh result;
  {
    py::gil_scoped_release unlocked;
    if(remeshing.target_edge_length > 0) {
      result = CGAL::Fast_mesher_3::mesh_remeshed_surface_files(paths, remeshing, options);
    } else {
      result = CGAL::Fast_mesher_3::mesh_surface_files(paths, options);
    }
  }
  return mesh_arrays(result);
}
#endif

// delaunay(points, threads): the one-call form.
py::tuple delaunay(const py::handle& points, const py::object& threads)
{
  Row_triangulation t(thread_count(threads), false);
  t.insert(points);
  return t.take_finite_cells();
}

} // namespace fast_delaunay_3_python

PYBIND11_MODULE(_core, m)
{
  using namespace fast_delaunay_3_python;
  m.doc() = "Exact 3D Delaunay triangulations (CGAL's cells, computed by Fast_Delaunay_triangulation_3)";

  m.def("delaunay", &delaunay, py::arg("points"), py::arg("threads") = py::none(),
        R"(Delaunay triangulation of an (n, 3) array of points.

Returns (tets, neighbors): tets (m, 4) indices into `points` of the finite
tetrahedra, positively oriented, the same cells as CGAL's
Delaunay_triangulation_3; neighbors (m, 4): the tetrahedron across the facet
opposite vertex i, -1 on the convex hull.  Equal points are one vertex, named
by the first of them.  Indices are int32 (uint32 from 2^31 points on).
Fewer than 4 affinely independent points: no tetrahedra.  tets and neighbors
are the two halves of one (m, 8) array (views whose rows are 32 bytes apart:
the triangulation's own memory, handed over without a copy);
numpy.ascontiguousarray gives contiguous copies where a library needs them.
threads: Moore partitions inserted in parallel (None: all hardware threads).
A NaN or infinite coordinate raises ValueError naming the row.)");

  py::class_<Row_triangulation>(m, "Triangulation", R"(A Delaunay triangulation kept for several calls.

Vertices are named by rows: the rows of all the arrays inserted so far, in
order (the first array's rows are 0..n-1, the next array's follow); a row
equal to an earlier vertex's point names that vertex.)")
      .def(py::init([](const py::object& points, const py::object& threads) {
             Row_triangulation t(thread_count(threads));
             if(!points.is_none()) t.insert(points);
             return t;
           }),
           py::arg("points") = py::none(), py::arg("threads") = py::none())
      .def("insert", &Row_triangulation::insert, py::arg("points"),
           "Inserts an (n, 3) array; returns for each row the row naming its vertex.")
      .def("remove", &Row_triangulation::remove, py::arg("indices"),
           "Removes the vertices named by the rows `indices` (ValueError, nothing removed, for a row that names "
           "no vertex or is given twice).")
      .def("move", &Row_triangulation::move, py::arg("indices"), py::arg("points"),
           "Moves the vertices of `indices` to the rows of `points`; returns the row naming each afterwards "
           "(another vertex's if it landed on it: the moved one is then removed, as CGAL's move does).")
      .def("finite_cells", &Row_triangulation::finite_cells, "(tets, neighbors), as delaunay() returns them.")
      .def("hull_facets", &Row_triangulation::hull_facets,
           "(h, 3) rows of the convex hull's triangles, counterclockwise seen from outside.")
      .def("circumcenters", &Row_triangulation::circumcenters,
           "(m, 3) circumcentres of the finite cells, in finite_cells() order.")
      .def("voronoi",
           [](const Row_triangulation& t) { return py::make_tuple(t.circumcenters(), t.finite_cells()[1]); },
           "(vertices, neighbors): the Voronoi vertices (the circumcentres) and, per vertex, the four it is joined "
           "to by a Voronoi edge (-1: an unbounded edge, a ray).")
      .def("locate", &Row_triangulation::locate, py::arg("queries"),
           "For each row of a (k, 3) array, the finite cell containing it (finite_cells() order), -1 outside.")
      .def("nearest_vertex", &Row_triangulation::nearest_vertex, py::arg("queries"),
           "For each row of a (k, 3) array, the row of the nearest vertex.")
      .def_property_readonly("vertices", &Row_triangulation::vertex_rows, "The rows naming vertices, increasing.")
      .def_property_readonly("points",
                             [](const Row_triangulation& t) {
                               py::array_t<double> a({static_cast<py::ssize_t>(t.number_of_rows()), py::ssize_t(3)});
                               std::copy(t.rows().begin(), t.rows().end(), a.mutable_data());
                               return a;
                             },
                             "Every row inserted (a copy), moved vertices at their new place.")
      .def_property("threads", &Row_triangulation::threads,
                    [](Row_triangulation& t, const py::object& k) { t.set_threads(thread_count(k)); })
      .def_property_readonly("dimension", [](const Row_triangulation& t) { return t.delaunay().dimension(); })
      .def_property_readonly("number_of_vertices",
                             [](const Row_triangulation& t) { return t.delaunay().number_of_vertices(); })
      .def_property_readonly("number_of_finite_cells",
                             [](const Row_triangulation& t) { return t.delaunay().number_of_finite_cells(); })
      .def("is_valid", [](const Row_triangulation& t) { return t.delaunay().is_valid(); },
           "CGAL's is_valid(): combinatorics, orientation and the empty-sphere property.")
      .def(py::pickle([](const Row_triangulation& t) { return t.state(); },
                      [](const py::tuple& state) { return Row_triangulation::from_state(state); }));

#ifdef FDT3_PYTHON_WITH_MESHER
  const double default_dihedral_target = CGAL::Fast_mesher_3::Mesher_options().min_dihedral_target;
  // The remeshing's attempts and their shortening, from the library's values.
  static const std::string mesh_doc =
      std::string(R"(Tetrahedral mesh of the volumes bounded by closed triangulated surfaces.

vertices (n, 3), triangles (t, 3) indices into vertices.  Returns (points,
tets, subdomains): tets positively oriented, subdomain 1, 2, ... per
tetrahedron (one per volume).  size: maximum edge size (default: the
surface's own, interpolated), or a callable h(x, y, z) giving the size
where it is below the surface's (called from the mesher's threads, one at
a time under the GIL; an exception it raises ends the meshing as
RuntimeError, a value that is not a positive number raises ValueError).
size_field: a path to a size-field file, lines 'subdomain S H' (h at most
H in subdomain S) and 'X Y Z H' (background points: h at most the nearest
one's H); a malformed line raises ValueError naming it.  optimize: improve
the tetrahedra under gamma 0.3 or with a dihedral angle under
min_dihedral_target degrees (0: gamma alone; out of [0, 70] raises
ValueError).  remesh_surface: an edge length to remesh the surfaces to
first (CGAL's isotropic remeshing, each surface alone; edges where the
normals differ by over 60 degrees kept as polylines; up to )") +
      std::to_string(CGAL::Fast_mesher_3::Surface_remeshing_options().shortenings) + " times " +
      std::to_string(std::lround(100 * (1 - CGAL::Fast_mesher_3::remeshing_detail::shortening_factor))) + R"(%
shorter while walls narrower than the triangles leave bad tetrahedra with
four vertices on the surface); the boundary is then not the given
triangles, and where the surface is coarser than the size this removes the
flat tetrahedra its large triangles force.  A surface that is not closed, oriented,
manifold and free of self-intersections raises ValueError naming the
triangles.)";
  m.def("mesh", &mesh, py::arg("vertices"), py::arg("triangles"), py::arg("size") = py::none(),
        py::arg("threads") = py::none(), py::arg("optimize") = true, py::arg("size_field") = py::none(),
        py::arg("min_dihedral_target") = default_dihedral_target, py::arg("remesh_surface") = py::none(),
        mesh_doc.c_str());
  m.def("improve_mesh", &improve_mesh, py::arg("points"), py::arg("tets"), py::arg("subdomains") = py::none(),
        py::arg("triangles") = py::none(), py::arg("quality_threshold") = 0.3, py::arg("threads") = py::none(),
        py::arg("add_points") = true, py::arg("passes") = 10,
        py::arg("min_dihedral_target") = default_dihedral_target,
        R"(The mesher's improvement on a tetrahedral mesh of your own.

points (n, 3); tets (m, 4) indices into points, positively oriented;
subdomains (m,) integers from 1 (default: all 1); triangles (t, 3) facets to
keep besides the boundary and the facets between subdomains.  Flips, edge
removal, smoothing of interior points and (add_points) interior Steiner
points raise the quality gamma = 3 r_in / r_circ of the tetrahedra under
quality_threshold and the smallest dihedral angle of those under
min_dihedral_target degrees (0: gamma alone); the boundary, the listed triangles and the subdomain
interfaces stay exactly as given, their points do not move.  Returns
(points, tets, subdomains, statistics): the given points first (interior
ones possibly moved), then the added ones; statistics a dict (bad_before,
bad_after, min_gamma_before, min_gamma_after, min_dihedral_before,
min_dihedral_after in degrees, steiner_points, passes, seconds).  A mesh
it cannot take (an inverted or flat tetrahedron, an index out of range, a
facet in three tetrahedra, a boundary that is not closed, a triangle that
is not a facet) raises ValueError naming the defect.)");
  m.def("mesh_files", &mesh_files, py::arg("paths"), py::arg("size") = py::none(), py::arg("threads") = py::none(),
        py::arg("optimize") = true, py::arg("size_field") = py::none(),
        py::arg("min_dihedral_target") = default_dihedral_target, py::arg("remesh_surface") = py::none(),
        "mesh() of the surfaces in files (.off .stl .obj .ply).");
#endif
}
