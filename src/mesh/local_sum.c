/* The local scatter-add (zeroed local vector, accumulate, LocalToGlobal ADD_VALUES) of every face-by-face
   assembly, written once. */
#include "cs_mesh.h"

PetscErrorCode CSLocalSumBegin(DM dm, CSLocalSum *s)
{
  PetscFunctionBeginUser;
  s->dm = dm;
  PetscCall(DMGetLocalVector(dm, &s->l));
  PetscCall(VecSet(s->l, 0));
  PetscCall(VecGetArray(s->l, &s->a));
  PetscFunctionReturn(0);
}

PetscErrorCode CSLocalSumShare(CSLocalSum *s)
{
  Vec g;
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArray(s->l, &s->a));
  PetscCall(DMGetGlobalVector(s->dm, &g));
  PetscCall(VecSet(g, 0));
  PetscCall(DMLocalToGlobal(s->dm, s->l, ADD_VALUES, g));
  PetscCall(DMGlobalToLocal(s->dm, g, INSERT_VALUES, s->l));
  PetscCall(DMRestoreGlobalVector(s->dm, &g));
  PetscCall(VecGetArray(s->l, &s->a));
  PetscFunctionReturn(0);
}

PetscErrorCode CSLocalSumEnd(CSLocalSum *s, Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArray(s->l, &s->a));
  if (g) {
    PetscCall(VecSet(g, 0));
    PetscCall(DMLocalToGlobal(s->dm, s->l, ADD_VALUES, g));
  }
  PetscCall(DMRestoreLocalVector(s->dm, &s->l));
  s->a = NULL;
  PetscFunctionReturn(0);
}
