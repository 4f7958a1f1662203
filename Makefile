# Two commands on a fresh Debian machine: `make demo` and `make test`.
BUILD      ?= build
BENCH_BUILD?= build-bench
SAN_BUILD  ?= build-asan
FUZZ_SECONDS ?= 60
FUZZ_DIR   ?= $(SAN_BUILD)/fuzz-run
JOBS       ?= $(shell nproc)
BUILD_TYPE ?= Release
CMAKE_ARGS ?=

.PHONY: all deps deps-test build demo test bench install clean test-sanitize test-sanitize-ci fuzz

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
test: deps-test
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DPREIMAGE_BUILD_TESTS=ON $(CMAKE_ARGS)
	cmake --build $(BUILD) -j $(JOBS)
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
FUZZERS      = scene_json houseexpo visilibity geojson wkt beam_word beam_stream laser_log
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

# CI's share: every command-line test (each module's commands, the bad-input cases, the
# demo, the 10^5-vertex scenes) under the sanitizers; the unit-test binary is not built.
# Left out: cli.doc_examples and cli.help_examples, which run again the commands of the
# docs and of --help (the module tests run the same commands) and took 830 of the 1,780 s.
test-sanitize-ci: $(SAN_BUILD)/CMakeCache.txt
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(SAN_TESTS)
	cd $(SAN_BUILD) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -R '^(cli\.|large\.)' \
	  -E '^cli\.(doc|help)_examples$$'

# Each harness for FUZZ_SECONDS on a corpus seeded from tests/fixtures and examples,
# copied to $(FUZZ_DIR) (never written into the repository). A crash leaves its input in
# $(FUZZ_DIR)/artifacts and fails the target.
fuzz: $(SAN_BUILD)/CMakeCache.txt
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZERS))
	scripts/fuzz-run $(SAN_BUILD) $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZERS)

install: build
	cmake --install $(BUILD)

clean:
	rm -rf $(BUILD) $(BENCH_BUILD) $(SAN_BUILD)
