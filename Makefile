# Laser Workbench: `make run` opens the workbench on its built-in demo, `make test` runs every test.
# Both install missing Debian packages first (apt-get; sudo when not root).
BUILD  ?= build
JOBS   ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 600
SHARED_SLR ?= ../shared/data/slr

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

# Opens the workbench on its built-in demo. Without a display (no DISPLAY / WAYLAND_DISPLAY) it
# renders the demo window offscreen to $(BUILD)/demo.png instead and says so.
run: build
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then \
	  ./$(BUILD)/bin/laserwb; \
	else \
	  echo "make run: no display; rendering the demo offscreen to $(BUILD)/demo.png (set DISPLAY to open the window)"; \
	  ./$(BUILD)/bin/laserwb --screenshot $(BUILD)/demo.png && echo "make run: wrote $(BUILD)/demo.png"; \
	fi

# libFuzzer on the SLR readers (clang + ASan), FUZZ_SECONDS long; corpus and findings stay in $(FUZZ_BUILD).
fuzz:
	@LWB_FUZZ=1 ./.ci/install-deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DLWB_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build $(FUZZ_BUILD) -j$(JOBS) --target fuzz_slr_readers
	./tests/fuzz/make_seeds.sh $(SHARED_SLR) $(FUZZ_BUILD)/corpus
	mkdir -p $(FUZZ_BUILD)/artifacts
	./$(FUZZ_BUILD)/bin/fuzz_slr_readers $(FUZZ_BUILD)/corpus -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	  -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/artifacts/

bench: build
	./$(BUILD)/bin/laserwb-cli bench footprint

clean:
	rm -rf $(BUILD)
