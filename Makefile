# Two commands on a fresh Debian machine: `make demo` and `make test`.
BUILD      ?= build
BENCH_BUILD?= build-bench
SAN_BUILD  ?= build-asan
FUZZ_SECONDS ?= 60
FUZZ_DIR   ?= $(SAN_BUILD)/fuzz-run
JOBS       ?= $(shell nproc)
BUILD_TYPE ?= Release
CMAKE_ARGS ?=

.PHONY: all deps deps-test build demo test test-build bench install clean test-sanitize test-sanitize-ci \
        test-sanitize-ci-build fuzz fuzz-long

all: build

deps:
	@scripts/install-deps

deps-test:
	@scripts/install-deps --test

# A first configure builds no tests, so `make demo` needs neither GoogleTest nor a browser;
# `make test` turns them on in the same tree (the library's objects are reused).
$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DPREIMAGE_BUILD_TESTS=OFF $(CMAKE_ARGS)

# The library and the tool only: what `make demo` needs.
build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target preimage_cli

demo: build
	$(BUILD)/preimage demo --out $(BUILD)/demo

# Everything (tests included), then the whole suite.
test-build: deps-test
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DPREIMAGE_BUILD_TESTS=ON $(CMAKE_ARGS)
	cmake --build $(BUILD) -j $(JOBS)

test: test-build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Benchmarks build in Release in their own tree; results go to build/bench/*.json.
bench: deps-test
	cmake -S . -B $(BENCH_BUILD) -DCMAKE_BUILD_TYPE=Release -DPREIMAGE_BUILD_TESTS=OFF -DPREIMAGE_BUILD_BENCH=ON
	cmake --build $(BENCH_BUILD) -j $(JOBS)
	mkdir -p $(BUILD)/bench
	@for b in $(BENCH_BUILD)/bench/bench_*; do \
	  [ -x "$$b" ] || continue; n=$$(basename $$b); \
	  echo "== $$n"; "$$b" --benchmark_out=$(BUILD)/bench/$$n.json --benchmark_out_format=json || exit 1; \
	done

# Checks (docs/reliability.md). One tree, $(SAN_BUILD), built by clang++ with
# AddressSanitizer + UndefinedBehaviorSanitizer on everything and the libFuzzer harnesses
# of tests/fuzz: the sanitizer suite and the fuzzers share its (slow) library build.
SAN_TESTS    = preimage_cli preimage_large_scenes
FUZZERS      = scene_json houseexpo visilibity geojson wkt export pursuit_paths beam_word beam_stream laser_log
SAN_ENV      = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

$(SAN_BUILD)/CMakeCache.txt:
	@scripts/install-deps --checks
	cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
	  -DPREIMAGE_SANITIZE=ON -DPREIMAGE_FUZZ=ON -DPREIMAGE_PYTHON=OFF $(CMAKE_ARGS)

# The whole suite under the sanitizers, but install.find_package (its consumer project links
# the instrumented library without the sanitizer runtime: it tests packaging, not code).
test-sanitize: $(SAN_BUILD)/CMakeCache.txt
	cmake --build $(SAN_BUILD) -j $(JOBS)
	cd $(SAN_BUILD) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -E '^install\.'

# CI's share (docs/reliability.md): for every command the cheapest command-line test that
# must succeed and the cheapest that must fail (scripts/sanitize-subset, costs from the
# Release suite's last run in $(BUILD)), and the generator of the 10^5-vertex scenes; the
# unit-test binary is not built. `make test-sanitize` runs everything.
test-sanitize-ci-build: $(SAN_BUILD)/CMakeCache.txt
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(SAN_TESTS)

test-sanitize-ci: test-sanitize-ci-build
	cd $(SAN_BUILD) && subset=$$($(CURDIR)/scripts/sanitize-subset . $(abspath $(BUILD))) && \
	  $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -R "$$subset"

# Each harness for FUZZ_SECONDS on a corpus seeded from tests/fixtures and examples,
# copied to $(FUZZ_DIR) (never written into the repository), FUZZ_PARALLEL at a time. A
# crash leaves its input in $(FUZZ_DIR)/artifacts and fails the target.
FUZZ_PARALLEL ?= 1
fuzz: $(SAN_BUILD)/CMakeCache.txt
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZERS))
	FUZZ_PARALLEL=$(FUZZ_PARALLEL) scripts/fuzz-run $(SAN_BUILD) $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZERS)

# Beyond CI: each harness to FUZZ_RUNS executions or FUZZ_LONG_SECONDS, whichever comes
# first, continuing from the corpus earlier runs left in $(FUZZ_DIR).
FUZZ_RUNS ?= 10000000
FUZZ_LONG_SECONDS ?= 3600
fuzz-long: $(SAN_BUILD)/CMakeCache.txt
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZERS))
	FUZZ_PARALLEL=$(FUZZ_PARALLEL) FUZZ_RUNS=$(FUZZ_RUNS) scripts/fuzz-run $(SAN_BUILD) $(FUZZ_DIR) $(FUZZ_LONG_SECONDS) $(FUZZERS)

install: build
	cmake --install $(BUILD)

clean:
	rm -rf $(BUILD) $(BENCH_BUILD) $(SAN_BUILD)
