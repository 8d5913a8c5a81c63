# ramus — the two commands of the README (`make run`, `make test`) and the developer targets.
# Every target installs what it needs first (`make deps`), so a fresh Debian machine works.
JOBS      ?= $(shell nproc)
BUILD     ?= build/release
ASAN      ?= build/asan
OUT       ?= out
CMAKE_GEN := -G Ninja
RAMUS     := $(BUILD)/ramus

.PHONY: all deps build run showcase test unit asan-test validate format format-check \
        bench bench-peers fuzz fuzz-smoke clean

all: build

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# Main job: build and generate the showcase into out/.
run: build
	@scripts/showcase.sh $(RAMUS) $(OUT)

showcase: run

# Everything CI checks: format, unit tests (Release + asserts), the glTF validator on every GLB
# the tests wrote, the CLI end-to-end checks, and the unit tests again under ASan+UBSan.
test: deps format-check unit validate asan-test fuzz-smoke
	@echo "make test: all checks passed"

unit: deps
	@cmake -S . -B $(BUILD)-checked $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release \
	  -DRAMUS_ENABLE_ASSERTS=ON -DRAMUS_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(BUILD)-checked -j $(JOBS)
	@rm -rf $(BUILD)-checked/test-output && mkdir -p $(BUILD)-checked/test-output
	cd $(BUILD)-checked && RAMUS_TEST_OUTPUT=$(CURDIR)/$(BUILD)-checked/test-output \
	  RAMUS_BIN=$(CURDIR)/$(BUILD)-checked/ramus ./ramus_tests --gtest_brief=1

validate: unit
	@node tests/validator/validate.mjs $(BUILD)-checked/test-output

asan-test: deps
	@cmake -S . -B $(ASAN) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAMUS_SANITIZE=ON \
	  -DRAMUS_ENABLE_ASSERTS=ON -DRAMUS_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(ASAN) -j $(JOBS)
	cd $(ASAN) && RAMUS_BIN=$(CURDIR)/$(ASAN)/ramus RAMUS_SLOW_TESTS=0 ./ramus_tests --gtest_brief=1

FORMAT_FILES = $(shell git ls-files '*.cpp' '*.hpp')
format: deps
	@clang-format -i $(FORMAT_FILES)

format-check: deps
	@clang-format --dry-run --Werror $(FORMAT_FILES) && echo "clang-format: ok"

bench: build
	$(BUILD)/ramus_bench --benchmark_counters_tabular=true

bench-peers: build
	@cd bench/peers && npm ci --no-audit --no-fund --loglevel=error
	@bench/peers/run.sh $(BUILD)

FUZZ      ?= build/fuzz
FUZZ_SECS ?= 600
fuzz-build: deps
	@CXX=clang++ cmake -S . -B $(FUZZ) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DRAMUS_BUILD_FUZZ=ON -DRAMUS_BUILD_TESTS=OFF -DRAMUS_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(FUZZ) -j $(JOBS)

fuzz: fuzz-build
	@scripts/fuzz.sh $(FUZZ) $(FUZZ_SECS)

fuzz-smoke: fuzz-build
	@scripts/fuzz.sh $(FUZZ) 20

clean:
	rm -rf build $(OUT)
