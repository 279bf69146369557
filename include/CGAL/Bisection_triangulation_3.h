// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_BISECTION_TRIANGULATION_3_H
#define CGAL_BISECTION_TRIANGULATION_3_H

#include <CGAL/number_utils.h>
#include <CGAL/determinant.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/ISM_reconstruction_3/internal/Block_array.h>
#include <CGAL/ISM_reconstruction_3/internal/memory_budget.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgISMReconstruction3Ref

\brief A binary multitriangulation (BMT): a parallelepiped split into 6 tetrahedra
around one main diagonal, refined by conforming bisection.

Every cell (tetrahedron) knows its parent, its two children, its level and its four
vertices; the leaves form a conforming tetrahedral mesh of the box (no hanging vertex,
every interior triangle shared by exactly two leaves).

The refinement edge of a cell is chosen combinatorially, by Maubach's vertex ordering:
a cell `[x0,x1,x2,x3]` of level `l` is bisected along the edge `x0 x_k` with
`k = 3 - (l mod 3)`, its children being `[x0..x_{k-1}, z, x_{k+1}..x3]` and
`[x1..x_k, z, x_{k+1}..x3]`. On the 6 Kuhn tetrahedra of a cube this is longest-edge
bisection; because it never compares rounded lengths, refinement terminates, the leaves
stay conforming and all cells fall into a bounded number of similarity classes,
whatever floating point does.

Cells and vertices are integers indexing flat arrays; a bisected cell stays in the
tree as an inner cell, so cell indices are stable.

\tparam GeomTraits a model of `BisectionTriangulationTraits_3` (`Point_3`, `Vector_3`,
`Iso_cuboid_3`, `Orientation_3`, `Construct_midpoint_3`); every \cgal `Kernel` is one.
*/
template <class GeomTraits>
class Bisection_triangulation_3
{
public:
  /// \name Types
  /// @{
  /*! the geometric traits class */
  typedef GeomTraits Geom_traits;
  /// the number type of the coordinates
  typedef typename Geom_traits::FT FT;
  /// the point type
  typedef typename Geom_traits::Point_3 Point_3;
  /// the vector type
  typedef typename Geom_traits::Vector_3 Vector_3;
  /// the axis-aligned box type
  typedef typename Geom_traits::Iso_cuboid_3 Iso_cuboid_3;
  /// index of a cell (tetrahedron) of the tree; `-1` means none
  typedef std::int32_t Cell_index;
  /// index of a vertex
  typedef std::int32_t Vertex_index;
  /// @}

  /// The deepest level a cell can have. Edges shrink by 2 every 3 levels, so at this
  /// level they are 2^-32 of the box: far beyond any data, still far from double's limits.
  static constexpr int maximum_level() { return 96; }

private:
  // Bit 7 of m_level_and_parity holds the orientation parity of a cell relative to
  // the geometric orientation of its vertex order, so that export can orient every leaf
  // positively without a predicate.
  static constexpr std::uint8_t parity_bit = 0x80;

  Geom_traits m_gt;
  std::vector<Point_3> m_points;
  // One record per cell, so that creating a cell is one append; the level byte lives
  // apart to keep the record at 40 bytes.
  struct Cell
  {
    std::array<Vertex_index, 4> vertices;
    std::array<Cell_index, 4> neighbors;  // valid for leaves only
    Cell_index parent;
    Cell_index first_child;               // children are consecutive; -1 for a leaf
  };
  ISM_reconstruction_3::internal::Block_array<Cell> m_cells;
  ISM_reconstruction_3::internal::Block_array<std::uint8_t> m_level_and_parity;
  std::size_t m_number_of_leaves = 0;

  // scratch buffers of bisect(), kept to avoid allocations on the hot path
  std::vector<Cell_index> m_patch;

public:
  /// \name Creation
  /// @{

  /// Splits the axis-aligned box `box` into 6 tetrahedra around its diagonal from
  /// `box.min()` to `box.max()`.
  /// \throws std::invalid_argument if the box is flat or has a non-finite coordinate.
  explicit Bisection_triangulation_3(const Iso_cuboid_3& box, const Geom_traits& gt = Geom_traits())
    : m_gt(gt)
  {
    // written as !(d > 0) so that a NaN extent fails too
    const double extent[] = { to_double(box.xmax()) - to_double(box.xmin()),
                              to_double(box.ymax()) - to_double(box.ymin()),
                              to_double(box.zmax()) - to_double(box.zmin()) };
    for(double d : extent)
      if(!(d > 0) || !std::isfinite(d))
        throw std::invalid_argument("Bisection_triangulation_3: the box is flat or has non-finite coordinates");
    const Vector_3 a(box.xmax() - box.xmin(), 0, 0), b(0, box.ymax() - box.ymin(), 0),
                   c(0, 0, box.zmax() - box.zmin());
    initialize((box.min)(), a, b, c);
  }

  /// Splits the parallelepiped `{origin + s a + t b + u c | s,t,u in [0,1]}` into 6
  /// tetrahedra around its diagonal from `origin` to `origin + a + b + c`.
  /// \throws std::invalid_argument if the parallelepiped is flat or has a non-finite coordinate.
  Bisection_triangulation_3(const Point_3& origin, const Vector_3& a, const Vector_3& b,
                            const Vector_3& c, const Geom_traits& gt = Geom_traits())
    : m_gt(gt)
  {
    initialize(origin, a, b, c);
  }
  /// @}

  /// \name Access
  /// @{
  /*! the geometric traits */
  const Geom_traits& geom_traits() const { return m_gt; }
  /// the number of cells of the tree, leaves and inner cells; cells are indexed from `0`
  std::size_t number_of_cells() const { return m_cells.size(); }
  /// the number of leaves (the tetrahedra of the current mesh)
  std::size_t number_of_leaves() const { return m_number_of_leaves; }
  /// the number of vertices; vertices are indexed from `0`, the 8 box corners first
  std::size_t number_of_vertices() const { return m_points.size(); }

  /// the point of vertex `v`
  const Point_3& point(Vertex_index v) const { return m_points[v]; }
  /// the points of all vertices, indexed by vertex
  const std::vector<Point_3>& points() const { return m_points; }

  /// `true` if `c` has not been bisected
  bool is_leaf(Cell_index c) const { return m_cells[c].first_child < 0; }
  /// the level of `c`: `0` for the 6 roots, one more than its parent's otherwise
  int level(Cell_index c) const { return m_level_and_parity[c] & ~parity_bit; }
  /// the parent of `c`, `-1` for the 6 roots (cells `0` to `5`)
  Cell_index parent(Cell_index c) const { return m_cells[c].parent; }
  /// child `i` (`0` or `1`) of an inner cell; child 0 holds `vertex(c,0)`.
  Cell_index child(Cell_index c, int i) const { return m_cells[c].first_child < 0 ? -1 : m_cells[c].first_child + i; }
  /// vertex `i` (`0` to `3`) of `c`, in Maubach's order
  Vertex_index vertex(Cell_index c, int i) const { return m_cells[c].vertices[i]; }
  /// the four vertices of `c`, in Maubach's order (not necessarily positively oriented,
  /// see `positive_vertices()`)
  const std::array<Vertex_index, 4>& vertices(Cell_index c) const { return m_cells[c].vertices; }

  /// local index `k` such that the refinement edge of `c` is `(vertex(c,0), vertex(c,k))`
  static int refinement_index(int level) { return 3 - level % 3; }
  /// the refinement edge of `c`, as two vertex indices
  std::array<Vertex_index, 2> refinement_edge(Cell_index c) const
  {
    return {{ m_cells[c].vertices[0], m_cells[c].vertices[refinement_index(level(c))] }};
  }

  /// the leaf sharing the face of leaf `c` opposite to its local vertex `i`,
  /// `-1` on the boundary of the box
  Cell_index neighbor(Cell_index c, int i) const { return m_cells[c].neighbors[i]; }

  /// `true` if the vertex order of `c` is positively oriented (CGAL's `orientation`).
  bool is_positively_oriented(Cell_index c) const { return (m_level_and_parity[c] & parity_bit) == 0; }

  /// the four vertices of `c` ordered so that the tetrahedron is positively oriented
  std::array<Vertex_index, 4> positive_vertices(Cell_index c) const
  {
    std::array<Vertex_index, 4> v = m_cells[c].vertices;
    if(!is_positively_oriented(c))
      std::swap(v[2], v[3]);
    return v;
  }

  /// the leaves, in increasing index order
  std::vector<Cell_index> leaves() const
  {
    std::vector<Cell_index> result;
    result.reserve(m_number_of_leaves);
    for(Cell_index c = 0; c < Cell_index(number_of_cells()); ++c)
      if(is_leaf(c))
        result.push_back(c);
    return result;
  }
  /// @}

  /// \name Refinement
  /// @{

  /*!
    Bisects the leaf `c` conformingly: whatever leaves around its refinement edge do not
    have that edge as refinement edge are bisected first (recursively), then every leaf
    around the edge is bisected at its midpoint. `on_bisect(parent, child0, child1)` is
    called for every cell bisected, in order, so that a caller can distribute data
    (e.g. points) to the children.
    \throws std::length_error if the cell or vertex count would overflow the indices
    \throws std::domain_error if a cell would exceed `maximum_level()`, or if a midpoint rounds
    so that a child would be flat or inverted (cells too small for the precision of their
    coordinates); the mesh stays conforming, as it does when `on_bisect` throws
  */
  template <class OnBisect>
  void bisect(Cell_index c, OnBisect&& on_bisect)
  {
    if(c < 0 || c >= Cell_index(number_of_cells()) || !is_leaf(c))
      throw std::invalid_argument("Bisection_triangulation_3::bisect: not a leaf");
    if(level(c) >= maximum_level())
      throw std::domain_error("Bisection_triangulation_3::bisect: maximum level " +
                              std::to_string(maximum_level()) + " reached");
    bisect_recursively(c, on_bisect);
  }

  /// Bisects the leaf `c` conformingly, as `bisect(c, on_bisect)` without a callback.
  void bisect(Cell_index c) { bisect(c, [](Cell_index, Cell_index, Cell_index) {}); }

  /*!
    Bisects, conformingly, every leaf of level below `max_level` for which
    `must_refine(c)` is `true`, and then the new leaves, until no leaf qualifies.
    `on_bisect` is called as in `bisect()`.
  */
  template <class MustRefine, class OnBisect>
  void refine(MustRefine&& must_refine, int max_level, OnBisect&& on_bisect)
  {
    check_level(max_level);
    std::vector<Cell_index> stack = leaves();
    std::reverse(stack.begin(), stack.end());
    while(!stack.empty())
    {
      const Cell_index c = stack.back();
      stack.pop_back();
      if(!is_leaf(c) || level(c) >= max_level || !must_refine(c))
        continue;
      bisect(c, [&](Cell_index p, Cell_index c0, Cell_index c1) {
        on_bisect(p, c0, c1);
        stack.push_back(c1);
        stack.push_back(c0);
      });
    }
  }

  /// Refines as `refine(must_refine, max_level, on_bisect)` without a callback.
  template <class MustRefine>
  void refine(MustRefine&& must_refine, int max_level)
  {
    refine(must_refine, max_level, [](Cell_index, Cell_index, Cell_index) {});
  }

  /// Bisects every leaf until all leaves have level `l` (6 * 2^l leaves).
  /// \throws std::length_error if that many cells cannot be indexed, or, before allocating
  /// them, if they would need more memory than the process may use (physical memory,
  /// `ulimit -v` and `-d`, cgroup limits)
  void refine_uniformly(int l)
  {
    check_level(l);
    const double cells = 12. * std::ldexp(1., l);
    if(cells > double((std::numeric_limits<Cell_index>::max)()))
      throw std::length_error("Bisection_triangulation_3::refine_uniformly: level " + std::to_string(l) +
                              " needs more cells than the indices can hold");
    // the arrays reserved below, and the growth of the other ones: levels 26 and 27 (35 and
    // 70 GB) had been left to std::bad_alloc, or to the OOM killer where memory is overcommitted
    const double needed = 1.25 * (cells * double(sizeof(Cell) + 1) + std::ldexp(1., l) * double(sizeof(Point_3)));
    const ISM_reconstruction_3::internal::Memory_budget budget = ISM_reconstruction_3::internal::available_memory();
    if(needed > double(budget.bytes))
      throw std::length_error("Bisection_triangulation_3::refine_uniformly: level " + std::to_string(l) + " needs about " +
                              ISM_reconstruction_3::internal::format_bytes(needed) + ", but this process may use only " +
                              ISM_reconstruction_3::internal::format_bytes(double(budget.bytes)) + " more (limited by " +
                              budget.limited_by + ")");
    m_cells.reserve(std::size_t(cells));
    m_level_and_parity.reserve(std::size_t(cells));
    m_points.reserve(std::size_t(std::ldexp(1., l) + 64));
    refine([](Cell_index) { return true; }, l);
  }
  /// @}

  /// \name Point location
  /// @{

  /// `0` or `1`: the child of the inner cell `c` on whose side of the bisecting plane
  /// `p` lies (points on the plane go to child 0).
  int child_side(Cell_index c, const Point_3& p) const
  {
    const std::array<Vertex_index, 4>& v = m_cells[c].vertices;
    const int k = refinement_index(level(c));
    const Point_3& z = m_points[m_cells[m_cells[c].first_child].vertices[k]];
    const int j1 = (k == 1) ? 2 : 1, j2 = (k == 3) ? 2 : 3;
    const Orientation op = m_gt.orientation_3_object()(p, z, m_points[v[j1]], m_points[v[j2]]);
    if(op == COPLANAR) return 0;
    // v0 is on child 0's side: orientation(v0, z, v_j1, v_j2) = orientation(v0, v_k, v_j1, v_j2)
    // (z halves the edge v0 v_k), the cell's own orientation permuted, odd for k = 2. Read
    // from the parity bit instead of a second predicate: point location costs one per level.
    const Orientation v0_side = (is_positively_oriented(c) != (k == 2)) ? POSITIVE : NEGATIVE;
    CGAL_assertion(v0_side == m_gt.orientation_3_object()(m_points[v[0]], z, m_points[v[j1]], m_points[v[j2]]));
    return op == v0_side ? 0 : 1;
  }

  /// `true` if `p` lies in the closed tetrahedron `c`
  bool has_on(Cell_index c, const Point_3& p) const
  {
    const std::array<Vertex_index, 4> v = positive_vertices(c);
    typename Geom_traits::Orientation_3 orientation = m_gt.orientation_3_object();
    const Point_3 &a = m_points[v[0]], &b = m_points[v[1]], &cc = m_points[v[2]], &d = m_points[v[3]];
    return orientation(p, b, cc, d) != NEGATIVE && orientation(a, p, cc, d) != NEGATIVE &&
           orientation(a, b, p, d) != NEGATIVE && orientation(a, b, cc, p) != NEGATIVE;
  }

  /// the root (0 to 5) containing `p`, or `-1` if `p` is outside the box; a point outside
  /// every root by less than 1e-9 of its size (barycentric) counts as in the nearest one
  Cell_index locate_root(const Point_3& p) const
  {
    // refused here rather than deep in a filter
    if(!is_finite(p))
      return -1;
    for(Cell_index r = 0; r < 6; ++r)
      if(has_on(r, p))
        return r;
    return nearly_containing_root(p);
  }

  /// \cond SKIP_IN_MANUAL
  // Why: the box's edge midpoints are rounded with inexact constructions, so vertices of the
  // triangulation on the box's boundary can lie just outside it; with an inexact kernel
  // (Simple_cartesian<double>) the predicates round too, and a point on a face shared by two
  // roots can test outside both. The root whose smallest barycentric coordinate of `p` is
  // largest holds it if that coordinate is above -1e-9 (computed in doubles).
  Cell_index nearly_containing_root(const Point_3& p) const
  {
    typedef std::array<double, 3> D3;
    const auto xyz = [](const Point_3& q) { return D3{{ to_double(q.x()), to_double(q.y()), to_double(q.z()) }}; };
    const auto volume = [](const D3& a, const D3& b, const D3& c, const D3& d) {
      return CGAL::determinant(b[0] - a[0], b[1] - a[1], b[2] - a[2], c[0] - a[0], c[1] - a[1], c[2] - a[2],
                               d[0] - a[0], d[1] - a[1], d[2] - a[2]);
    };
    const D3 x = xyz(p);
    Cell_index best = -1;
    double best_coordinate = -1e-9;
    for(Cell_index r = 0; r < 6; ++r)
    {
      const std::array<Vertex_index, 4> v = positive_vertices(r);
      D3 q[4];
      for(int i = 0; i < 4; ++i) q[i] = xyz(m_points[v[i]]);
      const double whole = volume(q[0], q[1], q[2], q[3]);
      if(!(whole > 0)) continue;
      double smallest = HUGE_VAL;
      for(int i = 0; i < 4; ++i)
      {
        D3 with_p[4] = { q[0], q[1], q[2], q[3] };
        with_p[i] = x;
        smallest = (std::min)(smallest, volume(with_p[0], with_p[1], with_p[2], with_p[3]) / whole);
      }
      if(smallest >= best_coordinate)
      {
        best_coordinate = smallest;
        best = r;
      }
    }
    return best;
  }
  /// \endcond

  /// the leaf containing `p`, found by descending the cell tree from its root in O(level).
  /// \throws std::out_of_range if `p` is outside the box
  Cell_index locate(const Point_3& p) const
  {
    if(!is_finite(p))
      throw std::invalid_argument("Bisection_triangulation_3::locate: the point has a non-finite coordinate");
    Cell_index c = locate_root(p);
    if(c < 0)
      throw std::out_of_range("Bisection_triangulation_3::locate: the point is outside the box");
    while(!is_leaf(c))
      c = m_cells[c].first_child + child_side(c, p);
    // Rounded midpoints lie off their edges by an ulp, so two children cover their parent
    // only up to slivers that thin: a point within rounding of a face can descend into the
    // leaf beside its own (60 of 576 edge midpoints of a box with decimal corners). The walk
    // confirms the leaf in one step, or crosses to the right one.
    const Cell_index w = walk_to(p, c, 8);
    return w >= 0 ? w : c;
  }

  /// the leaf containing `p`, found by walking across the faces of the leaves from the leaf
  /// `hint`: a few steps when `hint` is near `p`, where `locate(p)` descends O(level) cells.
  /// Falls back to `locate(p)` when `hint` is not a leaf or the walk is long.
  /// \throws std::out_of_range if `p` is outside the box
  Cell_index locate(const Point_3& p, Cell_index hint) const
  {
    const Cell_index c = walk_to(p, hint);
    return c >= 0 ? c : locate(p);
  }

  /// the leaf containing `p` by the walk of `locate(p, hint)`, or `-1` if the walk leaves the
  /// box, takes more than `maximum_steps` steps, `hint` is not a leaf, or `p` has a non-finite
  /// coordinate (`locate(p, hint)` then throws as `locate(p)` does)
  Cell_index walk_to(const Point_3& p, Cell_index hint, int maximum_steps = 64) const
  {
    if(hint < 0 || hint >= Cell_index(m_cells.size()) || !is_leaf(hint)) return -1;
    if(!is_finite(p))
      return -1;
    typename Geom_traits::Orientation_3 orientation = m_gt.orientation_3_object();
    Cell_index c = hint;
    for(int step = 0; step <= maximum_steps; ++step)
    {
      const std::array<Vertex_index, 4>& v = m_cells[c].vertices;
      // p replaces vertex i: the orientation changes sign when p is beyond the face opposite i
      const Orientation beyond = is_positively_oriented(c) ? NEGATIVE : POSITIVE;
      int exit = -1;
      for(int i = 0; i < 4 && exit < 0; ++i)
      {
        const Point_3* q[4] = { &m_points[v[0]], &m_points[v[1]], &m_points[v[2]], &m_points[v[3]] };
        q[i] = &p;
        if(orientation(*q[0], *q[1], *q[2], *q[3]) == beyond) exit = i;
      }
      if(exit < 0) return c;
      c = m_cells[c].neighbors[exit];
      if(c < 0) return -1;
    }
    return -1;
  }
  /// @}

  /// \name Adjacency of the leaf mesh
  /// @{

  /// Appends to `out` the leaves around the edge `(vertex(c,i), vertex(c,j))` of leaf `c`:
  /// `c` first, then the others in rotational order (walking face neighbours). Around an
  /// edge on the box boundary the leaves are an open fan: from `c` to one end of it, then
  /// the leaves on `c`'s other side, from `c` to the other end.
  template <class OutputIterator>
  OutputIterator leaves_around_edge(Cell_index c, int i, int j, OutputIterator out) const
  {
    const Vertex_index a = m_cells[c].vertices[i], b = m_cells[c].vertices[j];
    int others[2], n = 0;
    for(int l = 0; l < 4; ++l)
      if(l != i && l != j) others[n++] = l;
    *out++ = c;
    // Walk one way; if the ring is open (the edge is on the box boundary), walk the other way too.
    if(walk_around_edge(c, a, b, m_cells[c].vertices[others[0]], m_cells[c].neighbors[others[1]], out))
      return out;
    walk_around_edge(c, a, b, m_cells[c].vertices[others[1]], m_cells[c].neighbors[others[0]], out);
    return out;
  }

  /*!
    The leaves around every vertex, as a compressed array: the leaves incident to vertex
    `v` are `cells[offsets[v]]` to `cells[offsets[v+1]-1]`, in increasing order.
  */
  void leaves_around_vertices(std::vector<std::size_t>& offsets, std::vector<Cell_index>& cells) const
  {
    offsets.assign(number_of_vertices() + 1, 0);
    for(Cell_index c = 0; c < Cell_index(number_of_cells()); ++c)
      if(is_leaf(c))
        for(Vertex_index v : m_cells[c].vertices) ++offsets[v + 1];
    for(std::size_t v = 0; v < number_of_vertices(); ++v)
      offsets[v + 1] += offsets[v];
    cells.resize(offsets.back());
    std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
    for(Cell_index c = 0; c < Cell_index(number_of_cells()); ++c)
      if(is_leaf(c))
        for(Vertex_index v : m_cells[c].vertices) cells[fill[v]++] = c;
  }

  /*!
    The edges of the leaf mesh, each once as `(u,v)` with `u < v`, sorted.
    Built per vertex from the leaves around it, so no global sort or hash is needed.
  */
  std::vector<std::array<Vertex_index, 2> > edges() const
  {
    std::vector<std::size_t> offsets;
    std::vector<Cell_index> cells;
    leaves_around_vertices(offsets, cells);
    std::vector<std::array<Vertex_index, 2> > result;
    std::vector<Vertex_index> ring;
    for(Vertex_index u = 0; u < Vertex_index(number_of_vertices()); ++u)
    {
      ring.clear();
      for(std::size_t i = offsets[u]; i < offsets[u + 1]; ++i)
        for(Vertex_index v : m_cells[cells[i]].vertices)
          if(v > u) ring.push_back(v);
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      for(Vertex_index v : ring)
        result.push_back({{u, v}});
    }
    return result;
  }

  /// The leaf mesh as a tetrahedron soup: every vertex, and every leaf as 4 vertex
  /// indices in positive orientation.
  std::vector<std::array<Vertex_index, 4> > leaf_tetrahedra() const
  {
    std::vector<std::array<Vertex_index, 4> > tets;
    tets.reserve(m_number_of_leaves);
    for(Cell_index c = 0; c < Cell_index(number_of_cells()); ++c)
      if(is_leaf(c))
        tets.push_back(positive_vertices(c));
    return tets;
  }

  /// Releases the spare capacity of the arrays (after the last refinement).
  void shrink_to_fit()
  {
    m_points.shrink_to_fit();
    m_cells.shrink_to_fit();
    m_level_and_parity.shrink_to_fit();
    std::vector<Cell_index>().swap(m_patch);
  }

  /// Bytes held by the arrays of the triangulation (capacity, not size).
  std::size_t memory_usage() const
  {
    return m_points.capacity() * sizeof(Point_3) + m_cells.memory_usage() + m_level_and_parity.memory_usage();
  }
  /// @}

  /// \cond SKIP_IN_MANUAL
  /// Bisects one leaf WITHOUT its neighbours, leaving a hanging vertex. Only for tests
  /// that must show a non-conforming mesh is detected.
  void bisect_non_conforming_for_testing(Cell_index c)
  {
    m_patch.assign(1, c);
    auto ignore = [](Cell_index, Cell_index, Cell_index) {};
    bisect_patch(ignore, true);
  }
  /// \endcond

private:
  // exact predicates cannot order a NaN, and an infinite corner breaks the box
  static bool is_finite(const Point_3& p)
  {
    return std::isfinite(to_double(p.x())) && std::isfinite(to_double(p.y())) && std::isfinite(to_double(p.z()));
  }

  void check_level(int l) const
  {
    if(l < 0 || l > maximum_level())
      throw std::domain_error("Bisection_triangulation_3: level " + std::to_string(l) +
                              " is outside [0, " + std::to_string(maximum_level()) + "]");
  }

  void initialize(const Point_3& o, const Vector_3& a, const Vector_3& b, const Vector_3& c)
  {
    const double coords[] = { to_double(o.x()), to_double(o.y()), to_double(o.z()),
                              to_double(a.x()), to_double(a.y()), to_double(a.z()),
                              to_double(b.x()), to_double(b.y()), to_double(b.z()),
                              to_double(c.x()), to_double(c.y()), to_double(c.z()) };
    for(double x : coords)
      if(!std::isfinite(x))
        throw std::invalid_argument("Bisection_triangulation_3: the box has a non-finite coordinate");
    // Corner (i,j,k) is o + i a + j b + k c, numbered i + 2j + 4k.
    for(int corner = 0; corner < 8; ++corner)
    {
      Point_3 p = o;
      if(corner & 1) p = p + a;
      if(corner & 2) p = p + b;
      if(corner & 4) p = p + c;
      if(!is_finite(p))
        throw std::invalid_argument("Bisection_triangulation_3: a corner of the box overflows the double range");
      m_points.push_back(p);
    }
    if(m_gt.orientation_3_object()(m_points[0], m_points[1], m_points[2], m_points[4]) == COPLANAR)
      throw std::invalid_argument("Bisection_triangulation_3: the box is flat");
    // The 6 Kuhn tetrahedra [0, e_p0, e_p0 + e_p1, 7] for the permutations p of the axes;
    // with Maubach's tag 3 they all bisect the main diagonal first.
    static const int perms[6][3] = { {0,1,2}, {0,2,1}, {1,0,2}, {1,2,0}, {2,0,1}, {2,1,0} };
    for(const auto& p : perms)
    {
      const int v1 = 1 << p[0], v2 = v1 | (1 << p[1]);
      new_cell({{0, v1, v2, 7}}, -1, 0);
      const Orientation o4 = m_gt.orientation_3_object()(m_points[0], m_points[v1], m_points[v2], m_points[7]);
      if(o4 == NEGATIVE)
        m_level_and_parity.back() |= parity_bit;
    }
    // Face neighbours of the roots: two roots are adjacent when they share 3 vertices.
    for(Cell_index r = 0; r < 6; ++r)
      for(int i = 0; i < 4; ++i)
        m_cells[r].neighbors[i] = -1;
    for(Cell_index r = 0; r < 6; ++r)
      for(Cell_index s = 0; s < 6; ++s)
        if(r != s)
          for(int i = 0; i < 4; ++i)
          {
            // does s contain the face of r opposite i?
            int shared = 0;
            for(int l = 0; l < 4; ++l)
              if(l != i && std::count(m_cells[s].vertices.begin(), m_cells[s].vertices.end(), m_cells[r].vertices[l]))
                ++shared;
            if(shared == 3) m_cells[r].neighbors[i] = s;
          }
    m_number_of_leaves = 6;
  }

  // Grow the point array by 1.5x rather than the library's 2x (the cells live in blocks).
  template <class Vector>
  static void grow(Vector& v, std::size_t extra)
  {
    if(v.size() + extra > v.capacity())
      v.reserve((std::max)(v.size() + extra, v.capacity() + v.capacity() / 2 + 16));
  }

  Cell_index new_cell(const std::array<Vertex_index, 4>& v, Cell_index parent, std::uint8_t level_and_parity)
  {
    m_cells.push_back(Cell{v, {{-1, -1, -1, -1}}, parent, -1});
    m_level_and_parity.push_back(level_and_parity);
    return Cell_index(m_cells.size() - 1);
  }

  bool same_edge(Cell_index c, Vertex_index a, Vertex_index b) const
  {
    const std::array<Vertex_index, 2> e = refinement_edge(c);
    return (e[0] == a && e[1] == b) || (e[0] == b && e[1] == a);
  }

  // Walks from `c` through the face (a, b, x) opposite to its other vertex, i.e. into
  // `next`, and on around the edge (a,b); returns true if it came back to `c` (closed ring).
  template <class OutputIterator>
  bool walk_around_edge(Cell_index c, Vertex_index a, Vertex_index b, Vertex_index x,
                        Cell_index next, OutputIterator& out) const
  {
    Cell_index t = next;
    while(t != -1 && t != c)
    {
      *out++ = t;
      // the vertex of t that is not a, b or x: cross the face opposite x next
      const std::array<Vertex_index, 4>& v = m_cells[t].vertices;
      int ix = -1;
      Vertex_index y = -1;
      for(int l = 0; l < 4; ++l)
      {
        if(v[l] == x) ix = l;
        else if(v[l] != a && v[l] != b) y = v[l];
      }
      if(ix < 0) return false;  // only on a deliberately non-conforming mesh
      t = m_cells[t].neighbors[ix];
      x = y;
    }
    return t == c;
  }

  template <class OnBisect>
  void bisect_recursively(Cell_index c, OnBisect& on_bisect)
  {
    // Maubach's ordering makes every leaf around the refinement edge that does not share
    // it as refinement edge strictly coarser; refining it first terminates.
    for(;;)
    {
      if(!is_leaf(c)) return;
      const std::array<Vertex_index, 2> e = refinement_edge(c);
      const int k = refinement_index(level(c));
      m_patch.clear();
      leaves_around_edge(c, 0, k, std::back_inserter(m_patch));
      Cell_index incompatible = -1;
      for(Cell_index t : m_patch)
        if(!same_edge(t, e[0], e[1])) { incompatible = t; break; }
      if(incompatible < 0) break;
      bisect_recursively(incompatible, on_bisect);
    }
    bisect_patch(on_bisect, false);
  }

  // Bisects every cell of m_patch (all sharing one refinement edge) at one new midpoint,
  // then relinks the face neighbours of the children.
  template <class OnBisect>
  void bisect_patch(OnBisect& on_bisect, bool non_conforming)
  {
    const Cell_index first = m_patch.front();
    const int k0 = refinement_index(level(first));
    const Vertex_index a = m_cells[first].vertices[0], b = m_cells[first].vertices[k0];
    if(m_points.size() >= std::size_t((std::numeric_limits<Vertex_index>::max)()))
      throw std::length_error("Bisection_triangulation_3: too many vertices for 32-bit vertex indices");
    if(m_cells.size() + 2 * m_patch.size() >= std::size_t((std::numeric_limits<Cell_index>::max)()))
      throw std::length_error("Bisection_triangulation_3: too many cells for 32-bit cell indices");
    grow(m_points, 1);
    const Vertex_index z = Vertex_index(m_points.size());
    m_points.push_back(m_gt.construct_midpoint_3_object()(m_points[a], m_points[b]));
    if(!non_conforming && !splits_patch(a, b, z))
    {
      m_points.pop_back();
      throw std::domain_error("Bisection_triangulation_3::bisect: at level " + std::to_string(level(first)) +
                              " the midpoint of an edge rounds onto its ends (the cells are too small for the "
                              "precision of their coordinates): refine less deeply, or place the box nearer "
                              "to the origin");
    }

    // create the children
    for(Cell_index t : m_patch)
    {
      const std::array<Vertex_index, 4> x = m_cells[t].vertices;
      const int l = level(t), k = refinement_index(l);
      const std::uint8_t parity = m_level_and_parity[t] & parity_bit;
      std::array<Vertex_index, 4> v0 = x, v1;
      v0[k] = z;
      for(int i = 0; i < k; ++i) v1[i] = x[i + 1];
      v1[k] = z;
      for(int i = k + 1; i < 4; ++i) v1[i] = x[i];
      // child 1 moves z from position 0 to position k: a cycle of k+1 entries, k transpositions
      const std::uint8_t parity1 = (k % 2 == 1) ? std::uint8_t(parity ^ parity_bit) : parity;
      const Cell_index c0 = new_cell(v0, t, std::uint8_t((l + 1) | parity));
      new_cell(v1, t, std::uint8_t((l + 1) | parity1));
      m_cells[t].first_child = c0;
      ++m_number_of_leaves;
    }

    // relink: for each child, the face opposite its vertex at position i
    for(Cell_index t : m_patch)
    {
      const std::array<Vertex_index, 4> x = m_cells[t].vertices;
      const int k = refinement_index(level(t));
      const Cell_index c0 = m_cells[t].first_child, c1 = c0 + 1;
      for(int i = 0; i < 4; ++i)
      {
        // child 0 = x with x_k -> z
        Cell_index n0;
        if(i == k)      n0 = relink_outer(m_cells[t].neighbors[k], t, c0);   // old face opposite x_k
        else if(i == 0) n0 = c1;                                       // the new inner face
        else            n0 = child_holding(m_cells[t].neighbors[i], x[0], non_conforming);
        m_cells[c0].neighbors[i] = n0;
        // child 1 = [x1..x_k, z, x_{k+1}..]: position i holds x_{i+1} (i<k), z (i=k), x_i (i>k)
        Cell_index n1;
        if(i == k)          n1 = relink_outer(m_cells[t].neighbors[0], t, c1); // old face opposite x_0
        else if(i == k - 1) n1 = c0;                                     // the face opposite x_k
        else                n1 = child_holding(m_cells[t].neighbors[i < k ? i + 1 : i], x[k], non_conforming);
        m_cells[c1].neighbors[i] = n1;
      }
    }
    // once the patch is whole: a callback that throws then leaves a conforming mesh (called
    // within the relinking, it left stale links, and the next bisection walked forever)
    for(Cell_index t : m_patch) on_bisect(t, m_cells[t].first_child, m_cells[t].first_child + 1);
  }

  // Whether the midpoint z of the edge (a, b) of the cells of m_patch gives them children of
  // their orientation. Rounded midpoints stay between the ends in every coordinate unless
  // the edge spans about an ulp in one (cells too small for their offset from the origin:
  // a unit box at 1e9 at level 72); only then are the children's orientations tested (on
  // every bisection it would add two orientation tests a child to the reconstruction). Flat children made
  // flat leaves that contained every point tested and were refined without end.
  bool splits_patch(Vertex_index a, Vertex_index b, Vertex_index z) const
  {
    const Point_3 &pa = m_points[a], &pb = m_points[b], &pz = m_points[z];
    if(pz == pa || pz == pb) return false;
    const auto strictly_between = [](const auto& x, const auto& lo, const auto& hi) {
      return lo == hi || (lo < x && x < hi) || (hi < x && x < lo);
    };
    if(strictly_between(pz.x(), pa.x(), pb.x()) && strictly_between(pz.y(), pa.y(), pb.y()) &&
       strictly_between(pz.z(), pa.z(), pb.z()))
      return true;
    typename Geom_traits::Orientation_3 orientation = m_gt.orientation_3_object();
    for(Cell_index t : m_patch)
    {
      const std::array<Vertex_index, 4>& x = m_cells[t].vertices;
      const Orientation parent = orientation(m_points[x[0]], m_points[x[1]], m_points[x[2]], m_points[x[3]]);
      // each child is the parent with a or b replaced by z
      for(Vertex_index end : { a, b })
      {
        const Point_3* q[4] = { &m_points[x[0]], &m_points[x[1]], &m_points[x[2]], &m_points[x[3]] };
        for(int i = 0; i < 4; ++i)
          if(x[i] == end) q[i] = &pz;
        if(orientation(*q[0], *q[1], *q[2], *q[3]) != parent) return false;
      }
    }
    return true;
  }

  // The face of t across from its neighbour n now belongs to `child`: point n at it.
  Cell_index relink_outer(Cell_index n, Cell_index t, Cell_index child)
  {
    if(n >= 0)
      for(int s = 0; s < 4; ++s)
        if(m_cells[n].neighbors[s] == t) m_cells[n].neighbors[s] = child;
    return n;
  }

  // The child of the (bisected) neighbour n that holds vertex v.
  Cell_index child_holding(Cell_index n, Vertex_index v, bool non_conforming) const
  {
    if(n < 0) return -1;
    if(non_conforming && is_leaf(n)) return n;  // deliberately broken mesh: keep a stale link
    return m_cells[n].vertices[0] == v ? m_cells[n].first_child : m_cells[n].first_child + 1;
  }
};

} // namespace CGAL

#endif // CGAL_BISECTION_TRIANGULATION_3_H
