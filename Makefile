# clothbench: the two set-up commands of README.md, plus a few helpers.
#   make reproduce   install missing Debian packages, build Release, regenerate results/
#   make test        same set-up, then build and run every test with ctest
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
PACKAGES := cmake g++ make pkg-config libeigen3-dev libfcl-dev libembree-dev libosmesa6-dev \
            libegl-dev libegl-mesa0 \
            libassimp-dev assimp-testmodels libmeshoptimizer-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev \
            libtomlplusplus-dev nlohmann-json3-dev libpng-dev python3-matplotlib libboost-dev \
            libopenvdb-dev libboost-iostreams-dev valgrind libjs-three libjs-chart.js
# what only `make reproduce` needs (CI's `make test` stays lean): ffmpeg for the walking video, chromium for
# the screenshots of results/index.html
REPRODUCE_PACKAGES := ffmpeg chromium
# the headless browser of `make test`'s browser test (tests/browser), without recommends
BROWSER_PACKAGES := chromium
# the one-node Slurm cluster of `make test`'s cluster test (tools/slurm-local), without recommends
CLUSTER_PACKAGES := slurmctld slurmd slurm-client munge
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
CTEST_FLAGS ?= --output-on-failure -LE 'slow|benchmark'

.PHONY: reproduce test test-sanitize fuzz deps configure build quick clean perf-baseline bench-gpu

reproduce: build
	$(MAKE) deps PACKAGES="$(REPRODUCE_PACKAGES)"
	$(BUILD)/bin/clothbench reproduce --jobs $(shell nproc) --out results

quick: build
	$(BUILD)/bin/clothbench reproduce --quick --out $(BUILD)/results-quick

test: build
	$(MAKE) deps PACKAGES="$(CLUSTER_PACKAGES) $(BROWSER_PACKAGES)" APT_FLAGS=--no-install-recommends
	cd $(BUILD) && ctest $(CTEST_FLAGS) -j$(JOBS)

# the CI performance gate's baseline: instruction counts of perf/'s workloads under callgrind, rewritten
# into results/ci-baseline.json (commit it with the change that moved them; perf/README.md)
perf-baseline: build
	python3 perf/measure.py --workloads $(BUILD)/bin/clothbench_perf_workloads accept --baseline results/ci-baseline.json

# the GPU-relevant benchmarks in one command, for a machine with a GPU (docs/gpu.md): map rendering per
# renderer (OSMesa, EGL, CPU) at 320^2 / 512^2 / 1024^2 and the walking dress's 6 views x 5 layers, query batches
# (CPU, and is-egl on its device), and both walking garments of walking-t2 (skirt 672 v,
# dress with sleeves 2,300 v) with is-egl and is-cpu (every frame measured), each also with the next frame prepared
# on a second thread (body.prepare_ahead, -ahead.json), as JSON in $(BUILD)/bench-gpu/; each row names its device. CLOTHBENCH_EGL_DEVICE=N
# picks EGL device N (default: the first that is not Mesa's software device)
BENCH_GPU := $(BUILD)/bench-gpu
bench-gpu: build
	mkdir -p $(BENCH_GPU)
	$(BUILD)/bin/clothbench maps $(CURDIR)/scenes/data/body/mh_female_walk.glb --renderer egl --png $(BENCH_GPU)/maps
	$(BUILD)/bin/collide_is_bench --benchmark_filter='^(render|query)/' --benchmark_repetitions=3 \
	  --benchmark_out=$(BENCH_GPU)/map-render.json --benchmark_out_format=json
	for gv in skirt:672 dress_sleeves:2300; do for c in is-egl is-cpu; do for a in false true; do g=$${gv%:*}; \
	  $(BUILD)/bin/clothbench run scenes/walking/$$g.toml --collider $$c --set garment.vertices=$${gv#*:} \
	    --set body.prepare_ahead=$$a --every-frame --quiet \
	    --json $(BENCH_GPU)/walking-$$g-$$c$$([ $$a = true ] && echo -ahead).json || exit 1; done; done; done
	@echo "bench-gpu: JSON in $(BENCH_GPU)/ (map-render.json, walking-*.json)"

# AddressSanitizer + UndefinedBehaviorSanitizer build and test run (not part of CI: about 3x slower)
# (libOSMesa's own allocations are suppressed; the reproduce smoke test is too slow under ASan)
test-sanitize:
	LSAN_OPTIONS=suppressions=$(CURDIR)/cmake/lsan.supp $(MAKE) test BUILD=build-sanitize \
	  CMAKE_FLAGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCLOTHBENCH_SANITIZE=ON" \
	  CTEST_FLAGS="--output-on-failure -LE 'slow|benchmark|smoke'"

# libFuzzer targets (fuzz/) built with clang + ASan + UBSan in build-fuzz; each runs FUZZ_SECONDS,
# new inputs go to build-fuzz/corpus, crashes to build-fuzz/artifacts; exit 1 on any finding
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS := scene pattern garmentcode overrides body
FUZZ_CMAKE_FLAGS := -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer" \
  -DCLOTHBENCH_BUILD_FUZZ=ON -DCLOTHBENCH_BUILD_TESTS=OFF -DCLOTHBENCH_BUILD_BENCHMARKS=OFF \
  -DCLOTHBENCH_WITH_FCL=OFF -DCLOTHBENCH_WITH_EMBREE=OFF

fuzz: deps
	$(MAKE) deps PACKAGES=clang
	cmake -S . -B $(FUZZ_BUILD) $(FUZZ_CMAKE_FLAGS)
	cmake --build $(FUZZ_BUILD) -j$(JOBS) --target $(FUZZ_TARGETS:%=%_fuzz)
	@failed=0; for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$t $(FUZZ_BUILD)/artifacts; \
	  $(FUZZ_BUILD)/bin/$${t}_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -print_final_stats=1 \
	    -artifact_prefix=$(FUZZ_BUILD)/artifacts/$$t- $(FUZZ_BUILD)/corpus/$$t fuzz/corpus/$$t > $(FUZZ_BUILD)/fuzz-$$t.log 2>&1; \
	  rc=$$?; [ $$rc = 0 ] || failed=1; \
	  echo "$$t: $$(sed -n 's/^stat::number_of_executed_units: *//p' $(FUZZ_BUILD)/fuzz-$$t.log) executions in $(FUZZ_SECONDS) s," \
	    "$$(ls $(FUZZ_BUILD)/corpus/$$t | wc -l) inputs found so far, exit $$rc (log: $(FUZZ_BUILD)/fuzz-$$t.log)"; \
	done; exit $$failed

# install only what is missing (dpkg-query says which)
deps:
	@missing=$$(for p in $(PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $(APT_FLAGS) $$missing; \
	fi

configure: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j$(JOBS)

clean:
	rm -rf $(BUILD)
