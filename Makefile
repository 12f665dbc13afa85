# Laser Workbench: `make run` opens the workbench on its built-in demo, `make test` runs every test.
# Both install missing Debian packages first (apt-get; sudo when not root).
BUILD  ?= build
JOBS   ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 30
FUZZ_TARGETS ?=
SANITIZE_BUILD ?= build-sanitize
SHARED_SLR ?= ../shared/data/slr
PREFIX ?= /usr/local

.PHONY: all deps configure build test test-sanitize run bench fuzz install deb clean screenshots translations

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

# Refreshes the Chinese translation's source (ui/i18n/laserwb_zh_CN.ts) from the code: the schema
# rows' texts first (ui/i18n/schema_strings.cpp), then lupdate. New strings come in unfinished;
# translate them in Qt Linguist (linguist ui/i18n/laserwb_zh_CN.ts) or in the XML; ui_test_translations
# fails until every one is.
translations: build
	./$(BUILD)/bin/lwb-i18n-strings ui/i18n/schema_strings.cpp
	cmake --build $(BUILD) --target update_translations

# Opens the workbench on its built-in demo. Without a display (no DISPLAY / WAYLAND_DISPLAY) it
# renders the demo window offscreen to $(BUILD)/demo.png instead and says so.
run: build
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then \
	  ./$(BUILD)/bin/laserwb; \
	else \
	  echo "make run: no display; rendering the demo offscreen to $(BUILD)/demo.png (set DISPLAY to open the window)"; \
	  ./$(BUILD)/bin/laserwb --screenshot $(BUILD)/demo.png && echo "make run: wrote $(BUILD)/demo.png"; \
	fi

# Every libFuzzer target (one per reader; clang, ASan + UBSan incl. float-cast-overflow), one after
# another, FUZZ_SECONDS each (FUZZ_TARGETS="crd json" for some; names without fuzz_). Prints each
# target's executions, rate and coverage; seeds, corpus, logs and findings stay in $(FUZZ_BUILD)
# (artifacts/). See docs/fuzzing.md.
fuzz:
	@LWB_CLANG=1 ./.ci/install-deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DLWB_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build $(FUZZ_BUILD) -j$(JOBS) --target fuzz_all
	./tests/fuzz/make_seeds.sh $(SHARED_SLR) $(FUZZ_BUILD)/seeds $(FUZZ_BUILD)/bin/fuzz_seeds
	./tests/fuzz/run_fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# The whole suite built with clang ASan + UBSan (incl. float-cast-overflow, no recovery) in
# $(SANITIZE_BUILD): any finding or leak (third-party suppressions: tests/sanitize/lsan.supp)
# fails. About 20 minutes from a clean tree on 2 cores (docs/fuzzing.md, "Sanitized suite");
# .ci/run runs it after make test when the CI budget allows.
test-sanitize:
	@LWB_CLANG=1 ./.ci/install-deps
	@[ -f $(SANITIZE_BUILD)/CMakeCache.txt ] || \
	  CC=clang CXX=clang++ cmake -S . -B $(SANITIZE_BUILD) -DLWB_SANITIZE=ON -DCMAKE_BUILD_TYPE=Release
	cmake --build $(SANITIZE_BUILD) -j$(JOBS)
	rm -f $(SANITIZE_BUILD)/sanitizer-reports/*
	@cd $(SANITIZE_BUILD) && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j$(JOBS); rc=$$?; \
	  if ls sanitizer-reports/* >/dev/null 2>&1; then \
	    echo "test-sanitize: sanitizer reports:"; cat sanitizer-reports/*; rc=1; fi; \
	  [ $$rc -eq 0 ] && echo "test-sanitize: suite green under ASan + UBSan"; exit $$rc

# Installs the programs, man pages, desktop entry, icon, metainfo, bash completion and docs under
# PREFIX (default /usr/local; `make install PREFIX=$$HOME/.local` needs no root). Through sudo when
# PREFIX is not writable and you are not root.
install: build
	@if [ -w "$(PREFIX)" ] || { [ ! -e "$(PREFIX)" ] && [ -w "$$(dirname "$(PREFIX)")" ]; } || [ "$$(id -u)" -eq 0 ]; then \
	  cmake --install $(BUILD) --prefix "$(PREFIX)"; \
	else \
	  sudo cmake --install $(BUILD) --prefix "$(PREFIX)"; \
	fi

# The Debian package (build/laserwb_VERSION_ARCH.deb): install it with `sudo apt install ./build/laserwb_*.deb`.
deb: build
	cd $(BUILD) && cpack -G DEB

bench: build
	./$(BUILD)/bin/laserwb-cli bench footprint

clean:
	rm -rf $(BUILD)

# The small-screen screenshots of docs/screens.md: every workspace on the built-in demo in a
# 1024x700 window and at 150 % scaling on 1920x1080 (1280x720 logical), each with fresh settings.
SCREENS := footprint footprint:trend slr calibration calibration:waveform radiometry
screenshots: build
	@mkdir -p docs/img/screens
	@for lang in en zh_CN; do sfx=$$([ $$lang = en ] || echo -$$lang); \
	 for ws in $(SCREENS); do n=$$(echo $$ws | tr : -)$$sfx; cfg=$$(mktemp -d); \
	  QT_QPA_PLATFORM=offscreen XDG_CONFIG_HOME=$$cfg ./$(BUILD)/bin/laserwb --language $$lang --workspace $$ws \
	    --size 1024x700 --screenshot docs/img/screens/$$n-1024x700.png 2>/dev/null && \
	  QT_QPA_PLATFORM=offscreen QT_SCALE_FACTOR=1.5 XDG_CONFIG_HOME=$$cfg ./$(BUILD)/bin/laserwb --language $$lang --workspace $$ws \
	    --size 1280x720 --screenshot docs/img/screens/$$n-150pct.png 2>/dev/null && \
	  rm -rf $$cfg && echo "screenshots: $$n"; done; done
