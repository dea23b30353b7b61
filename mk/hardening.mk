# Issue 18: `make sanitize` builds the program and the unit programs with -fsanitize=address,undefined into
# build/san/ (.ci/run runs the unit programs and the bad-input cases with them, .ci/sanitizer.supp suppressing only
# Open MPI's and PETSc's own leaks); `make fuzz` builds the libFuzzer targets of fuzz/ with Debian's clang into
# build/fuzz/ (fuzz/run.sh runs them on the committed corpus).

SAN_FLAGS   := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
SAN_LIB_OBJ := $(LIB_SRC:%.c=build/san/obj/%.o) $(CXX_SRC:%.cc=build/san/obj/%.o)
SAN_DRV_OBJ := $(DRV_SRC:%.c=build/san/obj/%.o)
SAN_TESTS   := $(TEST_SRC:tests/unit/%.c=build/san/tests/%)

sanitize: build/san/bin/confsurf $(SAN_TESTS)

build/san/obj/src/linalg/quaternion_cholesky.o: CFLAGS += -O3
build/san/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@

build/san/obj/%.o: %.cc
	@mkdir -p $(dir $@)
	$(CXX) $(CPPFLAGS_CGAL) $(CXXFLAGS) $(SAN_FLAGS) -c $< -o $@

build/san/libconfsurf.a: $(SAN_LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

build/san/bin/confsurf: $(SAN_DRV_OBJ) build/san/libconfsurf.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -o $@ $(SAN_DRV_OBJ) build/san/libconfsurf.a $(LDLIBS)

build/san/tests/%: tests/unit/%.c build/san/libconfsurf.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(SAN_FLAGS) -o $@ $< build/san/libconfsurf.a $(LDLIBS)

# libFuzzer: clang (Debian's clang package) through Open MPI's wrapper; the readers and util/ instrumented
FUZZ_CC    := OMPI_CC=clang mpicc
FUZZ_FLAGS := -g -O1 -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
FUZZ_SRC   := $(wildcard src/util/*.c) $(addprefix src/mesh/,meshdata_reader.c meshdata_obj.c meshdata_off.c meshdata_ply.c meshdata_validate.c meshdata_edges.c meshdata_io.c)
FUZZ_OBJ   := $(FUZZ_SRC:%.c=build/fuzz/obj/%.o)
FUZZERS    := build/fuzz/fuzz_obj build/fuzz/fuzz_off build/fuzz/fuzz_ply build/fuzz/fuzz_values

fuzz: $(FUZZERS)

build/fuzz/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(CPPFLAGS) -std=gnu11 $(FUZZ_FLAGS) -c $< -o $@

build/fuzz/fuzz_%: fuzz/fuzz_mesh.c $(FUZZ_OBJ)
	$(FUZZ_CC) $(CPPFLAGS) -std=gnu11 $(FUZZ_FLAGS) -DFORMAT=$* -DFORMAT_$* -fsanitize=fuzzer -o $@ $< $(FUZZ_OBJ) $(LDLIBS)

build/fuzz/fuzz_values: fuzz/fuzz_values.c $(FUZZ_OBJ)
	$(FUZZ_CC) $(CPPFLAGS) -std=gnu11 $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_OBJ) $(LDLIBS)

-include $(SAN_LIB_OBJ:.o=.d) $(SAN_DRV_OBJ:.o=.d)
.PHONY: sanitize fuzz
