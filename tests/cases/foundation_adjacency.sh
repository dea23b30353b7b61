# Issue 23 item 5: the mesh adjacency (edge sides, diamonds, boundary prev/next; tests/unit/test_adjacency.c):
# face counts, V - E + F, well-formed diamonds, boundary cycles, copies agreeing across ranks and the tables in
# file numbering equal to the serial mesh's.
# nprocs: 1 2 3
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_adjacency" -malloc_debug -malloc_dump
