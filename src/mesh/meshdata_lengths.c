/* An intrinsic metric from a file (issue 15 item 6: the conformal class from edge lengths): md->len, the flows'
   target class c0 = C log l (cgd, soliman2021 Eq. 3) and C~ lambda (trianglefield, Eq. 14), as -gen lattice
   provides it. The file holds 3 |F| positive numbers, per face in the mesh's face order the lengths of the edges
   opposite its corners 0, 1, 2 (white space or commas, '#' comments). Rank 0. */
#include "cs_meshdata.h"
#include "cs_util.h"

typedef struct {
  PetscInt  a, b; /* vertices, a < b */
  PetscReal l;
  PetscInt  face;
} EdgeLength;

static int CompareEdges(const void *p, const void *q)
{
  const EdgeLength *x = (const EdgeLength *)p, *y = (const EdgeLength *)q;
  if (x->a != y->a) return x->a < y->a ? -1 : 1;
  if (x->b != y->b) return x->b < y->b ? -1 : 1;
  return 0;
}

/* the two faces of every edge must give it the same length (1e-10 relative), and each face's lengths must be a
   triangle (strict triangle inequalities) */
static PetscErrorCode CheckLengths(const char option[], const char path[], const CSMeshData *md, const PetscReal *len)
{
  EdgeLength *e;
  PetscFunctionBeginUser;
  for (PetscInt f = 0; f < md->nf; f++) {
    const PetscReal *l = len + 3 * f;
    PetscCheck(l[0] > 0 && l[1] > 0 && l[2] > 0 && l[0] < l[1] + l[2] && l[1] < l[2] + l[0] && l[2] < l[0] + l[1], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: face %" PetscInt_FMT " has lengths %g %g %g, not a triangle (positive, strict triangle inequalities)", option, path, f, (double)l[0], (double)l[1], (double)l[2]);
  }
  PetscCall(PetscMalloc1(3 * md->nf, &e));
  for (PetscInt f = 0; f < md->nf; f++)
    for (int k = 0; k < 3; k++) {
      PetscInt u = md->f[3 * f + (k + 1) % 3], v = md->f[3 * f + (k + 2) % 3];
      e[3 * f + k] = (EdgeLength){PetscMin(u, v), PetscMax(u, v), len[3 * f + k], f};
    }
  qsort(e, 3 * md->nf, sizeof(EdgeLength), CompareEdges);
  for (PetscInt i = 1; i < 3 * md->nf; i++) {
    if (CompareEdges(&e[i - 1], &e[i])) continue;
    if (PetscAbsReal(e[i].l - e[i - 1].l) > 1e-10 * PetscMax(e[i].l, e[i - 1].l)) {
      EdgeLength x = e[i - 1], y = e[i];
      PetscCall(PetscFree(e));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: the edge (%" PetscInt_FMT ", %" PetscInt_FMT ") has length %.15g in face %" PetscInt_FMT " but %.15g in face %" PetscInt_FMT " (one length per edge)", option, path, x.a, x.b, x.l, x.face, y.l, y.face);
    }
  }
  PetscCall(PetscFree(e));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataReadLengths(const char option[], const char path[], CSMeshData *md)
{
  PetscInt   n, *lines;
  PetscReal *v;
  PetscFunctionBeginUser;
  PetscCheck(!md->len, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "%s %s: the mesh %s already carries an intrinsic metric (-gen lattice)", option, path, md->name);
  PetscCall(CSReadNumberFile(option, path, &n, &v, &lines));
  PetscCall(PetscFree(lines));
  if (n != 3 * md->nf) {
    PetscCall(PetscFree(v));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: %" PetscInt_FMT " numbers, expected 3 x %" PetscInt_FMT " faces = %" PetscInt_FMT " (per face the lengths of the edges opposite its corners 0, 1, 2)", option, path, n, md->nf, 3 * md->nf);
  }
  {
    PetscErrorCode ierr = CheckLengths(option, path, md, v);
    if (ierr) {
      PetscCall(PetscFree(v));
      return ierr;
    }
  }
  md->len = v;
  PetscFunctionReturn(0);
}
