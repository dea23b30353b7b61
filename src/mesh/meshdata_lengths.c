/* An intrinsic metric from a file (issue 15 item 6: the conformal class from edge lengths): md->len, the flows'
   target class c0 = C log l (cgd, soliman2021 Eq. 3) and C~ lambda (trianglefield, Eq. 14), as -gen lattice
   provides it. The file holds 3 |F| positive numbers, per face in the mesh's face order the lengths of the edges
   opposite its corners 0, 1, 2 (white space or commas, '#' comments). Rank 0. */
#include "cs_meshdata.h"
#include "cs_util.h"

/* the two faces of every edge must give it the same length (1e-10 relative), and each face's lengths must be a
   triangle (strict triangle inequalities) */
static PetscErrorCode CheckLengths(const char option[], const char path[], const CSMeshData *md, const PetscReal *len)
{
  CSMeshDataEdges E;
  PetscFunctionBeginUser;
  for (PetscInt f = 0; f < md->nf; f++) {
    const PetscReal *l = len + 3 * f;
    PetscCheck(l[0] > 0 && l[1] > 0 && l[2] > 0 && l[0] < l[1] + l[2] && l[1] < l[2] + l[0] && l[2] < l[0] + l[1], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: face %" PetscInt_FMT " has lengths %g %g %g, not a triangle (positive, strict triangle inequalities)", option, path, f, (double)l[0], (double)l[1], (double)l[2]);
  }
  PetscCall(CSMeshDataEdgesCreate(md, &E));
  for (PetscInt s = 0, e; s < E.nh; s = e) {
    e = CSMeshDataEdgesGroupEnd(&E, md, s);
    for (PetscInt i = s + 1; i < e; i++) { /* half-edge h = 3f + c is the edge opposite corner c + 2 of face f */
      PetscInt  h0 = E.he[s], h1 = E.he[i];
      PetscReal l0 = len[3 * (h0 / 3) + (h0 % 3 + 2) % 3], l1 = len[3 * (h1 / 3) + (h1 % 3 + 2) % 3];
      if (PetscAbsReal(l1 - l0) > 1e-10 * PetscMax(l0, l1)) {
        PetscInt a = PetscMin(md->f[h0], md->f[CSHalfedgeNext(h0)]), b = E.key[s];
        PetscCall(CSMeshDataEdgesDestroy(&E));
        SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: the edge (%" PetscInt_FMT ", %" PetscInt_FMT ") has length %.15g in face %" PetscInt_FMT " but %.15g in face %" PetscInt_FMT " (one length per edge)", option, path, a, b, (double)l0, h0 / 3, (double)l1, h1 / 3);
      }
    }
  }
  PetscCall(CSMeshDataEdgesDestroy(&E));
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
