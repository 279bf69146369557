// Throughput and memory of Bisection_triangulation_3: leaf bisections per second and
// bytes per leaf, for uniform refinement to ~1.6 M / 3.1 M leaves and for adaptive
// refinement around 100k points on a sphere. Run a Release build on an idle machine.
// Like ism_reconstruct, it restarts itself once with glibc's large blocks on transparent
// huge pages (internal/huge_pages.h; ISM_NO_HUGE_PAGES=1 for normal pages).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bisection_triangulation_3.h>
#include <CGAL/ISM_reconstruction_3/internal/huge_pages.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Timer.h>

#include <cmath>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bisection_triangulation_3<K> BT;
typedef K::Point_3 P;

int main(int argc, char** argv)
{
  CGAL::ISM_reconstruction_3::internal::restart_with_huge_pages(argv);
  const int uniform_level = argc > 1 ? std::atoi(argv[1]) : 18;
  std::cout << "| case | leaves | bisections | time (s) | bisections/s | bytes/leaf |\n|---|---|---|---|---|---|\n";
  for(int level : {uniform_level, uniform_level + 1})
  {
    BT bt(K::Iso_cuboid_3(P(0, 0, 0), P(1, 1, 1)));
    CGAL::Real_timer t;
    CGAL::Timer cpu;  // user time: the page faults of fresh memory show in wall time only
    t.start(); cpu.start();
    bt.refine_uniformly(level);
    t.stop(); cpu.stop();
    const double bisections = double(bt.number_of_leaves() - 6);
    std::cout << "| uniform level " << level << " | " << bt.number_of_leaves() << " | " << bisections << " | "
              << t.time() << " | " << bisections / t.time() / 1e6 << " M (" << bisections / cpu.time() / 1e6
              << " M per CPU second) | " << double(bt.memory_usage()) / double(bt.number_of_leaves()) << " |\n";
  }
  {
    CGAL::Random rnd(1);
    std::vector<P> pts;
    for(int i = 0; i < 100000; ++i)
    {
      double x = rnd.get_double(-1, 1), y = rnd.get_double(-1, 1), z = rnd.get_double(-1, 1);
      const double n = std::sqrt(x * x + y * y + z * z);
      pts.push_back(P(0.5 + 0.4 * x / n, 0.5 + 0.4 * y / n, 0.5 + 0.4 * z / n));
    }
    BT bt(K::Iso_cuboid_3(P(0, 0, 0), P(1, 1, 1)));
    // points partitioned in place: each cell owns a contiguous range of one index array
    std::vector<int> index(pts.size());
    for(int i = 0; i < int(pts.size()); ++i) index[i] = i;
    std::vector<std::array<int, 2> > range(6, {{0, 0}});
    std::sort(index.begin(), index.end(), [&](int a, int b) { return bt.locate_root(pts[a]) < bt.locate_root(pts[b]); });
    for(int i = 0, r = 0; r < 6; ++r)
    {
      range[r][0] = i;
      while(i < int(index.size()) && bt.locate_root(pts[index[i]]) == r) ++i;
      range[r][1] = i;
    }
    CGAL::Real_timer t;
    t.start();
    bt.refine([&](BT::Cell_index c) { return range[c][1] - range[c][0] > 1; }, 27,
              [&](BT::Cell_index p, BT::Cell_index c0, BT::Cell_index c1) {
                range.resize(bt.number_of_cells());
                auto mid = std::partition(index.begin() + range[p][0], index.begin() + range[p][1],
                                          [&](int i) { return bt.child_side(p, pts[i]) == 0; });
                const int m = int(mid - index.begin());
                range[c0] = {{range[p][0], m}};
                range[c1] = {{m, range[p][1]}};
              });
    t.stop();
    const double bisections = double(bt.number_of_leaves() - 6);
    const double peak = double(bt.memory_usage()) / double(bt.number_of_leaves());
    bt.shrink_to_fit();
    std::cout << "| adaptive, 100k points on a sphere, level 27 | " << bt.number_of_leaves() << " | " << bisections
              << " | " << t.time() << " | " << bisections / t.time() / 1e6 << " M | "
              << double(bt.memory_usage()) / double(bt.number_of_leaves()) << " (" << peak
              << " before shrink_to_fit) |\n";
  }
  return 0;
}
