# The extension points (issue 37, point 3; docs/DESIGN.md "Extending confsurf"): tests/unit/test_extension.c registers
# a toy energy (with its own option -flow_toy_weight) and a toy constraint through the public registration alone,
# runs CGD with them, and checks the gradient of every registered energy and the rows of every registered
# constraint against central differences, and refuses a kind registered with another kind's ops.id (the id a
# checkpoint stores). No leak: -malloc_dump lists unfreed blocks at PetscFinalize (and -malloc_debug, which checks every allocation, took 37 s instead of 4 on 2 ranks: serially only).
# nprocs: 1 2
source tests/lib.sh
debug=""; [ "${NP:-1}" = 1 ] && debug="-malloc_debug"
timeout 120 $MPIEXEC "$CS_TESTS/test_extension" $debug -malloc_dump > "$TMP/out" 2>&1 || { cat "$TMP/out"; echo "BAD: test_extension failed"; exit 1; }
cat "$TMP/out"
if grep -qE "^\[ *[0-9]+\] [0-9]+ bytes " "$TMP/out"; then echo "BAD: unfreed memory at PetscFinalize"; exit 1; fi
