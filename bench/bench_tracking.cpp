// SPDX-License-Identifier: Apache-2.0
// One TRACK iteration (section IV) on a laser scan of the cluttered lab, split by stage,
// at 360 and 720 readings; and the escape-path tree against the brute-force oracle
// (visibility graph + Dijkstra) on the same local map. Target: >= 100,000 iterations/s.
// And the simulated scan of the evaluation's inner loop against a ray cast per beam.
#include <preimage/geometry/queries.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/tracker.hpp>

#include "ratio_reporter.hpp"
#include "support/escape_oracle.hpp"

#include <benchmark/benchmark.h>

#include <map>

using namespace preimage;
using namespace preimage::tracking;

namespace {

const scene::Scene& lab_scene() {
  static const scene::Scene sc = scene::load_scene(std::string(PREIMAGE_BENCH_EXAMPLES) + "/tracking/lab.json");
  return sc;
}

struct Case {
  Scan scan;
  LocalMap map;
  Point target;
  TrackerParams params;
};

const Case& scan_case(std::size_t beams) {
  static std::map<std::size_t, Case> cases;
  auto it = cases.find(beams);
  if (it != cases.end()) return it->second;
  const auto& env = lab_scene().require_environment();
  LaserSpec spec;
  spec.beams = beams;
  spec.noise_sigma = 0.01;
  std::mt19937_64 rng(1);
  Case c;
  c.target = Point(3.0, -0.4);  // sensor frame: the target 3 m ahead, a little right
  c.scan = simulate_scan(env, Pose{Point(2, 6), 0.0}, spec, Disc{Point(5, 5.6), 0.2}, &rng);
  const Detection d = detect_target(c.scan, c.params.detect);
  if (!d.found) throw std::runtime_error("bench: target not detected");
  c.target = d.center;
  c.map = local_map_without_target(c.scan, d, c.params.map);
  return cases.emplace(beams, std::move(c)).first->second;
}

void full(benchmark::State& st) {
  const Case& c = scan_case(static_cast<std::size_t>(st.range(0)));
  for (auto _ : st) {
    TrackStep s = track(c.scan, c.params, c.target);
    benchmark::DoNotOptimize(s.control.command);
  }
  st.counters["iterations/s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}
void stage_detect(benchmark::State& st) {
  const Case& c = scan_case(static_cast<std::size_t>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(detect_target(c.scan, c.params.detect, c.target));
}
void stage_map(benchmark::State& st) {  // points -> polylines -> V
  const Case& c = scan_case(static_cast<std::size_t>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(local_map_from_scan(c.scan, c.params.map));
  st.counters["vertices"] = static_cast<double>(c.map.size());
}
void stage_ept(benchmark::State& st) {
  const Case& c = scan_case(static_cast<std::size_t>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(escape_path_tree(c.map, c.target));
  st.counters["free_edges"] = static_cast<double>(escape_path_tree(c.map, c.target).paths.size());
}
void stage_gradient(benchmark::State& st) {
  const Case& c = scan_case(static_cast<std::size_t>(st.range(0)));
  const EscapePathTree tree = escape_path_tree(c.map, c.target);
  for (auto _ : st) {
    const auto risks = escape_risks(c.map, tree, c.params.risk);
    benchmark::DoNotOptimize(recursive_average(tree, risks));
  }
}
void stage_command(benchmark::State& st) {
  const Case& c = scan_case(static_cast<std::size_t>(st.range(0)));
  const RiskAverage risk{0.5, Vec2{0.3, -0.2}};
  for (auto _ : st) benchmark::DoNotOptimize(risk_control(risk, c.target, c.params.control));
}
// Simulated scans, the evaluation's inner loop: all beams at once against one
// geometry::ray_range call per beam (its trigonometry and all walls per beam).
const Pose kScanPose{Point(2, 6), 0.3};
const Disc kScanTarget{Point(5, 5.6), 0.2};
void scan_batch(benchmark::State& st) {
  const auto& env = lab_scene().require_environment();
  for (auto _ : st) benchmark::DoNotOptimize(simulate_scan(env, kScanPose, LaserSpec{}, kScanTarget));
}
void scan_per_beam(benchmark::State& st) {
  const auto& env = lab_scene().require_environment();
  const LaserSpec spec;
  std::vector<double> ranges(spec.beams);
  for (auto _ : st) {
    for (std::size_t i = 0; i < spec.beams; ++i) {
      const double a = kScanPose.heading - M_PI + 2 * M_PI * static_cast<double>(i) / static_cast<double>(spec.beams);
      double r = geometry::ray_range(env, kScanPose.position, a, spec.max_range);
      const double dx = std::cos(a), dy = std::sin(a);
      const double cx = kScanTarget.center.x() - kScanPose.position.x(), cy = kScanTarget.center.y() - kScanPose.position.y();
      const double b = cx * dx + cy * dy, c = cx * cx + cy * cy - kScanTarget.radius * kScanTarget.radius;
      if (b * b - c >= 0 && b - std::sqrt(b * b - c) > 0) r = std::min(r, b - std::sqrt(b * b - c));
      ranges[i] = r;
    }
    benchmark::DoNotOptimize(ranges.data());
  }
}

void ept_brute(benchmark::State& st) {
  const Case& c = scan_case(static_cast<std::size_t>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(preimage::testing::brute_force_sde(c.map, c.target));
}

}  // namespace

BENCHMARK(full)->Name("track-iteration")->ArgName("beams")->Arg(360)->Arg(720)->Unit(benchmark::kMicrosecond);
BENCHMARK(stage_detect)->Name("stage/1-detection")->ArgName("beams")->Arg(360)->Arg(720)->Unit(benchmark::kMicrosecond);
BENCHMARK(stage_map)->Name("stage/2-polylines+V")->ArgName("beams")->Arg(360)->Arg(720)->Unit(benchmark::kMicrosecond);
BENCHMARK(stage_ept)->Name("stage/3-escape-path-tree")->ArgName("beams")->Arg(360)->Arg(720)->Unit(benchmark::kMicrosecond);
BENCHMARK(stage_gradient)->Name("stage/4-gradient")->ArgName("beams")->Arg(360)->Arg(720)->Unit(benchmark::kMicrosecond);
BENCHMARK(stage_command)->Name("stage/5-command")->ArgName("beams")->Arg(360)->Unit(benchmark::kMicrosecond);
BENCHMARK(stage_ept)->Name("escape-paths/preimage")->ArgName("beams")->Arg(720)->Unit(benchmark::kMicrosecond);
BENCHMARK(ept_brute)->Name("escape-paths/reference")->ArgName("beams")->Arg(720)->Unit(benchmark::kMicrosecond);
BENCHMARK(scan_batch)->Name("simulated-scan/preimage/lab-360-beams")->Unit(benchmark::kMicrosecond);
BENCHMARK(scan_per_beam)->Name("simulated-scan/reference/lab-360-beams")->Unit(benchmark::kMicrosecond);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
