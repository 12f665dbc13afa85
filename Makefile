# Laser Workbench: `make run` opens the workbench on its built-in demo, `make test` runs every test.
# Both install missing Debian packages first (apt-get; sudo when not root).
BUILD  ?= build
JOBS   ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps configure build test run bench fuzz clean

all: build

deps:
	@./.ci/install-deps

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j$(JOBS)

test: build
	cd $(BUILD) && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j$(JOBS)

run: build
	./$(BUILD)/bin/laserwb-cli demo

bench: build
	./$(BUILD)/bin/laserwb-cli bench footprint

clean:
	rm -rf $(BUILD)
