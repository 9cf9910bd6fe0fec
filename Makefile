# The README's two commands: `make demo` (every method on the built-in demo scene, speed-vs-error
# report under out/) and `make test` (every test through CTest). Each installs what it needs first.
BUILD ?= build
JOBS ?= $(shell nproc)
RETROAA = $(BUILD)/app/retroaa

# Debian 12 packages: toolchain (python3 for tools/device/summary.py's dry run), headless GL (EGL +
# Mesa's llvmpipe), and the chosen libraries.
APT_PACKAGES = cmake g++ make pkg-config git python3 assimp-testmodels xvfb xauth libimgui-dev \
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libepoxy-dev libglfw3-dev libglm-dev \
  libopenimageio-dev openimageio-tools nlohmann-json3-dev libcli11-dev libassimp-dev libgtest-dev

# clang and its sanitizer and libFuzzer runtimes, for test-sanitize and fuzz only.
CLANG_PACKAGES = clang libclang-rt-14-dev

.PHONY: check-library-only deps deps-clang stk-deps stk stk-report stk-cost test-stk build demo demo-full test test-sanitize fuzz soak regress regress-golden presets docs-config docs-robustness clean

deps:
	@missing=$$(for p in $(APT_PACKAGES); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q "install ok installed" || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:" $$missing; \
	  if [ "$$(id -u)" != 0 ]; then echo "error: apt-get needs root for:" $$missing; exit 1; fi; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi

deps-clang: deps
	@$(MAKE) --no-print-directory deps APT_PACKAGES="$(CLANG_PACKAGES)"

# SuperTuxKart 1.4 with retroaa (engine-patch/supertuxkart/): its build dependencies, its game data and
# ccache; the source is ../shared/third_party/stk-code-1.4-src.tar.xz.
STK_PACKAGES = ccache patch libshaderc-dev libsdl2-dev libopenal-dev libcurl4-gnutls-dev libfreetype-dev \
  libharfbuzz-dev libjpeg-dev libpng-dev libvorbis-dev libogg-dev libmbedtls-dev libxrandr-dev libxxf86vm-dev \
  zlib1g-dev libgl-dev libglu1-mesa-dev supertuxkart-data xvfb xauth
STK = $(BUILD)/stk/stk-build/bin/supertuxkart
STK_DIR = engine-patch/supertuxkart
stk-deps: deps
	@$(MAKE) --no-print-directory deps APT_PACKAGES="$(STK_PACKAGES)"

# Builds patched SuperTuxKart (first time 40-60 min on 2 cores; through ccache, minutes). Run it with
# `--retroaa=METHOD` (docs/integration.md#supertuxkart).
stk: build stk-deps
	bash $(STK_DIR)/build.sh $(BUILD)

# Every method in SuperTuxKart on three of its tracks (sky and power lines; indoor; conifers and a start line)
# at 640x480 4x against its stock render at 2560x1920 box-filtered, with STK's particles on (forward passes):
# out/stk/<track>/report.md (+ .json, the images and a crop where the frame model matters: the sky's edge,
# the kart against the wall, a conifer).
STK_TRACKS ?= cornfield_crossing olivermath black_forest
STK_FRAME ?= 40
STK_REPORT_METHODS = off stk-mlaa fxaa smaa resolve resolve/front resolve/back resolve/fso coverage reconstruct \
  edge adaptive aggregate smaa-s2x per-sample resolve+fxaa resolve+smaa resolve+coverage resolve+reconstruct \
  edge+smaa ssaa@supersample=2 temporal@temporal_before_tonemap=off per-sample@sample_shading=1 edge@sample_shading=1
# Then the same with the effects of STK's high preset on but SSAO (out/stk/effects/<track>; capture.sh says
# why SSAO cannot be matched at 4x), and a driven race
# (out/stk/race: STK's AI drives, each method from the start, frames 600-607 at 320x240 against the same
# frames at 1280x960; the kart and the wires scored apart).
STK_RACE_METHODS = off fxaa smaa reconstruct resolve edge per-sample temporal reconstruct+temporal
# Races with three AI opponents on each track (temporal's swing, flicker and karts among other karts).
STK_OPPONENT_RACE_METHODS = fxaa edge temporal
STK_OPPONENT_RACE_TRACKS = $(STK_TRACKS) lighthouse zengarden sandtrack hacienda xr591
# A race with three AI opponents, the player's kart scored apart (race.sh's options after OUT).
STK_OPPONENT_RACE = --karts=4 --region kart=120,110,80,75
STK_RACE_SCORE = --region kart=120,110,80,75 --region wires=160,0,160,70 --crop 128,112,64 --crop 200,20,64
stk-report: stk
	for effects in "--particles" "--effects --no-ssao"; do for track in $(STK_TRACKS); do \
	  case $$track in black_forest) crop=210,130,64 ;; *) crop=300,200,64 ;; esac; \
	  case $$effects in --effects*) dir=out/stk/effects/$$track ;; *) dir=out/stk/$$track ;; esac; \
	  bash $(STK_DIR)/capture.sh $(STK) $$track 640x480 $(STK_FRAME) "$(STK_REPORT_METHODS)" $$dir 1 $$effects && \
	  bash $(STK_DIR)/capture.sh $(STK) $$track 2560x1920 $(STK_FRAME) "off" $$dir/reference 1 $$effects && \
	  $(RETROAA) score $$dir --reference $$dir/reference/off.png --factor 4 --crop $$crop || exit 1; done; done
	bash $(STK_DIR)/race.sh $(STK) $(RETROAA) cornfield_crossing 320x240 607 8 "$(STK_RACE_METHODS)" out/stk/race \
	  $(STK_RACE_SCORE)
	for track in $(STK_OPPONENT_RACE_TRACKS); do \
	  bash $(STK_DIR)/race.sh $(STK) $(RETROAA) $$track 320x240 607 8 "$(STK_OPPONENT_RACE_METHODS)" \
	    out/stk/race-opponents/$$track $(STK_OPPONENT_RACE) || exit 1; done

# What the plugin's own passes cost inside SuperTuxKart, each beside its floor (a pass of the same shape that
# only moves its bytes), and `resolve` and `edge` without the floors for the walls, on the report's three
# tracks at 320x240, 10 timed frames each: out/stk/cost/
# (<track>/report.md and cost.md, the targets of docs/results.md#what-the-passes-cost met or missed).
stk-cost: stk
	bash $(STK_DIR)/cost.sh $(STK) $(RETROAA) out/stk/cost 320x240 10 $(STK_TRACKS)

# The real-engine check (run by .ci/run, not by `make test`): the core methods at 320x240 on an indoor
# track (silhouettes against geometry: every multi-sample method must beat off's edge PSNR) and on one
# with sky and power lines (the sky must stay as off has it), each against STK's own 4x render.
STK_TEST_METHODS = off fxaa resolve reconstruct edge per-sample temporal@temporal_before_tonemap=off
# Then: the choice in STK's graphics settings (saved, applied in a race, an unknown one falling back); the
# effects of its high preset on; a short driven race (reproducible, every method from the start); and races
# with three AI opponents on the tracks where temporal meets every race target (docs/results.md says what
# it misses on the other five of stk-report's eight and why: olivermath's own swing, the foliage's flicker
# on lighthouse and zengarden).
STK_TEST_OPPONENT_TRACKS = cornfield_crossing black_forest sandtrack
test-stk: stk
	bash $(STK_DIR)/test.sh $(STK) $(RETROAA) olivermath $(STK_FRAME) "$(STK_TEST_METHODS)" out/test-stk/olivermath --edges --whole-frame
	bash $(STK_DIR)/test.sh $(STK) $(RETROAA) cornfield_crossing $(STK_FRAME) "$(STK_TEST_METHODS)" out/test-stk/cornfield_crossing --sky --whole-frame
	bash $(STK_DIR)/options.sh $(STK) edge@samples=4 out/test-stk/options
	bash $(STK_DIR)/test.sh $(STK) $(RETROAA) olivermath $(STK_FRAME) "$(STK_TEST_METHODS)" out/test-stk/effects --effects
	bash $(STK_DIR)/test.sh $(STK) $(RETROAA) cornfield_crossing $(STK_FRAME) "off fxaa resolve reconstruct edge per-sample" \
	  out/test-stk/effects-forward --effects --no-ssao --forward
	bash $(STK_DIR)/race.sh $(STK) $(RETROAA) cornfield_crossing 320x240 607 8 "fxaa reconstruct temporal" out/test-stk/race \
	  $(STK_RACE_SCORE)
	python3 $(STK_DIR)/check.py out/test-stk/race $(STK_DIR)/patches --race
	for track in $(STK_TEST_OPPONENT_TRACKS); do \
	  bash $(STK_DIR)/race.sh $(STK) $(RETROAA) $$track 320x240 607 8 "fxaa temporal" out/test-stk/race-opponents/$$track \
	    $(STK_OPPONENT_RACE) && \
	  python3 $(STK_DIR)/check.py out/test-stk/race-opponents/$$track $(STK_DIR)/patches --race || exit 1; done

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build $(BUILD) -j$(JOBS)

# llvmpipe's thread count is pinned so images are byte-stable from run to run.
# The quick table first: one spec per method on the demo frame, a few minutes after the build.
demo: build
	LP_NUM_THREADS=2 $(RETROAA) bench --scene default --methods each,ssaa@supersample=2 --width 320 --height 240 \
	  --gt-samples 8 --repeats 1 --wall-frames 10 --json out/report.json --csv out/report.csv --report out/report.md \
	  --images out/images
	@echo "report: out/report.md (one frame, one spec per method; JSON, CSV, images beside it)"
	@echo "every variant, a finer ground truth and the recorded path: make demo-full (about 8 min)"

demo-full: build
	LP_NUM_THREADS=2 $(RETROAA) bench --scene default --methods all --width 320 --height 240 --gt-samples 16 \
	  --json out/report.json --csv out/report.csv --report out/report.md --images out/images
	LP_NUM_THREADS=2 $(RETROAA) regress default --out out/regress
	@echo "reports: out/report.md (one frame, every method; JSON, CSV, images beside it)"
	@echo "         out/regress/report.html (the demo scene's recorded path; open it in a browser)"

# The unit tests, the fuzzing corpus and a small integration subset under AddressSanitizer and
# UndefinedBehaviorSanitizer (clang). Mesa's own allocations are outside this project: leaks are not
# checked (detect_leaks=0); the GL objects the plugin holds are counted by its own tests instead.
SANITIZE_TESTS = 'Config|FuzzCorpus|Metrics|ResolveHardCases|AdaptiveMetrics|AggregateClustering|CoverageFilter|Plugin\.|Slices\.Edge|FramePath|Statistics\.|SecondHost\.(Edge|Aggregate|WorldPositions)'
test-sanitize: deps-clang
	CC=clang CXX=clang++ cmake -S . -B build-sanitize -DRETROAA_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build build-sanitize -j$(JOBS)
	cd build-sanitize && LP_NUM_THREADS=2 ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j2 -R $(SANITIZE_TESTS)

# libFuzzer on every parser a user can feed, FUZZ_SECONDS each; new inputs land in out/fuzz/, crashes
# as out/fuzz/<target>-crash-*. Add what it finds to integration-tests/fuzz/corpus/ to replay it forever.
FUZZ_SECONDS ?= 60
fuzz: deps-clang
	CC=clang CXX=clang++ cmake -S . -B build-fuzz -DRETROAA_FUZZ=ON -DRETROAA_SANITIZE=ON -DRETROAA_WITH_OPENIMAGEIO=OFF \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build build-fuzz -j$(JOBS) --target scene_fuzzer config_fuzzer model_fuzzer
	for t in scene config model; do mkdir -p out/fuzz/$$t; \
	  ASAN_OPTIONS=detect_leaks=0 build-fuzz/integration-tests/fuzz/$${t}_fuzzer -max_total_time=$(FUZZ_SECONDS) \
	    -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix=out/fuzz/$$t- out/fuzz/$$t \
	    integration-tests/fuzz/corpus/$$t || exit 1; done

# 2000 frames switching every method, sample count, detector and size in one process.
soak: build
	LP_NUM_THREADS=2 $(RETROAA) soak --frames 2000

# Every frame of the five recorded scenes, checked against integration-tests/golden/ (~4 min here).
regress: build
	LP_NUM_THREADS=2 $(RETROAA) regress --out out/regress --check

# Deliberately rewrites the goldens from this machine's run.
regress-golden: build
	LP_NUM_THREADS=2 $(RETROAA) regress --out out/regress --update-golden

test: build
	cd $(BUILD) && LP_NUM_THREADS=2 ctest --output-on-failure -j2

# The presets (`preset=low|medium|high|ultra`): the cheapest settings (lighting evaluations) whose worst
# frame of the demo and fence scenes reaches each edge-PSNR target. Rewrites presets/*.cfg, which the
# plugin embeds at build time; the measurements are cached in out/tune/.
PRESET_RUN = $(RETROAA) tune --scenes default,integration-tests/scenes/fence.json --frames 3 --width 160 --height 120 \
  --gt-samples 4 --cost evals_per_pixel --cache out/tune/presets-cache.json
presets: build
	LP_NUM_THREADS=2 $(PRESET_RUN) --target edge_psnr_db=17.5 --out presets/low.cfg
	LP_NUM_THREADS=2 $(PRESET_RUN) --target edge_psnr_db=19.0 --out presets/medium.cfg
	LP_NUM_THREADS=2 $(PRESET_RUN) --target edge_psnr_db=19.4 --out presets/high.cfg
	LP_NUM_THREADS=2 $(PRESET_RUN) --target edge_psnr_db=19.5 --out presets/ultra.cfg
	rm -f presets/*.cfg.json
	cmake --build $(BUILD) -j$(JOBS)

# Regenerates the key table of docs/config.md from the parser's own table (a test checks they agree).
docs-config: build
	@{ sed '/<!-- generated: retroaa config --markdown -->/q' docs/config.md; $(RETROAA) config --markdown; \
	   sed -n '/<!-- end generated -->/,$$p' docs/config.md; } > docs/config.md.new && mv docs/config.md.new docs/config.md

# Regenerates the hard-case matrix of docs/robustness.md from the robustness test.
docs-robustness: build
	@LP_NUM_THREADS=2 RETROAA_ROBUSTNESS_TABLE=$(BUILD)/robustness.md $(BUILD)/integration-tests/robustness_tests > /dev/null 2>&1; \
	 { sed '/<!-- generated: make docs-robustness -->/q' docs/robustness.md; cat $(BUILD)/robustness.md; \
	   sed -n '/<!-- end generated -->/,$$p' docs/robustness.md; } > docs/robustness.md.new && mv docs/robustness.md.new docs/robustness.md

# The library alone, configured, built and installed where only libepoxy's packages are visible (root: unshare).
check-library-only:
	bash integration-tests/consumer/library-only-isolated.sh .

clean:
	rm -rf $(BUILD) out
