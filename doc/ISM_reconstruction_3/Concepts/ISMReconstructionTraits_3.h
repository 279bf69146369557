/*!
\class ISMReconstructionTraits_3 ISM_reconstruction_function.h <CGAL/ISM_reconstruction_function.h>
\ingroup PkgISMReconstruction3Concepts
\cgalConcept

The concept `ISMReconstructionTraits_3` describes the geometric traits of
`CGAL::ISM_reconstruction_function`, `CGAL::ism_surface_reconstruction()` and
`CGAL::ism_orient_normals()`: those of the binary multitriangulation they refine, plus a
sphere type for `CGAL::ISM_reconstruction_function::bounding_sphere()` (the interface of
\cgal's `ImplicitFunction` meshers).

The reconstruction computes in `double` internally (local PCA fits, Ising energy, distance
estimation by a kd-tree), so it reads coordinates with `CGAL::to_double()` and builds points
and vectors from three `double`: a model must provide these constructions,
`Point_3(double, double, double)` and `Vector_3(double, double, double)`, and
`Sphere_3(const Point_3& center, const FT& squared_radius)`.

\cgalRefines `BisectionTriangulationTraits_3`

\cgalHasModel All models of the concept `Kernel`, for example `CGAL::Exact_predicates_inexact_constructions_kernel` and `CGAL::Simple_cartesian<double>`.

\sa `CGAL::ISM_reconstruction_function<GeomTraits>`
\sa `CGAL::ism_surface_reconstruction()`
*/
class ISMReconstructionTraits_3
{
public:
  /// \name Types
  /// @{

  /// \brief The sphere type; a model of `Kernel::Sphere_3`.
  ///
  /// It must be constructible from a center and a
  /// squared radius.
  typedef unspecified_type Sphere_3;

  /// @}
};
