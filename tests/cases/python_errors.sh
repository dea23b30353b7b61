# The Python interface's bad arguments and repeated calls (tests/cases/python_tools.py): wrong shapes, dtypes,
# non-finite values and out-of-range indices raise ValueError naming the array and row; an unknown option, an
# unknown flow, a solver option no solver reads, a rho of the wrong length or beyond 1e12, a missing
# -options_file, a duplicate face and -gen beside the arrays raise confsurf.Error with bin/confsurf's one-line
# message; the next call gives the first call's result. Then 60 small calls (flows, a failing call, curve flows)
# under -malloc_debug: PETSc's allocated bytes after call 6 and call 60
# are equal, the global options database is unchanged, and an option of one call (-flow_max_it 0) is not seen by the
# next (runs/python_leak.sh makes 1000 calls and quotes the RSS; NP=2 there for 2 ranks). The repeated calls run
# serially only (a property of the process; on 2 ranks each rank spins in MPI on the shared cores, 2.6 s a call
# under load 20); the bad arguments on 1 and 2 ranks (a refusal on rank 0 reaches every rank: no hang).
# `import confsurf` from a fresh shell works.
# nprocs: 1 2
source tests/lib.sh
export PYTHONPATH=$CS_ROOT/python
cd "$TMP"
/usr/bin/python3 -c "import confsurf; print('import confsurf:', confsurf.__file__)"
timeout 120 $MPIEXEC /usr/bin/python3 "$CS_ROOT/tests/cases/python_tools.py" errors
if [ "$NP" = 1 ]; then
  PETSC_OPTIONS=-malloc_debug timeout 300 /usr/bin/python3 "$CS_ROOT/tests/cases/python_tools.py" repeat 60
fi
