// Per-query visibility time on bench_visibility's maps, for before/after comparisons of
// two commits in one run (interleaved by compare.py). Uses only API that commit 73df79e
// (the code issue 29 found) already had, so it builds against either library:
//   g++ -std=c++20 -O3 -DNDEBUG [-DREUSED] -I <tree>/include visibility_times.cpp \
//       <tree>/build/libpreimage.a -lpolyclipping -lgmp -lmpfr -o times_<name>
// -DREUSED times compute(q, out) into one polygon (not in 73df79e); without it compute(q)
// by value. `times gen MAP...` writes 500 interior queries per map (uniform in the box,
// fixed seed) to $PREIMAGE_QUERIES (default /tmp), `times time MAP...` prints
// "map us_per_query checksum" (the checksum, of the output sizes, must agree). Time is the
// thread's CPU time (as the issue measured), which leaves out time the virtual machine
// takes the core away; wall time on this machine varied up to 1.7x between rounds.
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/queries.hpp>
#include "maps.hpp"
#include <ctime>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
using namespace preimage::geometry;
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
int main(int argc, char** argv) {
  const auto maps = before_after::maps();
  const std::string mode = argv[1];  // gen | time
  for (int a = 2; a < argc; ++a) {
    const std::string name = argv[a];
    const Environment env = maps.at(name)();
    const VisibilityIndex vis(env);
    std::vector<Point> qs;
    const std::string qf = before_after::env_or("PREIMAGE_QUERIES", "/tmp") + "/q-" + name + ".txt";
    if (mode == "gen") {
      std::mt19937 rng(7);
      const auto b = env.bbox();
      std::uniform_real_distribution<double> X(b.xmin(), b.xmax()), Y(b.ymin(), b.ymax());
      std::ofstream o(qf);
      o.precision(17);
      while (qs.size() < 500) {
        Point q(X(rng), Y(rng));
        if (locate(env, q).kind != Location::Kind::Interior) continue;
        qs.push_back(q);
        o << q.x() << " " << q.y() << "\n";
      }
      continue;
    }
    std::ifstream in(qf);
    double x, y;
    while (in >> x >> y) qs.push_back(Point(x, y));
    std::size_t sum = 0;
    for (auto& q : qs) sum += vis.compute(q).vertices.size();
    const int reps = std::max<int>(1, static_cast<int>(200000 / (env.num_vertices() * qs.size() / 100 + 1)));
    const double t0 = thread_seconds();
#ifdef REUSED
    VisibilityPolygon out;
    for (int r = 0; r < reps; ++r)
      for (auto& q : qs) vis.compute(q, out), sum += out.vertices.size();
#else
    for (int r = 0; r < reps; ++r)
      for (auto& q : qs) sum += vis.compute(q).vertices.size();
#endif
    const double t1 = thread_seconds();
    std::printf("%s %.4f %zu\n", name.c_str(), 1e6 * (t1 - t0) / (reps * qs.size()), sum % 1000);
  }
}
