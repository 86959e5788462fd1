# slipwave build. `make run` and `make test` install missing Debian packages first
# (scripts/install-deps.sh), then re-enter make so pkg-config sees the installed PETSc.
BUILD    ?= build
# Parallel compilation in the re-entered make (the recipes below are independent).
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
comma    := ,
CXX      := mpicxx
PETSC_CFLAGS := $(shell pkg-config --cflags PETSc 2>/dev/null) $(shell pkg-config --cflags hdf5-openmpi 2>/dev/null)
PETSC_LIBS   := $(shell pkg-config --libs PETSc 2>/dev/null) $(shell pkg-config --libs hdf5-openmpi 2>/dev/null) -lmetis -lyaml
PETSC_RPATH  := $(patsubst -L%,-Wl$(comma)-rpath$(comma)%,$(filter -L%,$(shell pkg-config --libs PETSc 2>/dev/null)))
OPT      ?= -O3 -march=native
WARN     := -Wall -Wextra -Wno-unused-parameter
CXXFLAGS := -std=c++17 $(OPT) -g $(WARN) -Iinclude $(PETSC_CFLAGS) -MMD -MP
LDLIBS   := $(PETSC_LIBS) $(PETSC_RPATH) -lm

LIB_SRC  := $(shell find src -name '*.cpp' -not -path 'src/bin/*' 2>/dev/null | sort)
LIB_OBJ  := $(LIB_SRC:%.cpp=$(BUILD)/%.o)
BIN_SRC  := $(wildcard src/bin/*.cpp)
BINS     := $(BIN_SRC:src/bin/%.cpp=$(BUILD)/%)
UNIT_SRC := $(wildcard tests/unit/test_*.cpp)
UNITS    := $(UNIT_SRC:%.cpp=$(BUILD)/%)
BENCH_SRC:= $(wildcard bench/bench_*.cpp)
BENCHES  := $(BENCH_SRC:%.cpp=$(BUILD)/%)
LIB      := $(BUILD)/libslipwave.a

.PHONY: all deps run test bench clean build-only test-only run-only bench-only convergence-check
# Keep the objects of the programs (make would delete them as intermediates and relink).
.SECONDARY:
all: deps
	@$(MAKE) --no-print-directory -j$(JOBS) build-only

deps:
	@bash scripts/install-deps.sh

build-only: $(BINS) $(UNITS) $(BENCHES)

run: deps
	@$(MAKE) --no-print-directory -j$(JOBS) build-only && $(MAKE) --no-print-directory run-only

# The default scene (main/) and its 2 m companion (coarse/), then its answers with their
# grid-convergence bands (scripts/convergence_check.py), then the plots of the main run.
run-only: build-only
	MPIEXEC_FLAGS="$(MPIEXEC_FLAGS)" /usr/bin/python3 scripts/convergence_check.py config/scenes/default.yaml --np $(NP) --out $(BUILD)/run/default --echo-main
	/usr/bin/python3 scripts/plot_results.py $(BUILD)/run/default/main --layer 30,200
	xvfb-run -a pvpython --force-offscreen-rendering scripts/paraview_views.py $(BUILD)/run/default/main --state $(BUILD)/run/default/main/plots/view.pvsm
	@echo "Plots and a ParaView view in $(BUILD)/run/default/main/plots/ (view.pvsm: File > Load State); volume.xmf, interface_base.xmf open in ParaView"

# The scene's main answers with a grid-convergence band: the scene and a companion resolution
# (scripts/convergence_check.py; CHECK_ARGS: its options, e.g. "--levels 3 -- -ts_max_time 5").
SCENE ?= config/scenes/default.yaml
convergence-check: build-only
	MPIEXEC_FLAGS="$(MPIEXEC_FLAGS)" /usr/bin/python3 scripts/convergence_check.py $(SCENE) --np $(NP) --out $(BUILD)/run/convergence/$(basename $(notdir $(SCENE))) $(CHECK_ARGS)

test: deps
	@$(MAKE) --no-print-directory -j$(JOBS) build-only && $(MAKE) --no-print-directory test-only

test-only: build-only
	@bash tests/run_tests.sh

bench: deps
	@$(MAKE) --no-print-directory -j$(JOBS) build-only && $(MAKE) --no-print-directory bench-only

bench-only: build-only
	@bash bench/run_bench.sh

clean:
	rm -rf $(BUILD)

NP ?= 2
MPIEXEC_FLAGS ?= --oversubscribe $(if $(filter 0,$(shell id -u)),--allow-run-as-root,)

$(LIB): $(LIB_OBJ)
	@mkdir -p $(@D)
	ar rcs $@ $^

$(BUILD)/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -c $< -o $@

$(BUILD)/%: $(BUILD)/src/bin/%.o $(LIB)
	$(CXX) $(CXXFLAGS) $< $(LIB) $(LDLIBS) -o $@

$(BUILD)/tests/unit/%: $(BUILD)/tests/unit/%.o $(LIB)
	$(CXX) $(CXXFLAGS) $< $(LIB) $(LDLIBS) -o $@

$(BUILD)/bench/%: $(BUILD)/bench/%.o $(LIB)
	$(CXX) $(CXXFLAGS) $< $(LIB) $(LDLIBS) -o $@

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
