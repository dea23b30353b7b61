# The extension points (issue 37, point 3; docs/DESIGN.md "How to add ..."): tests/unit/test_extension.c registers
# a toy energy (with its own option -flow_toy_weight) and a toy constraint through the public registration alone,
# runs CGD with them, and checks the gradient of every registered energy and the rows of every registered
# constraint against central differences.
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_extension" -malloc_debug -malloc_dump
