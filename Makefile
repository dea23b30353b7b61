# confsurf: `make` builds, `make run` runs the default experiment (a constrained Willmore flow with its pictures,
# scripts/run-default.sh), `make demo` one short example per method with a gallery (scripts/demo.sh), `make test` runs the test suite,
# `make check-docs` runs the options files whose headers state measured figures and compares (runs/check_options_headers.py),
# `make bench` runs the benchmarks in runs/ (runs/run-all.sh), `make deps` installs the system packages
# (scripts/install-deps.sh; the other goals do it too when packages are missing). `make WERROR=` builds without -Werror.
.DEFAULT_GOAL := all
GOALS := all run demo test test-serial check-docs bench clean sanitize fuzz
WERROR ?= -Werror

deps:
	bash scripts/install-deps.sh

# `make run`/`make demo`/`make test` from a fresh clone: build on every core (the test runner then shares the cores
# out itself, tests/run.sh)
ifneq ($(filter run demo test test-serial,$(MAKECMDGOALS)),)
MAKEFLAGS += -j$(shell nproc)
endif

HAVE_DEPS := $(shell bash scripts/install-deps.sh --check >/dev/null 2>&1 && pkg-config --exists petsc slepc 2>/dev/null && echo yes)

ifneq ($(HAVE_DEPS),yes)
$(GOALS):
	bash scripts/install-deps.sh
	$(MAKE) $@
else

CC       := $(shell pkg-config --variable=ccompiler petsc)
CPPFLAGS := -Iinclude $(shell pkg-config --cflags slepc petsc)
CFLAGS   ?= -O2 -g
CFLAGS   += -std=gnu11 -Wall -Wextra -Wno-unused-parameter $(WERROR) -MMD -MP
LDLIBS   := $(shell pkg-config --libs slepc petsc) -lptscotch -lscotch -lcholmod -llapack -lblas -lz -lm

LIB_SRC  := $(sort $(wildcard src/*/*.c src/*/*/*.c src/*/*/*/*/*.c))
LIB_SRC  := $(filter-out src/driver/% src/api/%,$(LIB_SRC))

# CGAL (header-only, with GMP/MPFR) for -mesh_remesh: its .pc if it ships one, else the header probe. Without it
# the build still succeeds and -mesh_remesh refuses with a line naming `make deps` (src/mesh/meshdata_remesh.c).
CXX      := $(or $(shell pkg-config --variable=cxxcompiler petsc),mpicxx)
CXXFLAGS ?= -O2 -g
CXXFLAGS += -std=c++17 -Wall -Wextra -Wno-unused-parameter $(WERROR) -MMD -MP
HAVE_CGAL := $(shell (pkg-config --exists CGAL 2>/dev/null || test -f /usr/include/CGAL/version.h) && echo yes)
ifeq ($(HAVE_CGAL),yes)
CXX_SRC  := src/mesh/meshdata_remesh_cgal.cc
CPPFLAGS_CGAL := -DCS_HAVE_CGAL $(shell pkg-config --cflags CGAL 2>/dev/null)
LDLIBS_CGAL   := -lgmp -lmpfr -lstdc++
endif
# meshdata_remesh.o is compiled again when CGAL appears or goes (build/cgal.flag changes only then)
$(shell mkdir -p build && (echo "$(HAVE_CGAL)" | cmp -s - build/cgal.flag || echo "$(HAVE_CGAL)" > build/cgal.flag))
build/obj/src/mesh/meshdata_remesh.o build/san/obj/src/mesh/meshdata_remesh.o: build/cgal.flag
build/obj/src/mesh/meshdata_remesh.o build/san/obj/src/mesh/meshdata_remesh.o: CPPFLAGS += $(CPPFLAGS_CGAL)
DRV_SRC  := $(wildcard src/driver/*.c)
TEST_SRC := $(wildcard tests/unit/*.c)
LDLIBS   += $(LDLIBS_CGAL)
LIB_OBJ  := $(LIB_SRC:%.c=build/obj/%.o) $(CXX_SRC:%.cc=build/obj/%.o)
DRV_OBJ  := $(DRV_SRC:%.c=build/obj/%.o)
TESTS    := $(TEST_SRC:tests/unit/%.c=build/tests/%)
BENCH_SRC:= $(wildcard runs/*.c)
BENCHES  := $(BENCH_SRC:runs/%.c=build/runs/%)
LIB      := build/libconfsurf.a
# The shared library of the Python interface (python/confsurf, docs/python.md): the library, the driver's tasks
# (not main.c) and the entry layer src/api/. Every object is compiled once, position-independent, and serves the
# static library, the binary and the .so alike (a second -fPIC copy doubled the build of `make test`);
# -fno-semantic-interposition keeps gcc inlining and calling our own global functions directly, as without -fPIC.
CFLAGS   += -fPIC -fno-semantic-interposition
CXXFLAGS += -fPIC
API_SRC  := $(wildcard src/api/*.c)
API_OBJ  := $(API_SRC:%.c=build/obj/%.o)
SO_OBJ   := $(LIB_OBJ) $(filter-out build/obj/src/driver/main.o,$(DRV_OBJ)) $(API_OBJ)
SO       := build/libconfsurf.so
# every object is compiled again when the compiler flags change (as meshdata_remesh.o with build/cgal.flag)
$(shell (echo "$(CFLAGS) $(CXXFLAGS)" | cmp -s - build/cflags.flag || echo "$(CFLAGS) $(CXXFLAGS)" > build/cflags.flag))
$(LIB_OBJ) $(DRV_OBJ) $(API_OBJ): build/cflags.flag

all: bin/confsurf $(TESTS) $(BENCHES) $(SO)

# the quaternion Cholesky's dense loops need -O3 to be vectorised (gcc 12 does not at -O2)
build/obj/src/linalg/quaternion_cholesky.o: CFLAGS += -O3

build/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

build/obj/%.o: %.cc
	@mkdir -p $(dir $@)
	$(CXX) $(CPPFLAGS_CGAL) $(CXXFLAGS) -c $< -o $@

# linked against PETSc, SLEPc, MPI and the rest as the binary is (-lstdc++ with CGAL: the remeshing unit is C++);
# Python loads it with ctypes (python/confsurf/_lib.py)
$(SO): $(SO_OBJ)
	$(CC) $(CFLAGS) -shared -o $@ $(SO_OBJ) $(LDLIBS)
	@echo "make: built $@; the Python package: PYTHONPATH=$(CURDIR)/python python3 -c 'import confsurf'"

$(LIB): $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

bin/confsurf: $(DRV_OBJ) $(LIB)
	@mkdir -p bin
	$(CC) $(CFLAGS) -o $@ $(DRV_OBJ) $(LIB) $(LDLIBS)

build/tests/%: tests/unit/%.c $(LIB)
	@mkdir -p build/tests
	$(CC) $(CPPFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

build/runs/%: runs/%.c $(LIB)
	@mkdir -p build/runs
	$(CC) $(CPPFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

run: bin/confsurf
	bash scripts/run-default.sh

demo: bin/confsurf
	bash scripts/demo.sh

# the suite's own dependencies (ParaView for tests/cases/viewer_paraview.sh); a failed install leaves that test failing
test: all
	bash scripts/install-deps.sh --test || echo "make test: could not install the test dependencies (paraview)"
	bash tests/run.sh

test-serial: all
	bash scripts/install-deps.sh --test || echo "make test: could not install the test dependencies (paraview)"
	CS_TEST_NPROCS=1 bash tests/run.sh

# the options files' headers against the code (issue 39): every file with an `# expect:` line, serially;
# CHECK_DOCS_ARGS=--slow adds the `# expect-slow:` ones (not in CI)
check-docs: all
	python3 runs/check_options_headers.py $(CHECK_DOCS_ARGS)

bench: all
	bash runs/run-all.sh

clean:
	rm -rf build bin

-include $(LIB_OBJ:.o=.d) $(DRV_OBJ:.o=.d) $(TESTS:=.d) $(BENCHES:=.d) $(SO_OBJ:.o=.d)
include mk/hardening.mk
endif

.PHONY: $(GOALS) deps
