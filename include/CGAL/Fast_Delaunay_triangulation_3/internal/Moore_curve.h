// Moore curve (closed Hilbert curve) index of a grid cell, and the map from coordinates to grid cells.
//
// Paper §2.3 ("Fast spatial sorting"): points are ordered along a space-filling curve so that consecutive insertions
// are close in space and the walk stays short. Paper §3.3: the parallel engine cuts the curve into runs of equal
// point counts and, to re-partition, distorts the grid (per-axis split) and shifts the start of the loop; a closed
// curve is what makes that circular shift harmless (HXT_FACTS §2 and §5).
//
// The index is table-driven: a finite-state machine whose states are cube symmetries. The tables are derived at
// compile time from two small searches (below), so no table is typed in by hand and nothing is built at run time.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_MOORE_CURVE_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_MOORE_CURVE_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace moore_detail {

// Octants and cube corners share one 3-bit code: bit a is the coordinate along axis a (x = bit 0).
//
// A cube symmetry maps corner v to P(v) xor f, where P sends bit a of v to bit perm[a]. It is encoded as
// permutation_index * 8 + f, so the 48 symmetries are the integers [0, 48).
constexpr int symmetry_count = 48;
constexpr int axis_permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

constexpr unsigned gray(unsigned i) { return i ^ (i >> 1); }

// The canonical curve visits the octants in Gray-code order, so it enters at corner 0 and leaves at corner gray(7):
// the two ends differ along axis 2 only, which every sub-curve orientation below relies on.
static_assert(gray(7) == 4u, "the canonical curve must leave along axis 2");

constexpr int permutation_index(int p0, int p1, int p2)
{
  for(int k = 0; k < 6; ++k)
    if(axis_permutations[k][0] == p0 && axis_permutations[k][1] == p1 && axis_permutations[k][2] == p2)
      return k;
  return -1;
}

constexpr unsigned apply(int symmetry, unsigned corner)
{
  const int* perm = axis_permutations[symmetry / 8];
  unsigned image = 0;
  for(int a = 0; a < 3; ++a)
    image |= ((corner >> a) & 1u) << perm[a];
  return image ^ unsigned(symmetry % 8);
}

// (s o t)(v) = P_s(P_t v xor f_t) xor f_s: the permutations compose and t's flip is carried through s.
constexpr int compose(int s, int t)
{
  const int* ps = axis_permutations[s / 8];
  const int* pt = axis_permutations[t / 8];
  return permutation_index(ps[pt[0]], ps[pt[1]], ps[pt[2]]) * 8 + int(apply(s, unsigned(t % 8)));
}

// The symmetry that places the canonical sub-curve (corner 0 -> corner gray(7)) so that it enters its sub-cube at
// `entry` and leaves at `exit`, two corners of one edge. Two symmetries do that (the other two axes may be swapped);
// `option` picks one, and the searches below use that freedom to keep the number of states small.
constexpr int sub_curve_symmetry(unsigned entry, unsigned exit, int option)
{
  const unsigned edge = entry ^ exit;
  const int along = edge == 1u ? 0 : (edge == 2u ? 1 : 2);
  const int first = (along + 1 + option) % 3;
  const int second = (along + 2 - option) % 3;
  return permutation_index(first, second, along) * 8 + int(entry);
}

// Entry and exit corners (local to each octant's sub-cube) of the 8 sub-curves of one level.
struct Octant_path
{
  unsigned entry[8] = {};
  unsigned exit[8] = {};
};

// Every valid path: 3D has 5 open and 81 closed ones.
constexpr int max_paths = 96;
struct Path_list
{
  Octant_path path[max_paths];
  int count = 0;
};

// Depth-first over the octants in Gray order, the sub-curve in octant i leaving along one of 3 axes. Consecutive
// sub-curves must meet: the exit corner of one is a corner of the next sub-cube, which makes the two grid cells there
// face-adjacent at every resolution. A Hilbert curve must end at the outer corner gray(7); a Moore curve must come
// back to its own start.
constexpr void extend_paths(bool closed, unsigned i, unsigned entry, Octant_path& partial, Path_list& out)
{
  for(unsigned axis = 0; axis < 3; ++axis) {
    const unsigned exit = entry ^ (1u << axis);
    partial.entry[i] = entry;
    partial.exit[i] = exit;
    if(i == 7 && !closed) {
      if(exit == gray(7) && out.count < max_paths)
        out.path[out.count++] = partial;
      continue;
    }
    const unsigned next_octant = gray((i + 1) % 8);
    unsigned next_entry = 0;
    bool meets = true;
    for(int a = 0; a < 3; ++a) {
      // In units of one sub-cube the meeting point has coordinate octant bit + corner bit, in 0..2.
      const int offset = int((gray(i) >> a) & 1u) + int((exit >> a) & 1u) - int((next_octant >> a) & 1u);
      meets = meets && offset >= 0 && offset <= 1;
      next_entry |= unsigned(offset & 1) << a;
    }
    if(!meets)
      continue;
    if(i < 7)
      extend_paths(closed, i + 1, next_entry, partial, out);
    else if(next_entry == partial.entry[0] && out.count < max_paths)
      out.path[out.count++] = partial;
  }
}

constexpr Path_list octant_paths(bool closed)
{
  Path_list out;
  for(unsigned first_entry = 0; first_entry < (closed ? 8u : 1u); ++first_entry) {
    Octant_path partial;
    extend_paths(closed, 0u, first_entry, partial, out);
  }
  return out;
}

struct Symmetry_table
{
  int composed[symmetry_count][symmetry_count] = {};
};

constexpr Symmetry_table make_symmetry_table()
{
  Symmetry_table table;
  for(int s = 0; s < symmetry_count; ++s)
    for(int t = 0; t < symmetry_count; ++t)
      table.composed[s][t] = compose(s, t);
  return table;
}

// The two searches' result: how each level subdivides, and the finite set of orientations (states) it produces.
struct Curve_rules
{
  int hilbert_child[8] = {};   // orientation of the i-th visited octant relative to its parent (Hilbert levels)
  int moore_child[8] = {};     // orientation of the i-th visited octant at the top (Moore) level
  int state_symmetry[symmetry_count] = {};
  int hilbert_states = 0;      // states reachable below the top level; the Moore top level is one more state
};

// Orientations reachable from `start` by descending levels (BFS); returns how many, listed in `states`, or stops
// early with a count above `limit`.
constexpr int reachable_orientations(const Symmetry_table& table, const int (&children)[8], const int* start,
                                     int start_count, int (&states)[symmetry_count], int limit = symmetry_count)
{
  bool seen[symmetry_count] = {};
  int count = 0;
  for(int k = 0; k < start_count; ++k)
    if(!seen[start[k]]) {
      seen[start[k]] = true;
      states[count++] = start[k];
    }
  for(int head = 0; head < count && count <= limit; ++head)
    for(int i = 0; i < 8; ++i) {
      const int next = table.composed[states[head]][children[i]];
      if(!seen[next]) {
        seen[next] = true;
        states[count++] = next;
      }
    }
  return count;
}

constexpr Curve_rules find_curve_rules()
{
  const Symmetry_table table = make_symmetry_table();
  Curve_rules rules;

  // Hilbert levels: among all valid paths and sub-curve orientations, keep the one with the fewest states, since
  // the 9-bit lookup table has 512 entries per state and should stay in L1.
  int best_count = symmetry_count + 1;
  int best_states[symmetry_count] = {};
  const Path_list open_paths = octant_paths(false);
  for(int k = 0; k < open_paths.count; ++k) {
    const Octant_path& path = open_paths.path[k];
    for(int options = 0; options < 256; ++options) {
      int children[8] = {};
      for(int i = 0; i < 8; ++i)
        children[i] = sub_curve_symmetry(path.entry[i], path.exit[i], (options >> i) & 1);
      int states[symmetry_count] = {};
      const int identity = 0;
      const int count = reachable_orientations(table, children, &identity, 1, states, best_count - 1);
      if(count < best_count) {
        best_count = count;
        for(int i = 0; i < 8; ++i)
          rules.hilbert_child[i] = children[i];
        for(int j = 0; j < count; ++j)
          best_states[j] = states[j];
      }
    }
  }

  // Moore top level: a closed path whose sub-curves all use orientations already among the Hilbert states, so the
  // closed curve costs a single extra state (its top level) and no larger table.
  bool in_hilbert_set[symmetry_count] = {};
  for(int k = 0; k < best_count; ++k)
    in_hilbert_set[best_states[k]] = true;
  const Path_list closed_paths = octant_paths(true);
  bool found = false;
  for(int k = 0; k < closed_paths.count && !found; ++k) {
    const Octant_path& path = closed_paths.path[k];
    bool all_known = true;
    for(int i = 0; i < 8 && all_known; ++i) {
      const int option0 = sub_curve_symmetry(path.entry[i], path.exit[i], 0);
      const int option1 = sub_curve_symmetry(path.entry[i], path.exit[i], 1);
      if(in_hilbert_set[option0])
        rules.moore_child[i] = option0;
      else if(in_hilbert_set[option1])
        rules.moore_child[i] = option1;
      else
        all_known = false;
    }
    found = all_known;
  }
  if(!found)
    return Curve_rules{};   // hilbert_states == 0 fails the static_assert below

  rules.hilbert_states =
    reachable_orientations(table, rules.hilbert_child, rules.moore_child, 8, rules.state_symmetry);
  return rules;
}

inline constexpr Curve_rules curve_rules = find_curve_rules();
static_assert(curve_rules.hilbert_states > 0 && curve_rules.hilbert_states <= 12,
              "the 3D Hilbert curve has a 12-orientation form, and the closed top level must reuse it");

constexpr int state_count = curve_rules.hilbert_states + 1;
constexpr int top_state = curve_rules.hilbert_states;   // the Moore level, always the first one descended

// Entries pack the index digits in the low bits and the next state above them.
struct Moore_tables
{
  std::uint8_t one_level[state_count][8] = {};        // 3-bit digit | next state << 3
  std::uint16_t three_levels[state_count][512] = {};  // 9 bits of digits | next state << 9
};

struct Step
{
  unsigned digit;
  int next_state;
};

constexpr int state_of(const Curve_rules& rules, int symmetry)
{
  for(int k = 0; k < rules.hilbert_states; ++k)
    if(rules.state_symmetry[k] == symmetry)
      return k;
  return -1;
}

// One level down from `state` into the world octant `octant`: the rank of that octant along the curve, and the state
// of the sub-curve inside it. A state's symmetry s places the i-th visited octant at s(gray(i)).
constexpr Step step(const Curve_rules& rules, int state, unsigned octant)
{
  const bool top = state == top_state;
  const int symmetry = top ? 0 : rules.state_symmetry[state];
  for(unsigned i = 0; i < 8; ++i)
    if(apply(symmetry, gray(i)) == octant) {
      const int child = top ? rules.moore_child[i] : compose(symmetry, rules.hilbert_child[i]);
      return {i, state_of(rules, child)};
    }
  return {0u, -1};
}

// Three levels per lookup take the 9 bits (x2 x1 x0 | y2 y1 y0 << 3 | z2 z1 z0 << 6) straight from the cell
// coordinates, so no bit interleaving is needed before the lookup.
constexpr Moore_tables make_moore_tables(const Curve_rules& rules)
{
  Moore_tables tables;
  for(int state = 0; state < state_count; ++state)
    for(unsigned octant = 0; octant < 8; ++octant) {
      const Step s = step(rules, state, octant);
      tables.one_level[state][octant] = std::uint8_t(s.digit | unsigned(s.next_state) << 3);
    }
  for(int state = 0; state < state_count; ++state) {
    for(unsigned bits = 0; bits < 512; ++bits) {
      int current = state;
      unsigned digits = 0;
      for(int level = 2; level >= 0; --level) {
        const unsigned octant = ((bits >> level) & 1u) | ((bits >> (3 + level)) & 1u) << 1 |
                                ((bits >> (6 + level)) & 1u) << 2;
        const unsigned entry = tables.one_level[current][octant];
        digits = digits << 3 | (entry & 7u);
        current = int(entry >> 3);
      }
      tables.three_levels[state][bits] = std::uint16_t(digits | unsigned(current) << 9);
    }
  }
  return tables;
}

// Every descent lands on a known state; otherwise a table entry would hold a garbage state number.
constexpr bool every_step_has_a_state(const Curve_rules& rules)
{
  for(int state = 0; state < state_count; ++state)
    for(unsigned octant = 0; octant < 8; ++octant)
      if(step(rules, state, octant).next_state < 0)
        return false;
  return true;
}
static_assert(every_step_has_a_state(curve_rules), "the state set must be closed under descent");

inline constexpr Moore_tables moore_tables = make_moore_tables(curve_rules);

} // namespace moore_detail

// Closed Hilbert curve on a 2^b x 2^b x 2^b grid, 1 <= b <= 21, so that the index (3b bits) fits in 63 bits.
// Consecutive indices are face-adjacent cells, and so are the last and the first cell.
class Moore_curve
{
public:
  static constexpr int max_bits_per_axis = 21;

  explicit Moore_curve(int bits_per_axis)
    : bits_(bits_per_axis), single_levels_(bits_per_axis % 3)
  {
    CGAL_precondition(bits_per_axis >= 1 && bits_per_axis <= max_bits_per_axis);
  }

  int bits_per_axis() const { return bits_; }

  std::uint64_t index(std::uint32_t x, std::uint32_t y, std::uint32_t z) const
  {
    CGAL_precondition(x >> bits_ == 0 && y >> bits_ == 0 && z >> bits_ == 0);
    const auto& tables = moore_detail::moore_tables;
    unsigned state = unsigned(moore_detail::top_state);
    std::uint64_t digits = 0;
    int shift = bits_;
    // The levels that do not fill a group of three go first, so the Moore level is always descended from the top
    // state whatever b is, and the remaining levels are whole 9-bit lookups.
    for(int k = 0; k < single_levels_; ++k) {
      --shift;
      const unsigned octant = ((x >> shift) & 1u) | ((y >> shift) & 1u) << 1 | ((z >> shift) & 1u) << 2;
      const unsigned entry = tables.one_level[state][octant];
      digits = digits << 3 | (entry & 7u);
      state = entry >> 3;
    }
    while(shift > 0) {
      shift -= 3;
      const unsigned bits = ((x >> shift) & 7u) | ((y >> shift) & 7u) << 3 | ((z >> shift) & 7u) << 6;
      const unsigned entry = tables.three_levels[state][bits];
      digits = digits << 9 | (entry & 511u);
      state = entry >> 9;
    }
    return digits;
  }

private:
  int bits_;
  int single_levels_;
};

// About ceil(log2(n) / 3) + 2 bits per axis: 8^(b-2) >= n cells, i.e. at least 64 cells per point, enough to
// separate almost all points (paper §2.3: m = k log2 n keeps the points per cell constant) while the keys stay
// short for the radix sort (27 bits for 1e6 points instead of HXT's fixed 63).
inline int moore_bits_per_axis(std::size_t n)
{
  int levels = 0;
  std::size_t cells = 1;
  while(cells < n && levels < Moore_curve::max_bits_per_axis) {
    ++levels;
    cells = cells > (std::numeric_limits<std::size_t>::max() >> 3) ? std::numeric_limits<std::size_t>::max()
                                                                   : cells << 3;
  }
  return std::min(std::max(levels + 2, 1), Moore_curve::max_bits_per_axis);
}

// Maps coordinates to grid cells of a Moore curve.
//
// The box is made nearly cubic (an axis thinner than 1/1.5 of the widest is widened about its centre) so that flat
// inputs do not get needle-shaped cells, which would break the locality of the curve. Each axis is mapped piecewise
// linearly: [lo, lo + split (hi - lo)] onto the lower half of the grid, the rest onto the upper half; split = 0.5 is
// the plain uniform grid, other values compress one side and stretch the other (paper §3.3 re-partitioning).
// The lo/hi of the split are those of the widened box.
class Moore_grid
{
public:
  Moore_grid(const double lo[3], const double hi[3], int bits_per_axis, const double split[3] = nullptr)
    : bits_(bits_per_axis),
      half_cells_(double(std::uint32_t(1) << (bits_per_axis - 1))),
      cells_(double(std::uint64_t(1) << bits_per_axis)),
      max_cell_((std::uint32_t(1) << bits_per_axis) - 1)
  {
    CGAL_precondition(bits_per_axis >= 1 && bits_per_axis <= Moore_curve::max_bits_per_axis);
    double center[3] = {}, half[3] = {};
    double widest = 0;
    for(int a = 0; a < 3; ++a) {
      CGAL_precondition(lo[a] <= hi[a]);
      // Halving first keeps hi - lo from overflowing for boxes spanning most of the double range.
      center[a] = 0.5 * lo[a] + 0.5 * hi[a];
      half[a] = 0.5 * hi[a] - 0.5 * lo[a];
      widest = std::max(widest, half[a]);
    }
    for(int a = 0; a < 3; ++a) {
      // The smallest normal double as a floor keeps 1 / half finite for a box that is a single point.
      const double h = std::max({half[a], widest / 1.5, std::numeric_limits<double>::min()});
      const double s = split ? split[a] : 0.5;
      CGAL_precondition(s > 0 && s < 1);
      Axis_map& m = axis_[a];
      m.center = center[a];
      m.inv_half = 1.0 / h;
      m.split = 2 * s - 1;
      m.start[0] = -1;
      m.start[1] = m.split;
      m.first_cell[0] = 0;
      m.first_cell[1] = half_cells_;
      m.scale[0] = half_cells_ / (2 * s);
      m.scale[1] = half_cells_ / (2 * (1 - s));
    }
  }

  int bits_per_axis() const { return bits_; }

  std::uint32_t cell(int axis, double coordinate) const
  {
    CGAL_precondition(axis >= 0 && axis < 3);
    const Axis_map& m = axis_[axis];
    // u is in [-1, 1] inside the box; far outside it may be infinite, and NaN stays NaN.
    const double u = (coordinate - m.center) * m.inv_half;
    // The side is an index, not a branch: for random points a branch here is mispredicted half of the time, which
    // measured 3x slower keys (25 ms instead of 8 ms for 1e6 points).
    const int side = u >= m.split;
    const double g = m.first_cell[side] + (u - m.start[side]) * m.scale[side];
    // Converting a negative, too large or NaN double to an unsigned is undefined, hence the clamp before the cast;
    // the comparisons are written so that NaN lands in cell 0.
    if(!(g >= 0))
      return 0;
    if(g >= cells_)
      return max_cell_;
    return static_cast<std::uint32_t>(g);
  }

  std::uint64_t key(const Moore_curve& curve, const double p[3]) const
  {
    CGAL_precondition(curve.bits_per_axis() == bits_);
    return curve.index(cell(0, p[0]), cell(1, p[1]), cell(2, p[2]));
  }

private:
  struct Axis_map
  {
    double center;
    double inv_half;
    double split;          // the split point in u coordinates, 2 s - 1
    double start[2];       // per side of the split: where the piece starts in u,
    double first_cell[2];  // the grid coordinate it starts at,
    double scale[2];       // and grid cells per unit of u
  };

  Axis_map axis_[3];
  int bits_;
  double half_cells_;
  double cells_;
  std::uint32_t max_cell_;
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_MOORE_CURVE_H
