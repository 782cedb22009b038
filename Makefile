# clothbench: the two set-up commands of README.md, plus a few helpers.
#   make reproduce   install missing Debian packages, build Release, regenerate results/
#   make test        same set-up, then build and run every test with ctest
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
PACKAGES := cmake g++ make pkg-config libeigen3-dev libfcl-dev libembree-dev libosmesa6-dev \
            libassimp-dev assimp-testmodels libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev \
            libtomlplusplus-dev nlohmann-json3-dev libpng-dev python3-matplotlib
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
CTEST_FLAGS ?= --output-on-failure -LE 'slow|benchmark'

.PHONY: reproduce test test-sanitize deps configure build quick clean

reproduce: build
	$(BUILD)/bin/clothbench reproduce --out results

quick: build
	$(BUILD)/bin/clothbench reproduce --quick --out $(BUILD)/results-quick

test: build
	cd $(BUILD) && ctest $(CTEST_FLAGS) -j$(JOBS)

# AddressSanitizer + UndefinedBehaviorSanitizer build and test run (not part of CI: about 3x slower)
test-sanitize:
	$(MAKE) test BUILD=build-sanitize CMAKE_FLAGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCLOTHBENCH_SANITIZE=ON"

# install only what is missing (dpkg-query says which)
deps:
	@missing=$$(for p in $(PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

configure: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j$(JOBS)

clean:
	rm -rf $(BUILD)
