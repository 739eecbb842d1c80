# The two commands of the README. Both install missing Debian packages, configure and build.
PRESET ?= release
BUILD := build/$(PRESET)
JOBS ?= $(shell nproc)
# Lets ccache reuse objects between clones of the repository.
export CCACHE_BASEDIR := $(CURDIR)

.PHONY: all setup configure build demo test test-clang test-slow asan tsan lint bench clean

all: build

setup:
	@bash scripts/setup

configure: setup
	@[ -f $(BUILD)/build.ninja ] || cmake --preset $(PRESET) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@$(BUILD)/cli/dtlab demo --out out/demo

# The release preset's test also runs the second compiler (test-clang).
test: build
	@ctest --test-dir $(BUILD) -LE slow -j $(JOBS) --output-on-failure
	@[ "$(PRESET)" != release ] || $(MAKE) --no-print-directory test-clang
	@LINT_REPORT=1 LINT_TIDY_MAX=6 BUILD=$(BUILD) bash scripts/lint

# The second compiler: predicates and kernel built with clang++ (-O2 with assertions,
# warnings as errors: the clang preset) and their non-slow tests run, the kernel's mesh
# checks after every flip included.
test-clang: setup
	@[ -f build/clang/build.ninja ] || cmake --preset clang >/dev/null
	@cmake --build build/clang -j $(JOBS)
	@ctest --test-dir build/clang -LE slow -j $(JOBS) --output-on-failure

# clang-format on the changed lines, clang-tidy (function size, bug checks) on the
# changed files; exit 1 on a finding (scripts/lint says how the base is chosen).
lint: build
	@BUILD=$(BUILD) bash scripts/lint

test-slow: build
	@ctest --test-dir $(BUILD) -L slow -j $(JOBS) --output-on-failure

asan:
	@$(MAKE) --no-print-directory test PRESET=asan

# ThreadSanitizer on what runs threads: the kernel's (parallel loop, writers), the
# checker's ([threads] cases: parallel == serial) and the Voronoi tests. The parallel
# peers ([peers]) are left out: Debian's oneTBB is not instrumented, so TSan reports
# CGAL's Parallel_tag insertion inside TBB's scheduler, which is not our code.
tsan: setup
	@[ -f build/tsan/build.ninja ] || cmake --preset tsan >/dev/null
	@cmake --build --preset tsan -j $(JOBS)
	@ctest --test-dir build/tsan -L 'kernel|voronoi' -LE slow -j $(JOBS) --output-on-failure
	@build/tsan/oracle/check/dtlab_oracle_check_tests "[threads]"

bench: build
	@$(BUILD)/bench/dtlab_bench_predicates

clean:
	rm -rf build out
