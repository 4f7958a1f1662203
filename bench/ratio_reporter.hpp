// Console reporter that also prints, for every benchmark named ".../reference/<case>"
// and ".../preimage/<case>", the speed-up of preimage over the reference in the same run.
#pragma once
#include <benchmark/benchmark.h>

#include <map>
#include <string>

namespace preimage::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override;

 private:
  std::map<std::string, std::map<std::string, double>> times_;  // case -> {preimage, reference} -> ns
};

/// Runs all benchmarks with the ratio reporter on the console (and --benchmark_out as usual).
int run_with_ratios(int argc, char** argv);

}  // namespace preimage::bench
