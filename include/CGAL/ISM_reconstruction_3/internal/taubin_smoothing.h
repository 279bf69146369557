// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TAUBIN_SMOOTHING_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TAUBIN_SMOOTHING_H

// Mesh smoothing (paper section 4.4): Taubin's lambda/mu fairing (G. Taubin, "A signal
// processing approach to fair surface design", SIGGRAPH 1995) with uniform umbrella
// weights. Each step moves every vertex by factor * (mean of its neighbors - vertex),
// all vertices at once (double-buffered), so the result does not depend on threads.

#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

/// \cond SKIP_IN_MANUAL

// Smooths `points` in place: `iterations` times a lambda step then a mu step, the
// umbrella operator using the unique neighbors of each vertex along the triangles' edges.
// Vertices used by no triangle do not move. Usual values: lambda = 0.5, mu = -0.53.
inline void taubin_smoothing(std::vector<std::array<double, 3> >& points,
                             const std::vector<std::array<std::size_t, 3> >& triangles,
                             unsigned int iterations,
                             double lambda = 0.5,
                             double mu = -0.53)
{
  constexpr std::size_t grain = 4096;  // a vertex's step is a few additions
  const std::size_t n = points.size();
  if(n == 0 || triangles.empty() || iterations == 0)
    return;

  // Vertex adjacency in CSR form, each neighbor once.
  std::vector<std::size_t> offsets(n + 1, 0);
  for(const std::array<std::size_t, 3>& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      CGAL_precondition(t[i] < n);
      offsets[t[i] + 1] += 2;
    }
  for(std::size_t v = 0; v < n; ++v)
    offsets[v + 1] += offsets[v];
  std::vector<std::size_t> adjacency(offsets[n]);
  {
    std::vector<std::size_t> next(offsets.begin(), offsets.end() - 1);
    for(const std::array<std::size_t, 3>& t : triangles)
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t v = t[i];
        adjacency[next[v]++] = t[(i + 1) % 3];
        adjacency[next[v]++] = t[(i + 2) % 3];
      }
  }
  std::vector<std::size_t> unique_size(n, 0);
  for_chunks(0, n, grain, [&](std::size_t lo, std::size_t hi) {
    for(std::size_t v = lo; v < hi; ++v)
    {
      const auto b = adjacency.begin() + static_cast<std::ptrdiff_t>(offsets[v]);
      const auto e = adjacency.begin() + static_cast<std::ptrdiff_t>(offsets[v + 1]);
      std::sort(b, e);
      unique_size[v] = static_cast<std::size_t>(std::unique(b, e) - b);
    }
  });
  // Compact the unique neighbors.
  std::vector<std::size_t> compact_offsets(n + 1, 0);
  for(std::size_t v = 0; v < n; ++v)
    compact_offsets[v + 1] = compact_offsets[v] + unique_size[v];
  std::vector<std::size_t> compact_adjacency(compact_offsets[n]);
  for(std::size_t v = 0; v < n; ++v)
    std::copy(adjacency.begin() + static_cast<std::ptrdiff_t>(offsets[v]),
              adjacency.begin() + static_cast<std::ptrdiff_t>(offsets[v] + unique_size[v]),
              compact_adjacency.begin() + static_cast<std::ptrdiff_t>(compact_offsets[v]));
  std::vector<std::size_t>().swap(adjacency);
  const std::size_t* const off = compact_offsets.data();
  const std::size_t* const adj = compact_adjacency.data();

  std::vector<std::array<double, 3> > buffer(points);
  auto step = [&](const std::vector<std::array<double, 3> >& in,
                  std::vector<std::array<double, 3> >& out, double factor) {
    for_chunks(0, n, grain, [&](std::size_t lo, std::size_t hi) {
      for(std::size_t v = lo; v < hi; ++v)
      {
        const std::size_t d = off[v + 1] - off[v];
        if(d == 0)
        {
          out[v] = in[v];
          continue;
        }
        double sx = 0., sy = 0., sz = 0.;
        for(std::size_t k = off[v]; k < off[v + 1]; ++k)
        {
          const std::array<double, 3>& q = in[adj[k]];
          sx += q[0];
          sy += q[1];
          sz += q[2];
        }
        const double inv = 1. / static_cast<double>(d);
        out[v][0] = in[v][0] + factor * (sx * inv - in[v][0]);
        out[v][1] = in[v][1] + factor * (sy * inv - in[v][1]);
        out[v][2] = in[v][2] + factor * (sz * inv - in[v][2]);
      }
    });
  };
  for(unsigned int it = 0; it < iterations; ++it)
  {
    step(points, buffer, lambda);
    step(buffer, points, mu);
  }
}

/// \endcond

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_TAUBIN_SMOOTHING_H
