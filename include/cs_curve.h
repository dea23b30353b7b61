/* Planar polylines (the mesh layer of the curve flow, crane2013 Sec. 5): CSCurveData, the curve as read or
   generated on rank 0, and CSCurve, the distributed curve.
   Files: OBJ with `v x y [z]` lines and one `l i j k ...` element (1-based or negative indices, `i/t` allowed),
   or plain text with one `x y [z]` point per line (`#` comments). A polyline whose last point repeats the first
   (OBJ: the index, text: the coordinates) is closed; any other is open as written, which is an error unless
   the caller allows open lines (-curve_open) or closes them (-curve_close).
   CSCurve: vertex i (global, 0..N-1) is owned by the rank whose contiguous range holds it; edge i runs from
   vertex i to vertex i+1 (mod N when closed) and is owned with vertex i. Neighbour values across ranks (and the
   wrap-around of a closed curve) come from a VecScatter of the two ghost vertices (CSCurveGhosts). */
#ifndef CS_CURVE_H
#define CS_CURVE_H
#include <petscvec.h>

typedef struct {
  PetscInt   m;      /* vertices (a closed curve does not repeat the first) */
  PetscReal *x;      /* 2*m coordinates */
  PetscInt  *line;   /* file line of each vertex (0 for generated curves), for messages */
  PetscInt   lline;  /* line of the OBJ `l` element (0: none) */
  PetscBool  closed;
  char       name[PETSC_MAX_PATH_LEN];
} CSCurveData;

/* Parameters of the generators (-gen_curve_*): n vertices, radius r, ellipse semi-axes a b, star
   r(t) = r (1 + amplitude cos(petals t)), noisy circle r (1 + noise U(-1,1)) with seed, limacon
   r(t) = b + a cos t (a > b: an inner loop, turning number 2). */
typedef struct {
  PetscInt  n, petals, seed;
  PetscReal r, a, b, amplitude, noise;
} CSCurveGenParams;

/* .obj or a text file (any other extension); errors name the file, the line and the reason. Serial. */
PETSC_EXTERN PetscErrorCode CSCurveDataRead(const char path[], CSCurveData *cd);
/* Refuses fewer than 3 vertices, non-finite coordinates, repeated consecutive points, zero-length edges and,
   unless allow_open, an open line. Serial. */
PETSC_EXTERN PetscErrorCode CSCurveDataValidate(const CSCurveData *cd, PetscBool allow_open);
/* circle | ellipse | star | noisy | limacon (counter-clockwise, closed) */
PETSC_EXTERN PetscErrorCode CSCurveDataGenerate(const char shape[], const CSCurveGenParams *p, CSCurveData *cd);
/* .obj (v x y 0, one l element) or text (x y [kappa]); a closed curve repeats its first point/index. */
PETSC_EXTERN PetscErrorCode CSCurveDataWrite(const char path[], PetscInt m, const PetscReal x[], const PetscReal kappa[], PetscBool closed);
PETSC_EXTERN PetscErrorCode CSCurveDataDestroy(CSCurveData *cd);

typedef struct _p_CSCurve *CSCurve;
struct _p_CSCurve {
  MPI_Comm   comm;
  char       name[PETSC_MAX_PATH_LEN];
  PetscInt   N, n, rstart; /* global and local vertex counts, first owned vertex */
  PetscBool  closed;
  Vec        x;            /* positions, block size 2, the owned vertices */
  PetscInt   gl, gr;       /* global index of the left (rstart-1) and right (rstart+n) neighbour, -1 at an open end */
  VecScatter sc[2];        /* ghost gathers for block sizes 1 and 2 */
  Vec        g[2];         /* their sequential targets: [left, right] values */
};

/* From rank 0's cd (ignored elsewhere): distributes the positions in contiguous blocks. Collective. */
PETSC_EXTERN PetscErrorCode CSCurveCreate(MPI_Comm comm, const CSCurveData *cd, CSCurve *curve);
/* -curve FILE or -gen_curve circle|ellipse|star|noisy|limacon (-gen_curve_n, _radius, _a, _b, _amplitude,
   _petals, _noise, _seed); -curve_open (the flow of an open curve), -curve_close (close an open input line).
   Errors on rank 0 are raised on every rank. Collective. */
PETSC_EXTERN PetscErrorCode CSCurveCreateFromOptions(MPI_Comm comm, CSCurve *curve);
/* The points of a caller of the library (src/api: the Python interface's array P), used by
   CSCurveCreateFromOptions instead of -curve/-gen_curve (refused then) while set; read on rank 0 (other ranks pass
   any non-NULL cd), copied and validated as a file is. NULL: off. Set and cleared on every rank. */
PETSC_EXTERN PetscErrorCode CSCurveDataSetArraySource(const CSCurveData *cd);
/* The values of the left and right neighbour vertices of this rank's block of v (block size 1 or 2):
   lr[0..bs-1] left, lr[bs..2bs-1] right (zero at an open end). Collective. */
PETSC_EXTERN PetscErrorCode CSCurveGhosts(CSCurve curve, Vec v, PetscReal lr[4]);
/* Positions (and optionally a per-vertex field, written as a third column of a text file) gathered to rank 0
   and written there. Collective. */
PETSC_EXTERN PetscErrorCode CSCurveWrite(CSCurve curve, Vec x, Vec kappa, const char path[]);
PETSC_EXTERN PetscErrorCode CSCurveCreateScalarVec(CSCurve curve, Vec *v); /* one value per owned vertex */
PETSC_EXTERN PetscErrorCode CSCurveDestroy(CSCurve *curve);

#endif
