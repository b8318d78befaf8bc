# kolsky: the two commands a newcomer needs are `make reproduce` and `make test`.
# Every target installs missing Debian packages first (scripts/install-deps.sh, idempotent).
BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
REPORTS ?= reports
SANITIZE_BUILD ?= build-sanitize
FUZZ_SECONDS ?= 60
SETS    := verification bars chapter2 chapter3 chapter4 chapter5

.PHONY: all build deps configure test check reproduce bench help clean rebaseline gate fuzz \
        check-sanitize \
        reproduce-verification reproduce-bars \
        reproduce-chapter2 reproduce-chapter3 reproduce-chapter4 reproduce-chapter5

all: build

help:
	@echo "kolsky make targets:"
	@echo "  make               build (Release) after installing missing Debian packages"
	@echo "  make test          unit tests, verification checks and smoke reproductions (CTest)"
	@echo "  make check         unit tests and verification checks only (about a minute)"
	@echo "  make reproduce     every reproduction set at full scale -> $(REPORTS)/<set>/, index in $(REPORTS)/index.html"
	@echo "  make reproduce-<set>   one set: $(SETS)"
	@echo "  make reproduce-chapter2  Chapter 2 (EOS back-calculation, equilibrium, water content; ~5 min)"
	@echo "  make reproduce-chapter4  Chapter 4 DEM SHPB, N = 2: 4 runs, the k calibration, upscaling and seed studies (~21 min from scratch on two threads; see reproductions/chapter4/README.md)"
	@echo "  make reproduce-chapter5  Chapter 5 DEM with breakage: Wang (loaded to 72 MPa), Huang, Song, sigma_lim0(N) back-calculation (48 min on two cores from scratch before the 72 MPa loading, longer since: see reproductions/chapter5/README.md)"
	@echo "  make reproduce-chapter3  Chapter 3 coupled FE-DEM SHPB, N = 3: grain-size cases, friction, model levels, NORMK back-calculation (~8 min on one core; see reproductions/chapter3/README.md)"
	@echo "  make study-at-rest  issue 31 item 0: the Chapter 4 specimen held at rest, as packed and relaxed (N = 4, 3, 2; ~15 min) -> $(BUILD)/study-at-rest/"
	@echo "  make study-wang-loading  issue 31 H2/H3: Wang loaded to 72 MPa, reconstructed and L/10 top size (N = 1, 1.5, 2 x 3 seeds; ~2 h on two cores) -> $(BUILD)/study-wang/"
	@echo "  make study-backcalc-seeds  issue 31: sigma_lim0 back-calculated at N = 2.5 and 2 over packing seeds 1-3 (needs study-wang-loading's N = 1 case) -> $(BUILD)/study-backcalc-seeds/"
	@echo "  make study-huang-count  issue 31: five full-scale Huang variants for the count at 42.5 MPa (strength, c_lim = 0, porosity 0.44, seed 2 with and without c_lim; ~75 min on one core) -> $(BUILD)/study-huang-count/"
	@echo "  make study-ringing  issue 31: Chapter 3's early face-stress gap against the specimen's inertia (3 runs, ~4 min) -> $(BUILD)/study-ringing/"
	@echo "  make study-preparation  issue 31 H1: each packing procedure, relaxed, loaded (Chapter 4, N = 4, 3) and at rest (Chapter 3, N = 3; Chapter 5 Wang, N = 2); ~25 min -> $(BUILD)/study-preparation/"
	@echo "  make rebaseline SET=<set> REASON=\"...\" [SCALE=smoke|full] [RUNS=n]"
	@echo "                     rewrite reproductions/<set>/baseline_<scale>.json, log it in reproductions/BASELINES.md"
	@echo "  make gate          the regression gate alone, on the smoke results of the last make test"
	@echo "  make bench         Google Benchmark -> benchmarks/results/<date>_<commit>_<bench>.json"
	@echo "  make bench-summary figures and tables of benchmarks/results/ -> $(REPORTS)/benchmarks/"
	@echo "  make bench-check   short run; fails if a speed ratio (kolsky / reference) fell below the tracked one (~1 min)"
	@echo "  make fuzz          each libFuzzer target (scene, BARS.json, CSV tables, gauge records) for FUZZ_SECONDS (default 60) each, ASan + UBSan, in $(SANITIZE_BUILD)/"
	@echo "  make check-sanitize  the unit tests of the input layer and the small physics under ASan + UBSan (docs/fuzzing.md)"
	@echo "  make clean         remove $(BUILD)/, $(SANITIZE_BUILD)/ and $(REPORTS)/"

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

check: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L check

# Ends with $(REPORTS)/index.md and index.html: every set's counts, run time, commit, links, plots.
reproduce: build
	@status=0; for s in $(SETS); do \
	  $(BUILD)/reproductions/reproduce_$$s --scale full --out $(REPORTS)/$$s || status=1; \
	done; $(BUILD)/reproductions/reports_index --reports $(REPORTS) $(SETS) || status=1; exit $$status

reproduce-verification reproduce-bars reproduce-chapter2 reproduce-chapter3 reproduce-chapter4 reproduce-chapter5: reproduce-%: build
	@$(BUILD)/reproductions/reproduce_$* --scale full --out $(REPORTS)/$*

# Studies behind the chapter READMEs (not part of make reproduce; resumable).
.PHONY: study-at-rest study-preparation study-wang-loading study-backcalc-seeds study-ringing study-huang-count
study-ringing: build
	@bash scripts/study-ringing.sh $(BUILD) $(BUILD)/study-ringing
study-huang-count: build
	@bash scripts/study-huang-count.sh $(BUILD) $(BUILD)/study-huang-count
study-at-rest: build
	@bash scripts/study-at-rest.sh $(BUILD) $(BUILD)/study-at-rest

study-preparation: build
	@bash scripts/study-preparation.sh $(BUILD) $(BUILD)/study-preparation
	@bash scripts/study-preparation-census.sh $(BUILD) $(BUILD)/study-preparation 3
	@bash scripts/study-preparation-census.sh $(BUILD) $(BUILD)/study-preparation 5
study-wang-loading: build
	@bash scripts/study-wang-loading.sh $(BUILD) $(BUILD)/study-wang
study-backcalc-seeds: build
	@bash scripts/study-backcalc-seeds.sh $(BUILD) $(BUILD)/study-backcalc-seeds

rebaseline: build
	@bash scripts/rebaseline.sh $(BUILD) "$(SET)" "$(or $(SCALE),smoke)" "$(RUNS)" "$(REASON)"

gate:
	@$(BUILD)/reproductions/kolsky_gate check --results $(BUILD)/reports-smoke --scale smoke --all

bench: build
	@bash scripts/run-benchmarks.sh $(BUILD)/benchmarks benchmarks/results

# Benchmark tracking (reports/benchmarks/README.md). Not part of `make test`: bench-check
# depends on wall time; its margins and their measurement are in scripts/bench-check.sh.
.PHONY: bench-summary bench-check
bench-summary: build
	@$(BUILD)/benchmarks/summarize_benchmarks summary --results benchmarks/results --out $(REPORTS)/benchmarks

bench-check: build
	@bash scripts/bench-check.sh $(BUILD) benchmarks/results

# The sanitized build of the input layer (fuzz/CMakeLists.txt, docs/fuzzing.md); clang.
fuzz: deps
	@FUZZ_SECONDS=$(FUZZ_SECONDS) bash scripts/sanitize.sh fuzz $(SANITIZE_BUILD)

check-sanitize: deps
	@bash scripts/sanitize.sh check $(SANITIZE_BUILD)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(REPORTS)
