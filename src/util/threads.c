/* Threads inside one process (include/cs_util.h, CSLimitThreads).

   Debian's CHOLMOD (SuiteSparse 5.12) is built with OpenMP and asks for CHOLMOD_OMP_NUM_THREADS = 4 threads
   (a compile-time constant) in the parallel loops of its supernodal numeric factorisation, whatever
   OMP_NUM_THREADS says. On this 2-core machine the spinning, oversubscribed threads made every CHOLMOD
   factorisation 2.8x slower (level-5 flow, 11 factorisations of the Schur complement: 9.9 s against 3.5 s with
   OMP_THREAD_LIMIT=1). With dynamic adjustment on, libgomp bounds such requests by nthreads-var, so we switch
   it on, and nthreads-var is 1 unless the user set OMP_NUM_THREADS.
   OpenBLAS starts one thread per core in every process: with several ranks per node that oversubscribes the
   cores, so each rank gets one BLAS thread unless OPENBLAS_NUM_THREADS is set.
   PT-Scotch 7 (the partitioner of CSMeshCreate) starts threads too, and its multi-threaded partitioning is not
   deterministic: the same run on 2 ranks gave different partitions, hence different summation orders and, after
   a few iterations of a flow, different iteration counts (measured, docs/reproducibility.md). Scotch reads the
   thread count from SCOTCH_PTHREAD_NUMBER when it creates its context; we ask for one thread unless the user
   set it, so runs under mpirun are reproducible.
   Both libraries are reached through dlsym: the symbols are there when libcholmod / libopenblas are loaded, and
   nothing is done when they are not (another BLAS, a CHOLMOD without OpenMP). */
#include <dlfcn.h>
#include <stdlib.h>
#include "cs_util.h"

PetscErrorCode CSLimitThreads(MPI_Comm comm)
{
  void (*set_dynamic)(int)          = (void (*)(int))dlsym(RTLD_DEFAULT, "omp_set_dynamic");
  void (*set_num_threads)(int)      = (void (*)(int))dlsym(RTLD_DEFAULT, "omp_set_num_threads");
  void (*openblas_set_threads)(int) = (void (*)(int))dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (set_dynamic) set_dynamic(1);
  if (set_num_threads && !getenv("OMP_NUM_THREADS")) set_num_threads(1);
  if (openblas_set_threads && size > 1 && !getenv("OPENBLAS_NUM_THREADS")) openblas_set_threads(1);
  PetscCheck(setenv("SCOTCH_PTHREAD_NUMBER", "1", 0) == 0, comm, PETSC_ERR_SYS, "setenv SCOTCH_PTHREAD_NUMBER failed");
  PetscFunctionReturn(0);
}

PetscErrorCode CSGetThreadCounts(PetscInt *omp_threads, PetscInt *blas_threads)
{
  int (*get_max_threads)(void)      = (int (*)(void))dlsym(RTLD_DEFAULT, "omp_get_max_threads");
  int (*openblas_get_threads)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  PetscFunctionBeginUser;
  if (omp_threads) *omp_threads = get_max_threads ? get_max_threads() : 1;
  if (blas_threads) *blas_threads = openblas_get_threads ? openblas_get_threads() : 1;
  PetscFunctionReturn(0);
}
