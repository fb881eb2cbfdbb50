// SPDX-License-Identifier: GPL-3.0-or-later
// Exact against filtered kernels (a report driver, not a timed test): the orientation of
// three points, the predicate behind every verdict of validation (touching, crossing, inside),
// on easy triples and on nearly collinear ones (where a wall end touches another wall), with
// plain doubles (Simple_cartesian<double>), CGAL's filtered exact predicates (Epick, as
// roomcad uses) and unfiltered exact rationals (Simple_cartesian<Gmpq>). Wrong signs are
// counted against the exact answer. Prints CSV: kernel,triples,ns_per_test,wrong_pct.
//   kernel_bench [TRIPLES]
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

namespace {

struct Triple {
  double x[3], y[3];
};

/// SplitMix64, so every run tests the same triples.
std::uint64_t next(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
double uniform(std::uint64_t& state) { return static_cast<double>(next(state) >> 11) * 0x1.0p-53; }

/// Nearly collinear: Kettner et al.'s classroom example (a point a few ulps off (0.5, 0.5),
/// and (12, 12), (24, 24)), where rounding decides the sign; or random triples 1e6 m away.
std::vector<Triple> make_triples(std::size_t n, bool near_collinear) {
  std::uint64_t state = near_collinear ? 1 : 2;
  std::vector<Triple> out(n);
  const double ulp = 0x1p-53;
  for (Triple& t : out) {
    if (near_collinear) {
      const double px = 0.5 + static_cast<double>(next(state) % 256) * ulp;
      const double py = 0.5 + static_cast<double>(next(state) % 256) * ulp;
      t = Triple{{px, 12.0, 24.0}, {py, 12.0, 24.0}};
    } else {
      const double ax = 1e6 + 10 * uniform(state), ay = -1e6 + 10 * uniform(state);
      t = Triple{{ax, ax + 5 * uniform(state), ax + 5 * uniform(state)},
                 {ay, ay + 5 * uniform(state), ay + 5 * uniform(state)}};
    }
  }
  return out;
}

template <class K>
std::vector<int> orientations(const std::vector<Triple>& triples, double& ns) {
  using P = typename K::Point_2;
  std::vector<int> signs(triples.size());
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < triples.size(); ++i) {
    const Triple& t = triples[i];
    signs[i] = static_cast<int>(
        CGAL::orientation(P(t.x[0], t.y[0]), P(t.x[1], t.y[1]), P(t.x[2], t.y[2])));
  }
  ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
       static_cast<double>(triples.size());
  return signs;
}

void report(const char* kernel, const char* set, const std::vector<int>& got,
            const std::vector<int>& exact, double ns) {
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < got.size(); ++i) wrong += got[i] != exact[i];
  std::printf("%s,%s,%zu,%.1f,%.3f\n", kernel, set, got.size(), ns,
              100.0 * static_cast<double>(wrong) / static_cast<double>(got.size()));
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 200000;
  std::printf("kernel,triples,count,ns_per_test,wrong_pct\n");
  for (const bool near : {false, true}) {
    const std::vector<Triple> triples = make_triples(n, near);
    const char* set = near ? "nearly collinear (classroom example)" : "random at 1e6 m";
    double ns_exact = 0, ns_double = 0, ns_filtered = 0;
    const auto exact = orientations<CGAL::Simple_cartesian<CGAL::Gmpq>>(triples, ns_exact);
    const auto plain = orientations<CGAL::Simple_cartesian<double>>(triples, ns_double);
    const auto filtered = orientations<CGAL::Epick>(triples, ns_filtered);
    report("double", set, plain, exact, ns_double);
    report("Epick (filtered)", set, filtered, exact, ns_filtered);
    report("Gmpq (exact)", set, exact, exact, ns_exact);
  }
  return 0;
}
