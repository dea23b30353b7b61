/* The library's entry layer for callers outside C (src/api/api.c; the Python package python/confsurf on ctypes,
   docs/python.md): PETSc/SLEPc started once per process, one task per call on arrays, each call with its own
   options database, errors returned as a code with a one-line message. The top layer: it includes the driver's
   headers, nothing includes it. Plain C types only (double, long), so that ctypes needs no PETSc headers.
   Every function is collective on PETSC_COMM_WORLD (all ranks call it, in the same order). */
#ifndef CS_API_H
#define CS_API_H

/* PetscInitialize/SlepcInitialize once (MPI_Init by PETSc unless the caller, e.g. mpi4py, started MPI), with the
   start-up defaults of bin/confsurf; later calls return 0. CSApiFinalize ends PETSc (and MPI if PETSc started it). */
int CSApiInitialize(void);
int CSApiFinalize(void);
int CSApiRank(void);
int CSApiSize(void);

/* One task (info|flow|spin|spectrum|curveflow) with the command line's options (a string, -options_file too) in a
   private database that is destroyed afterwards. The input on rank 0 (ignored elsewhere):
     a mesh: V (nv x 3), F (nf x 3, 0-based); uv (nuv x 2) and fuv (nf x 3) or nuv = 0;
     spin's rho (nrho values, in place of -rho FILE) or rho NULL;
     a curve: P (np x 2), closed or open (as -curve_open);
     neither (nv = np = 0): the options name the input (-mesh, -gen, -curve, -gen_curve).
   refuse: NULL, or on rank 0 a message of a check the caller made: every rank then fails with it (no rank waits).
   quiet: the task's stdout lines are dropped (stderr kept). Returns 0 or a PETSc error code, the message in
   CSApiLastError(); the results (CSApiResult*) stay valid until the next CSApiRun or CSApiRelease. */
int CSApiRun(const char *task, const char *options, int quiet, long nv, const double *V, long nf, const long *F, long nuv, const double *uv, const long *fuv, long nrho, const double *rho, long np, const double *P, int closed, const char *refuse);
const char *CSApiLastError(void);
/* 1 when the last error was the refusal of the input (refuse, or arrays rank 0 could not take), on every rank */
int CSApiLastErrorIsInput(void);
/* rank 0 after a successful run: the summary (JSON text, NULL if the task wrote none) */
const char *CSApiResultSummary(void);
/* the final positions: *dim 3 (a mesh, the input's vertex order) or 2 (a curve), *n points; NULL if none */
const double *CSApiResultPositions(long *dim, long *n);
/* the faces -o writes (a refined or remeshed input has others), *nf of them */
const long *CSApiResultFaces(long *nf);
/* the history (-history_csv's columns): header line, *rows x *cols row-major; NULL if the task kept none */
const double *CSApiResultHistory(const char **header, long *rows, long *cols);
int CSApiRelease(void);
/* the number of options in the global (process) database: a call leaves it unchanged (tests/cases/python_*.sh) */
long CSApiGlobalOptionsCount(void);
/* bytes PETSc has allocated now (PetscMallocGetCurrentUsage), for the leak test */
double CSApiPetscMemory(void);

#endif
