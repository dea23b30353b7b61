#!/usr/bin/env bash
# The Python interface in one process over many calls (issue 40): N calls (default 1000) of small flows, a failing
# call (an option the task does not read) and curve flows, under PETSc's -malloc_debug; prints PETSc's allocated
# bytes and the process' RSS after the first tenth of the calls and at the end, and checks that the global options
# database and the first flow's result are unchanged (tests/cases/python_tools.py repeat; tests/cases/python_errors.sh
# runs 60). NP=2 runs it under mpirun -n 2. Result quoted in docs/python.md.
set -eu
cd "$(dirname "$0")/.."
export PYTHONPATH=$PWD/python OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
N=${N:-1000}; NP=${NP:-1}
launch=(); [ "$NP" -gt 1 ] && launch=(mpirun -n "$NP")
PETSC_OPTIONS=-malloc_debug /usr/bin/time -f "%e s wall, %M kB max RSS" "${launch[@]}" /usr/bin/python3 tests/cases/python_tools.py repeat "$N"
