// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISING_ANNEALING_H
#define CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISING_ANNEALING_H

// Topology estimation (paper section 4.2): minimisation of the Ising energy
// D(S) = sum_e H_e S_u S_v over S in {+1,-1}^V by Metropolis simulated annealing.
//
// The result depends only on the input and the seed, never on the number of threads:
// a sweep visits the vertices colour class by colour class (a greedy colouring, so the
// vertices of one class are independent and are updated in parallel), and the random
// number used for (sweep, vertex) is a counter-based hash of (seed, sweep, vertex).

#include <CGAL/ISM_reconstruction_3/internal/for_each_index.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace ISM_reconstruction_3 {
namespace internal {

/// \cond SKIP_IN_MANUAL

// Symmetric coupling graph in CSR form: the neighbors of `v` are
// `adjacency[offsets[v] .. offsets[v+1])`, each with the weight `H_e` stored at the same
// position in `weights`; every undirected edge is stored at both ends with the same weight.
struct Coupling_graph
{
  std::vector<std::size_t> offsets;  // size number_of_vertices() + 1 (or empty)
  std::vector<int> adjacency;
  std::vector<float> weights;  // annealing quantises them to 24 bits anyway

  std::size_t number_of_vertices() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

// Temperatures are in units of J = mean |H_e|.
struct Annealing_schedule
{
  double initial_temperature = 15.;  // in units of J
  double final_temperature = 0.3;    // in units of J
  int number_of_sweeps = 200;        // geometric cooling from initial to final over this many sweeps
  bool final_zero_temperature_pass = true;
};

namespace ising_detail {

inline std::uint64_t splitmix64(std::uint64_t z)
{
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Key of one sweep: mixes the seed and the sweep number.
inline std::uint64_t sweep_key(std::uint64_t seed, std::uint64_t sweep)
{
  return splitmix64(splitmix64(seed) ^ (sweep * 0xD1B54A32D192ED03ULL + 0x8CB92BA72F3D8DD7ULL));
}

// Uniform number in (0,1) (never 0, never 1) for vertex `v` in the sweep of key `key`.
inline double uniform_01(std::uint64_t key, std::uint64_t v)
{
  const std::uint64_t h = splitmix64(key + v * 0x9E3779B97F4A7C15ULL);
  return (static_cast<double>(h >> 11) + 0.5) * (1. / 9007199254740992.);  // 2^-53
}

// Smallest value of uniform_01() is 2^-54 ~ 5.55e-17 > exp(-38): when dE/T > 38 a move
// is rejected for every random number, so exp() need not be evaluated.
constexpr double max_exponent = 38.;

// Metropolis test u < exp(-x) for x > 0; the bounds 1 - x <= exp(-x) <= 1/(1 + x + x^2/2)
// decide most cases without calling exp().
inline bool accept(double u, double x)
{
  if(u <= 1. - x)
    return true;
  if(u * (1. + x * (1. + 0.5 * x)) >= 1.)
    return false;
  return u < std::exp(-x);
}

// One entry of a row of the internal copy of the coupling graph.
struct Packed_entry
{
  int neighbor;
  std::int32_t weight;  // H_e quantised, see `anneal()`
};

// the vertices of one colour class per parallel task: a flip test is a few operations
constexpr std::size_t annealing_grain = 2048;

} // namespace ising_detail

// Energy D(S) = sum over edges H_e S_u S_v, each undirected edge counted once
// (self-loops are ignored).
inline double ising_energy(const Coupling_graph& g, const std::vector<signed char>& signs)
{
  const std::size_t n = g.number_of_vertices();
  CGAL_precondition(signs.size() == n);
  CGAL_precondition(n == 0 || (g.adjacency.size() == g.offsets[n] && g.weights.size() == g.offsets[n]));
  double energy = 0.;
  for(std::size_t v = 0; v < n; ++v)
  {
    double h = 0.;
    for(std::size_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k)
    {
      const std::size_t u = static_cast<std::size_t>(g.adjacency[k]);
      if(u > v)
        h += g.weights[k] * signs[u];
    }
    energy += signs[v] * h;
  }
  return energy;
}

// Minimises D by Metropolis simulated annealing starting from `signs` (+1/-1 each; warm
// start). Vertices with `clamped[v] != 0` are never flipped (`clamped` may be empty: none
// clamped). Sweep `k` (0-based) runs at temperature
// `J * T0 * (T1/T0)^(k/(number_of_sweeps-1))`, `J` the mean of |H_e|; a move with energy
// change dE is accepted if dE <= 0 or u < exp(-dE/T). The optional final pass then flips
// greedily while a flip strictly lowers the energy (at most 100 sweeps). Energies are
// compared with the weights quantised to 2^-24 max |H_e| (see below); the returned
// energy uses the exact weights. The result is identical for any number of threads.
// Cost: one copy of the graph (8 bytes per stored entry) and, per sweep, one pass over
// it. Returns the final energy.
namespace ising_detail {
// `release`, if not null, is `&g`: its arrays are freed once copied into the internal
// layout, and the returned energy is then computed from the quantised weights.
inline double anneal(const Coupling_graph& g, Coupling_graph* release,
                     std::vector<signed char>& signs,
                     const std::vector<char>& clamped,
                     const Annealing_schedule& schedule,
                     std::uint64_t seed)
{
  using namespace ising_detail;
  const std::size_t n = g.number_of_vertices();
  CGAL_precondition(signs.size() == n);
  CGAL_precondition(clamped.empty() || clamped.size() == n);
  if(n == 0)
    return 0.;
  CGAL_precondition(g.adjacency.size() == g.offsets[n] && g.weights.size() == g.offsets[n]);
  CGAL_precondition(std::all_of(signs.begin(), signs.end(),
                                [](signed char s) { return s == 1 || s == -1; }));

  auto is_free = [&](std::size_t v) { return clamped.empty() || clamped[v] == 0; };

  // J = mean |H_e| over all stored entries (each undirected edge twice: same mean).
  double sum_abs = 0.;
  for(float w : g.weights)
    sum_abs += std::abs(double(w));
  const double J = g.weights.empty() ? 0. : sum_abs / static_cast<double>(g.weights.size());

  std::size_t number_of_free = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(is_free(v))
      ++number_of_free;
  if(number_of_free == 0 || !(J > 0.))
    return ising_energy(g, signs);  // nothing can move, or every flip has dE = 0

  // Greedy colouring of the free vertices, in index order (deterministic); clamped
  // vertices are never updated, so they need no colour.
  std::vector<int> colour(n, -1);
  std::vector<std::size_t> forbidden;  // forbidden[c] == v+1: colour c used by a neighbor of v
  for(std::size_t v = 0; v < n; ++v)
  {
    if(!is_free(v))
      continue;
    for(std::size_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k)
    {
      const int c = colour[static_cast<std::size_t>(g.adjacency[k])];
      if(c >= 0)
        forbidden[static_cast<std::size_t>(c)] = v + 1;
    }
    std::size_t c = 0;
    while(c < forbidden.size() && forbidden[c] == v + 1)
      ++c;
    if(c == forbidden.size())
      forbidden.push_back(0);
    colour[v] = static_cast<int>(c);
  }
  const std::size_t number_of_colours = forbidden.size();

  // Internal layout: free vertices grouped by colour (ascending index inside a class),
  // then the clamped ones, so that a colour class is a contiguous range.
  std::vector<std::size_t> class_begin(number_of_colours + 1, 0);
  for(std::size_t v = 0; v < n; ++v)
    if(colour[v] >= 0)
      ++class_begin[static_cast<std::size_t>(colour[v]) + 1];
  for(std::size_t c = 0; c < number_of_colours; ++c)
    class_begin[c + 1] += class_begin[c];
  std::vector<int> old_of_new(n), new_of_old(n);
  {
    std::vector<std::size_t> next(class_begin.begin(), class_begin.end() - 1);
    std::size_t next_clamped = number_of_free;
    for(std::size_t v = 0; v < n; ++v)
    {
      const std::size_t i = colour[v] >= 0 ? next[static_cast<std::size_t>(colour[v])]++ : next_clamped++;
      old_of_new[i] = static_cast<int>(v);
      new_of_old[v] = static_cast<int>(i);
    }
  }

  // Rows of the free vertices in the internal numbering, neighbor and weight packed
  // together (self-loops dropped: they do not change when a vertex flips). Weights are
  // quantised to integers, max |H_e| -> 2^24: local fields are then exact integer sums
  // (cheaper than floating point, independent of the summation order, and the
  // zero-temperature pass strictly decreases an exact energy, so it cannot cycle);
  // decisions ignore energy differences below 2^-24 max |H_e| per edge.
  double max_abs = 0.;
  for(float w : g.weights)
    max_abs = (std::max)(max_abs, std::abs(double(w)));
  CGAL_precondition(std::isfinite(max_abs));
  const double scale = 16777216. / max_abs;  // 2^24 / max |H_e|; max_abs > 0 since J > 0
  if(!std::isfinite(scale))  // weights below ~1e-301: as good as zero
    return ising_energy(g, signs);
  std::vector<std::size_t> offsets(number_of_free + 1, 0);
  for(std::size_t i = 0; i < number_of_free; ++i)
  {
    const std::size_t v = static_cast<std::size_t>(old_of_new[i]);
    std::size_t d = 0;
    for(std::size_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k)
      if(static_cast<std::size_t>(g.adjacency[k]) != v)
        ++d;
    offsets[i + 1] = offsets[i] + d;
  }
  // not value-initialised: filled (and first touched) in parallel below
  std::unique_ptr<Packed_entry[]> entries(new Packed_entry[offsets[number_of_free]]);
  for_chunks(0, number_of_free, annealing_grain, [&](std::size_t lo, std::size_t hi) {
    for(std::size_t i = lo; i < hi; ++i)
    {
      const std::size_t v = static_cast<std::size_t>(old_of_new[i]);
      std::size_t j = offsets[i];
      for(std::size_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k)
      {
        const std::size_t u = static_cast<std::size_t>(g.adjacency[k]);
        if(u == v)
          continue;
        entries[j].neighbor = new_of_old[u];
        entries[j].weight = static_cast<std::int32_t>(std::lround(double(g.weights[k]) * scale));
        ++j;
      }
    }
  });
  std::vector<signed char> s(n);
  for(std::size_t i = 0; i < n; ++i)
    s[i] = signs[static_cast<std::size_t>(old_of_new[i])];
  // the energy of the edges between clamped vertices never changes
  double clamped_energy = 0.;
  if(release)
  {
    for(std::size_t v = 0; v < n; ++v)
      if(!is_free(v))
        for(std::size_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k)
        {
          const std::size_t u = static_cast<std::size_t>(g.adjacency[k]);
          if(u > v && !is_free(u))
            clamped_energy += double(g.weights[k]) * signs[u] * signs[v];
        }
    *release = Coupling_graph();  // `g` is not used any more
  }

  const std::size_t* const off = offsets.data();
  const Packed_entry* const ent = entries.get();
  signed char* const sp = s.data();
  const int* const original = old_of_new.data();

  // scale * (sum over the neighbors u of i of H_iu S_u), exact
  auto local_field = [off, ent, sp](std::size_t i) {
    std::int64_t h = 0;
    for(std::size_t k = off[i]; k < off[i + 1]; ++k)
      h += static_cast<std::int64_t>(ent[k].weight) * sp[ent[k].neighbor];
    return h;
  };

  // Metropolis sweeps with geometric cooling.
  const int number_of_sweeps = (std::max)(schedule.number_of_sweeps, 0);
  if(number_of_sweeps > 0)
  {
    CGAL_precondition(schedule.initial_temperature > 0. && schedule.final_temperature > 0.);
    const double t0 = schedule.initial_temperature * J;
    const double ratio = schedule.final_temperature / schedule.initial_temperature;
    for(int sweep = 0; sweep < number_of_sweeps; ++sweep)
    {
      const double t = number_of_sweeps == 1
                         ? t0
                         : t0 * std::pow(ratio, static_cast<double>(sweep) / (number_of_sweeps - 1));
      const double minus_two_beta = -2. / (t * scale);  // local fields are scaled
      const std::uint64_t key = sweep_key(seed, static_cast<std::uint64_t>(sweep));
      for(std::size_t c = 0; c < number_of_colours; ++c)
      {
        for_chunks(class_begin[c], class_begin[c + 1], annealing_grain, [&](std::size_t lo, std::size_t hi) {
          for(std::size_t i = lo; i < hi; ++i)
          {
            // dE = -2 S_i h; accept if dE <= 0 or u < exp(-dE/T).
            const double x = minus_two_beta * static_cast<double>(sp[i] * local_field(i));  // dE / T
            // Written without short-circuits and with an unconditional store: the outcome
            // is unpredictable at high temperature, a mispredicted branch costs more
            // than the hash.
            const double u = uniform_01(key, static_cast<std::uint64_t>(original[i]));
            const bool flip = (x <= 0.) | (x < max_exponent && accept(u, x));
            sp[i] = static_cast<signed char>(flip ? -sp[i] : sp[i]);
          }
        });
      }
    }
  }

  // Zero-temperature pass: flip while a flip strictly lowers the energy.
  if(schedule.final_zero_temperature_pass)
  {
    constexpr int max_zero_temperature_sweeps = 100;
    for(int sweep = 0; sweep < max_zero_temperature_sweeps; ++sweep)
    {
      std::atomic<bool> changed(false);
      for(std::size_t c = 0; c < number_of_colours; ++c)
      {
        for_chunks(class_begin[c], class_begin[c + 1], annealing_grain, [&](std::size_t lo, std::size_t hi) {
          bool local_change = false;
          for(std::size_t i = lo; i < hi; ++i)
          {
            if(sp[i] * local_field(i) > 0)  // dE = -2 S_i h < 0
            {
              sp[i] = static_cast<signed char>(-sp[i]);
              local_change = true;
            }
          }
          if(local_change)
            changed.store(true, std::memory_order_relaxed);
        });
      }
      if(!changed.load())
        break;
    }
  }

  for(std::size_t i = 0; i < number_of_free; ++i)
    signs[static_cast<std::size_t>(old_of_new[i])] = s[i];
  if(!release)
    return ising_energy(g, signs);
  // free-free edges appear in both rows, free-clamped ones in one
  std::int64_t twice = 0;
  for(std::size_t i = 0; i < number_of_free; ++i)
    for(std::size_t k = off[i]; k < off[i + 1]; ++k)
      twice += static_cast<std::int64_t>(ent[k].weight) * sp[i] * sp[ent[k].neighbor] *
               (static_cast<std::size_t>(ent[k].neighbor) < number_of_free ? 1 : 2);
  return clamped_energy + 0.5 * static_cast<double>(twice) / scale;
}
} // namespace ising_detail

inline double anneal(const Coupling_graph& g,
                     std::vector<signed char>& signs,
                     const std::vector<char>& clamped,
                     const Annealing_schedule& schedule,
                     std::uint64_t seed)
{
  return ising_detail::anneal(g, nullptr, signs, clamped, schedule, seed);
}

// The same, freeing the graph as soon as it is copied into the internal layout (the
// annealing would otherwise hold it twice); the returned energy uses the weights
// quantised to 2^-24 max |H_e|.
inline double anneal(Coupling_graph&& g,
                     std::vector<signed char>& signs,
                     const std::vector<char>& clamped,
                     const Annealing_schedule& schedule,
                     std::uint64_t seed)
{
  return ising_detail::anneal(g, &g, signs, clamped, schedule, seed);
}

/// \endcond

} // namespace internal
} // namespace ISM_reconstruction_3
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_INTERNAL_ISING_ANNEALING_H
