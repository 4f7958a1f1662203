#include "ratio_reporter.hpp"

#include <cstdio>

namespace preimage::bench {

void RatioReporter::ReportRuns(const std::vector<Run>& runs) {
  ConsoleReporter::ReportRuns(runs);
  for (const auto& r : runs) {
    if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
    const std::string name = r.benchmark_name();
    for (const char* side : {"preimage", "reference"}) {
      const std::string tag = std::string("/") + side + "/";
      auto at = name.find(tag);
      if (at == std::string::npos) continue;
      const std::string key = name.substr(0, at) + "/" + name.substr(at + tag.size());
      times_[key][side] = r.GetAdjustedRealTime();
    }
  }
}

void RatioReporter::Finalize() {
  ConsoleReporter::Finalize();
  std::printf("\nspeed-up of preimage over the reference (same run, real time per iteration):\n");
  for (const auto& [key, t] : times_) {
    auto p = t.find("preimage"), r = t.find("reference");
    if (p == t.end() || r == t.end()) continue;
    std::printf("  %-48s %10.2f x   (preimage %.3g, reference %.3g)\n", key.c_str(), r->second / p->second,
                p->second, r->second);
  }
}

int run_with_ratios(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}

}  // namespace preimage::bench
