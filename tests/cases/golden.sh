#!/usr/bin/env bash
# nprocs: 1 2
# The golden regression suite (issue #23, tests/golden/): short runs of every options/*.opts and of each test's
# main command; their summaries and output meshes must agree with those stored from the binary before the
# redesign to 1e-10 relative. Guards every refactor: change a stored result only with a note in
# tests/golden/CHANGES.
. tests/lib.sh
# the references were stored with OpenBLAS's default threads (one per core serially): tests/run.sh's
# OPENBLAS_NUM_THREADS=1 for the other cases moves 10 of the 58 np 1 cases at round-off (docs/tests_time.md)
[ "${CS_TEST_BLAS_DEFAULT:-}" != 1 ] || unset OPENBLAS_NUM_THREADS
python3 tests/golden/run.py --np "$NP" --bin "$CS_BIN"
