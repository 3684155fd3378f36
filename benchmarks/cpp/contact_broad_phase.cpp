// Cost of the contact broad phase (kresling/contact/contact_broad_phase.hpp) from 1,000 to
// 100,000 triangles: a crumpled square sheet of unit cells (two triangles each, nodes
// jittered in the plane and out of it by 0.3), folded over on itself halfway so that half
// of it lies 0.5 above the other half (so contact candidates exist across the fold), at the
// distance d = 0.2 (a fifth of the mesh size) without and with a random step of up to 0.2
// per node (swept boxes). The last columns divide the time by n log2 n (n triangles) and
// by the first row's value: a flat ratio is O(n log n) growth. Times are processor times of
// this (single-threaded) process, the best of 3 to 5 runs.
//
// Run: build/py/contact_broad_phase  (built with KRESLING_BUILD_BENCHMARKS=ON).

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <random>

#include "kresling/contact/contact_broad_phase.hpp"

using namespace kresling;
using namespace kresling::contact;

namespace {

// Processor time of this process: the broad phase runs on one thread, and on a shared
// machine wall time also counts the other programs' turns.
double now() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

template <class F>
double best_of(F f, int repeat) {
  double best = 1e300;
  for (int i = 0; i < repeat; ++i) {
    const double start = now();
    f();
    best = std::min(best, now() - start);
  }
  return best;
}

struct Sheet {
  NodeMatrix nodes;
  TriangleMatrix triangles;
};

// An m x m grid of nodes, the half x > m / 2 folded back over the other half at height 0.5.
Sheet folded_sheet(int m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Sheet s;
  s.nodes.resize(m * m, 3);
  const double fold = 0.5 * (m - 1);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      double x = i + 0.2 * u(rng), z = 0.3 * u(rng);
      if (x > fold) {
        x = 2 * fold - x;  // mirrored over the fold line
        z = 0.5 - z;
      }
      s.nodes.row(i * m + j) << x, j + 0.2 * u(rng), z;
    }
  }
  s.triangles.resize(2 * (m - 1) * (m - 1), 3);
  Index t = 0;
  for (int i = 0; i + 1 < m; ++i) {
    for (int j = 0; j + 1 < m; ++j) {
      const Index a = i * m + j, b = a + m, c = a + 1, d = b + 1;
      s.triangles.row(t++) << a, b, c;
      s.triangles.row(t++) << c, b, d;
    }
  }
  return s;
}

}  // namespace

int main() {
  std::mt19937 rng(1);
  std::printf("%10s %9s %9s %11s %11s %10s %10s %13s %9s %13s %9s\n", "triangles", "nodes",
              "edges", "pt pairs", "ee pairs", "static ms", "swept ms", "static/nlogn",
              "ratio", "swept/nlogn", "ratio");
  double first_static = 0, first_swept = 0;
  for (int triangles : {1000, 3000, 10000, 30000, 100000}) {
    const int m = static_cast<int>(std::lround(std::sqrt(triangles / 2.0))) + 1;
    const Sheet sheet = folded_sheet(m, rng);
    const Index n = sheet.triangles.rows();
    NodeMatrix step(sheet.nodes.rows(), 3);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (Index i = 0; i < step.rows(); ++i) step.row(i) << u(rng), u(rng), u(rng);
    ContactCandidates found;
    const int repeat = n <= 10000 ? 5 : 3;
    // The edges are derived once per mesh by a caller, so their cost is timed with the rest.
    const double t_static = best_of(
        [&] {
          const EdgeMatrix edges = triangle_edges(sheet.triangles);
          found = contact_candidates(sheet.nodes, sheet.triangles, edges, 0.2);
        },
        repeat);
    const EdgeMatrix edges = triangle_edges(sheet.triangles);
    const double t_swept = best_of(
        [&] { contact_candidates(sheet.nodes, sheet.triangles, edges, 0.2, step); }, repeat);
    const double nlogn = n * std::log2(static_cast<double>(n));
    if (first_static == 0) {
      first_static = t_static / nlogn;
      first_swept = t_swept / nlogn;
    }
    std::printf("%10lld %9lld %9lld %11zu %11zu %10.2f %10.2f %10.2f ns %9.2f %10.2f ns %9.2f\n",
                static_cast<long long>(n), static_cast<long long>(sheet.nodes.rows()),
                static_cast<long long>(edges.rows()), found.point_triangle.size(),
                found.edge_edge.size(), 1e3 * t_static, 1e3 * t_swept, 1e9 * t_static / nlogn,
                t_static / nlogn / first_static, 1e9 * t_swept / nlogn,
                t_swept / nlogn / first_swept);
  }
  return 0;
}
