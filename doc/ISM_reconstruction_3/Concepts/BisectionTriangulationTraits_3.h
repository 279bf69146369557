/*!
\class BisectionTriangulationTraits_3 Bisection_triangulation_3.h <CGAL/Bisection_triangulation_3.h>
\ingroup PkgISMReconstruction3Concepts
\cgalConcept

The concept `BisectionTriangulationTraits_3` describes the types and the two geometric
operations `CGAL::Bisection_triangulation_3` needs: a point, a vector and an axis-aligned
box type to describe the bounding box or parallelepiped, the orientation predicate (point
location descends the cell tree by the side of the bisecting plane) and the midpoint
construction (the new vertex of a bisection).

The refinement itself is purely combinatorial (Maubach's vertex ordering) and never
compares lengths, so the traits need no length or distance computation.

Besides the types and functors below, a model must provide:
- the construction of a `Vector_3` from three `FT` and of a point `p + v` from a
  `Point_3 p` and a `Vector_3 v` (`operator+`);
- the accessors `x()`, `y()`, `z()` of `Point_3` and `Vector_3`, and `xmin()`, `ymin()`,
  `zmin()`, `xmax()`, `ymax()`, `zmax()` and `min()` of `Iso_cuboid_3`;
- `CGAL::to_double()` on `FT` (finiteness checks of the box).

\cgalHasModel All models of the concept `Kernel`, for example `CGAL::Exact_predicates_inexact_constructions_kernel` and `CGAL::Simple_cartesian<double>`.

\sa `CGAL::Bisection_triangulation_3<GeomTraits>`
\sa `ISMReconstructionTraits_3`
*/
class BisectionTriangulationTraits_3
{
public:
  /// \name Types
  /// @{

  /// The number type of the coordinates; a model of `FieldNumberType`.
  typedef unspecified_type FT;

  /// The point type; a model of `Kernel::Point_3`.
  typedef unspecified_type Point_3;

  /// The vector type; a model of `Kernel::Vector_3`.
  typedef unspecified_type Vector_3;

  /// The axis-aligned box type; a model of `Kernel::IsoCuboid_3`.
  typedef unspecified_type Iso_cuboid_3;

  /// \brief A predicate object type; a model of `Kernel::Orientation_3`.
  ///
  /// `Orientation operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s)`
  /// returns the orientation of the tetrahedron `pqrs`.
  typedef unspecified_type Orientation_3;

  /// \brief A construction object type; a model of `Kernel::ConstructMidpoint_3`.
  ///
  /// `Point_3 operator()(const Point_3& p, const Point_3& q)` returns the midpoint of `pq`.
  typedef unspecified_type Construct_midpoint_3;

  /// @}

  /// \name Operations
  /// @{

  /// returns the orientation predicate object
  Orientation_3 orientation_3_object() const;

  /// returns the midpoint construction object
  Construct_midpoint_3 construct_midpoint_3_object() const;

  /// @}
};
