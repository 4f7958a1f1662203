// SPDX-License-Identifier: Apache-2.0
// Batch speed-up of compute_many(queries, out) against two plain std::threads computing halves
// into their own reused polygons (what the machine gives independent threads), as the
// median and best over 30 interleaved pairs of 1-thread/2-thread runs per map:
//   g++ -std=c++20 -O2 -DNDEBUG -I include bench/before_after/batch_ceiling.cpp \
//       build/libpreimage.a -lpolyclipping -lgmp -lmpfr -pthread -o batch_ceiling
//   ./batch_ceiling QUERIES MAP...   (QUERIES per batch, e.g. 500; floor plans as in maps.hpp)
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/queries.hpp>
#include "maps.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>
using namespace preimage::geometry;
double now() { return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
double median(std::vector<double> v) { std::sort(v.begin(), v.end()); return v[v.size() / 2]; }
int main(int argc, char** argv) {
  const auto maps = before_after::maps();
  const std::size_t N = std::stoul(argv[1]);
  for (int a = 2; a < argc; ++a) {
    const Environment env = maps.at(argv[a])();
    const VisibilityIndex vis(env);
    std::mt19937 rng(7);
    const auto b = env.bbox();
    std::uniform_real_distribution<double> X(b.xmin(), b.xmax()), Y(b.ymin(), b.ymax());
    std::vector<Point> qs;
    while (qs.size() < N) { Point q(X(rng), Y(rng)); if (locate(env, q).kind == Location::Kind::Interior) qs.push_back(q); }
    std::vector<VisibilityPolygon> o1, o2;
    std::vector<VisibilityPolygon> p1(N), p2(N);
    std::vector<double> pool, plain;
    for (int r = 0; r < 31; ++r) {
      double t0 = now(); vis.compute_many(qs, o1, 1); double t1 = now(); vis.compute_many(qs, o2, 2); double t2 = now();
      if (r > 0) pool.push_back((t1 - t0) / (t2 - t1));
      // plain: one thread all, then two threads halves (thread start inside the timing)
      double s0 = now(); for (std::size_t i = 0; i < N; ++i) vis.compute(qs[i], p1[i]); double s1 = now();
      std::thread h([&] { for (std::size_t i = N / 2; i < N; ++i) vis.compute(qs[i], p2[i]); });
      for (std::size_t i = 0; i < N / 2; ++i) vis.compute(qs[i], p2[i]);
      h.join(); double s2 = now();
      if (r > 0) plain.push_back((s1 - s0) / (s2 - s1));
    }
    std::printf("%-16s N=%zu  pool reused median %.2f (best %.2f)   plain threads median %.2f (best %.2f)\n", argv[a], N,
                median(pool), *std::max_element(pool.begin(), pool.end()), median(plain), *std::max_element(plain.begin(), plain.end()));
  }
}
