# Two commands on a fresh Debian machine: `make demo` and `make test`.
BUILD      ?= build
BENCH_BUILD?= build-bench
JOBS       ?= $(shell nproc)
BUILD_TYPE ?= Release
CMAKE_ARGS ?=

.PHONY: all deps deps-test build demo test bench install clean

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

install: build
	cmake --install $(BUILD)

clean:
	rm -rf $(BUILD) $(BENCH_BUILD)
