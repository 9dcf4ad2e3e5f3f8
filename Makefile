# The two commands of the README, and a few more. Each installs missing Debian packages,
# configures once and builds incrementally.
BUILD      ?= build
JOBS       ?= $(shell nproc)
SCENE      ?= models/ring_inelastic.toml
CMAKE_ARGS ?=
# Ninja compiles a library's dependants while the library itself is still being built, where
# make waits for it: the first build on two cores takes 95 s instead of 115 s. A build folder keeps
# the generator it was first configured with.
configure = cmake -S . -B $(1) $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)

.PHONY: run test deps build python bench test-sanitize test-slurm fuzz update-snapshots clean

deps:
	@./scripts/install-deps.sh

$(BUILD)/CMakeCache.txt: | deps
	$(call configure,$(BUILD)) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

# The build ends by installing the Python module for Debian's python3 (docs/python.md).
build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)
	@cmake --install $(BUILD) --component python > /dev/null && echo "import plastica: installed for /usr/bin/python3"

# The module for another interpreter (a venv, pyenv, conda): make python PYTHON=/path/to/python.
# pip builds it with python/build_backend (no download) from this build where the ABI matches.
PYTHON ?=
python: build
	@test -n "$(PYTHON)" || { echo "make python PYTHON=/path/to/python: name the interpreter (Debian's python3 has it already)"; exit 2; }
	PLASTICA_BUILD_DIR=$(abspath $(BUILD)) $(PYTHON) -m pip install --no-build-isolation --force-reinstall --no-deps ./python

# The headline job: the elastic ring, then the inelastic ring with the elastic curve in its chart
# and its shapes beside. The elastic ring is drawn while the inelastic one is solved and drawn: each
# picture stage leaves a core idle at its start and its end, which the other fills.
# The two drawings share the cores: half each (one drawing process per core in all, where each on
# its own would start one per core and pay for two offscreen contexts on one core).
ifeq ($(SCENE),models/ring_inelastic.toml)
DRAW_JOBS = $(shell n=$$(( $(JOBS) / 2 )); [ $$n -ge 1 ] || n=1; echo $$n)
RUN_FIRST = $(BUILD)/cli/plastica run models/ring_elastic.toml -q --no-render && \
	{ $(BUILD)/cli/plastica render out/ring_elastic -q -j $(DRAW_JOBS) & elastic=$$!; } &&
RUN_ARGS  = --overlay out/ring_elastic --shapes 25,50,75,100 -j $(DRAW_JOBS)
RUN_LAST  = ; status=$$?; wait $$elastic && exit $$status
endif

# Builds only the program it runs (plastica and the plastica-draw it hands drawing to); make test
# builds the rest.
run: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target plastica
	$(RUN_FIRST) $(BUILD)/cli/plastica run $(SCENE) $(RUN_ARGS) $(RUN_LAST)

# The report test opens pages in a real browser: headless Chromium (Debian's chromium).
test: build
	@./scripts/install-deps.sh chromium
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The suite under AddressSanitizer + UndefinedBehaviorSanitizer checks memory and undefined
# behaviour: it leaves out the snapshots' pixels (tests/CMakeLists.txt) and the numerical checks
# that take over 30 s under the sanitizers, long paths of yielding and contact whose code the rest
# of the suite runs there too: the robustness matrix (7 minutes, 45 s in Release), every key of
# every scene set by its path (189 s), the crushings and flattenings along the members (35–152 s
# each) and Vogel's frame (42 s). The Release suite makes every one of them (docs/ci.md).
RELEASE_ONLY = Robustness matrix|Every key of every shipped scene|crushed onto a steel bed|flattened between plates acting along|crushed between plates acting along|six-storey frame reaches|pipe ring flattened between plates stops|plate.s direction through a flattening|perfectly plastic ring on 64 elements|flattening test reports the load
test-sanitize: deps
	@./scripts/install-deps.sh chromium
	$(call configure,build-sanitize) -DCMAKE_BUILD_TYPE=Debug -DPLASTICA_SANITIZE=ON $(CMAKE_ARGS)
	cmake --build build-sanitize -j $(JOBS)
	cd build-sanitize && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	  ctest --output-on-failure -j $(JOBS) -E '$(RELEASE_ONLY)'

# A one-node Slurm on this host runs the ring's 3 × 3 sweep as a job array; its sweep.csv must
# equal the in-process one (scripts/test-slurm.sh). Installs slurm-wlm and munge when missing.
test-slurm: build
	@./scripts/install-deps.sh slurm-wlm munge bc
	scripts/test-slurm.sh $(BUILD)/cli/plastica .

bench: deps
	$(call configure,build-bench) -DCMAKE_BUILD_TYPE=Release -DPLASTICA_BENCH=ON -DPLASTICA_TESTS=OFF -DPLASTICA_LTO=ON
	cmake --build build-bench -j $(JOBS) --target plastica_bench
	build-bench/bench/plastica_bench

# Fuzzes, for FUZZ_SECONDS each, the readers of what comes from outside (clang's libFuzzer, ASan +
# UBSan): scene files, --set overrides, PNGs given to compare, result folders given to report
# and merge, and the step files plastica.open reads. Crashes land in build-fuzz/findings/ and become test cases (tests/test_scene_errors.cpp,
# tests/test_cli_untrusted.cpp).
FUZZ_SECONDS ?= 120
FUZZERS = scene_reader_fuzzer override_fuzzer png_decode_fuzzer result_folder_fuzzer vtu_reader_fuzzer
fuzz:
	@./scripts/install-deps.sh clang
	$(call configure,build-fuzz) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DPLASTICA_FUZZ=ON -DPLASTICA_TESTS=OFF
	cmake --build build-fuzz -j $(JOBS) --target $(FUZZERS)
	mkdir -p build-fuzz/findings $(addprefix build-fuzz/corpus/,$(FUZZERS))
	cp models/*.toml build-fuzz/corpus/scene_reader_fuzzer/
	printf 'material[1].fy=250' > build-fuzz/corpus/override_fuzzer/index
	printf 'section[bar].I=2' > build-fuzz/corpus/override_fuzzer/name
	printf 'scene.title="a title"' > build-fuzz/corpus/override_fuzzer/text
	cp tests/snapshots/ring_elastic/contact_sheet.png build-fuzz/corpus/png_decode_fuzzer/
	cp tests/reference/vtu/*.vtu build-fuzz/corpus/vtu_reader_fuzzer/
	printf '{"program": "plastica", "scene": "ring", "status": "completed", "steps": 2}\0step,load,control_displacement\n0,0,0\n1,1,1\0id,analysis.increment\nr0001,1\n' \
	  > build-fuzz/corpus/result_folder_fuzzer/seed
	set -e; for f in $(FUZZERS); do \
	  echo "fuzzing $$f for $(FUZZ_SECONDS) s"; \
	  build-fuzz/fuzz/$$f build-fuzz/corpus/$$f -max_total_time=$(FUZZ_SECONDS) -max_len=8192 \
	    -timeout=10 -rss_limit_mb=4096 -artifact_prefix=build-fuzz/findings/$$f- -print_final_stats=1 > build-fuzz/$$f.log 2>&1 \
	    || { tail -n 40 build-fuzz/$$f.log; echo "$$f found a crash (build-fuzz/findings/)"; exit 1; }; \
	  tail -n 3 build-fuzz/$$f.log; \
	done

# Rewrites the stored snapshot references on purpose (review the new pictures before committing).
update-snapshots: build
	rm -rf tests/snapshots
	scripts/render-snapshots.sh $(BUILD)/cli/plastica tests/snapshots
	find tests/snapshots -name '.plastica-*' -delete

clean:
	rm -rf $(BUILD) build-sanitize build-bench build-fuzz
