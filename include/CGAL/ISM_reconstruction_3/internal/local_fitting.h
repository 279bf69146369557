// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_LOCAL_FITTING_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_LOCAL_FITTING_H

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <cstdint>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

// The local fit of a cell (paper 4.1): the plane through the barycenter of its points,
// normal to the eigenvector of the smallest eigenvalue of their covariance, and the
// coplanarity error eps = l0 / (l0 + l1 + l2).
struct Plane_fit
{
  // Single precision for the unit normal and the error keeps a fit at 24 bytes (one per
  // cell of the triangulation, the largest array after the cells); the offset is computed
  // from the rounded normal, so the plane still passes through the points' barycenter.
  std::array<float, 3> normal = {{0.f, 0.f, 1.f}};
  float coplanarity_error = 1.f; // eps in [0, 1/3]; 1 = no fit yet
  double offset = 0.;            // the plane is {x : normal . x = offset}

  // the side of the plane `x` lies on: +1 or -1 (a point on the plane counts as +1)
  int side(const std::array<double, 3>& x) const { return signed_distance(x) >= 0 ? 1 : -1; }
  double signed_distance(const std::array<double, 3>& x) const
  {
    return double(normal[0]) * x[0] + double(normal[1]) * x[1] + double(normal[2]) * x[2] - offset;
  }
};

// Accumulates first and second moments; centred on a reference point so that the
// covariance keeps its precision far from the origin.
class Moments
{
  std::array<double, 3> m_ref;
  double m_n = 0, m_s[3] = {0, 0, 0}, m_ss[6] = {0, 0, 0, 0, 0, 0};

public:
  explicit Moments(const std::array<double, 3>& reference) : m_ref(reference) {}

  void add(const std::array<double, 3>& p)
  {
    const double x = p[0] - m_ref[0], y = p[1] - m_ref[1], z = p[2] - m_ref[2];
    m_n += 1;
    m_s[0] += x; m_s[1] += y; m_s[2] += z;
    m_ss[0] += x * x; m_ss[1] += x * y; m_ss[2] += x * z;
    m_ss[3] += y * y; m_ss[4] += y * z; m_ss[5] += z * z;
  }

  std::size_t count() const { return std::size_t(m_n); }

  // PCA by Eigen's closed-form 3x3 solver. Returns false for fewer than 3 points.
  bool fit(Plane_fit& f) const
  {
    if(m_n < 3) return false;
    const double inv = 1. / m_n;
    const double c[3] = { m_s[0] * inv, m_s[1] * inv, m_s[2] * inv };
    Eigen::Matrix3d cov;
    cov(0, 0) = m_ss[0] * inv - c[0] * c[0];
    cov(0, 1) = cov(1, 0) = m_ss[1] * inv - c[0] * c[1];
    cov(0, 2) = cov(2, 0) = m_ss[2] * inv - c[0] * c[2];
    cov(1, 1) = m_ss[3] * inv - c[1] * c[1];
    cov(1, 2) = cov(2, 1) = m_ss[4] * inv - c[1] * c[2];
    cov(2, 2) = m_ss[5] * inv - c[2] * c[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(cov);
    const Eigen::Vector3d l = solver.eigenvalues().cwiseMax(0.);  // ascending
    const double sum = l.sum();
    if(!(sum > 0) || !std::isfinite(sum)) return false;
    const Eigen::Vector3d n = solver.eigenvectors().col(0).normalized();
    if(!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) return false;
    // Rounded through memory: GCC 12 at -O3 dropped the rounding of n[0] and n[1] where the
    // caller reads the normal back as double (PCA normals of the torus: x never rounded, at
    // -O2 always), and kept it in some inlined copies of a TBB loop body, so a run's values
    // depended on which copy ran a chunk (F differed by 1e-10 between runs under load).
    for(int d = 0; d < 3; ++d)
    {
      volatile float rounded = float(n[d]);
      f.normal[d] = rounded;
    }
    const double b[3] = { c[0] + m_ref[0], c[1] + m_ref[1], c[2] + m_ref[2] };
    f.offset = double(f.normal[0]) * b[0] + double(f.normal[1]) * b[1] + double(f.normal[2]) * b[2];
    f.coplanarity_error = float(l[0] / sum);
    return true;
  }
};

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_LOCAL_FITTING_H
