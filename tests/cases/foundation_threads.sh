# Threads per process (src/util/threads.c): OpenMP loops run on 1 thread unless OMP_NUM_THREADS says otherwise
# (Debian's CHOLMOD asks for 4 whatever the environment says, 2.8x slower on 2 cores); with several ranks each
# gets one OpenBLAS thread unless OPENBLAS_NUM_THREADS is set. Read back from the summary's omp_threads and
# blas_threads (rank 0). mpirun --bind-to none: OpenMPI binds each of 2 ranks to one core by default, and OpenBLAS
# then starts one thread anyway.
# nprocs: 1
source tests/lib.sh
G="-task info -gen icosphere -gen_level 2"
check() { # label key expected file
  local v; v=$(json "$2" "$4")
  if [ "$v" = "$3" ]; then echo "ok  $1: $2 = $v"; else echo "BAD $1: $2 = $v, expected $3"; exit 1; fi
}
env -u OMP_NUM_THREADS -u OPENBLAS_NUM_THREADS "$CS_BIN" $G -summary "$TMP/a.json" > /dev/null
check "serial, nothing set" omp_threads 1 "$TMP/a.json"
OMP_NUM_THREADS=2 "$CS_BIN" $G -summary "$TMP/b.json" > /dev/null
check "serial, OMP_NUM_THREADS=2" omp_threads 2 "$TMP/b.json"
env -u OMP_NUM_THREADS -u OPENBLAS_NUM_THREADS mpirun --bind-to none -n 2 "$CS_BIN" $G -summary "$TMP/c.json" > /dev/null
check "2 ranks, nothing set" omp_threads 1 "$TMP/c.json"
check "2 ranks, nothing set" blas_threads 1 "$TMP/c.json"
if [ "$(json blas_threads "$TMP/a.json")" -gt 1 ]; then # OpenBLAS with several threads by default: a user's choice stays
  OPENBLAS_NUM_THREADS=2 mpirun --bind-to none -x OPENBLAS_NUM_THREADS -n 2 "$CS_BIN" $G -summary "$TMP/d.json" > /dev/null
  check "2 ranks, OPENBLAS_NUM_THREADS=2" blas_threads 2 "$TMP/d.json"
fi
