/* The Sobolev metrics of the flow: H^2 = *0 + L *0^{-1} L (soliman2021 Eq. 11, Eq. 26) or L2 = *0. */
#include "cs_operators_conformal.h"

static PetscErrorCode H2ShellMult(Mat A, Vec u, Vec y)
{
  CSMetric *m;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &m));
  PetscCall(MatMult(m->Ls, u, m->work));        /* *0^{-1} L u */
  PetscCall(MatMult(m->L3, m->work, y));        /* L *0^{-1} L u */
  PetscCall(VecPointwiseMult(m->work, m->m3, u));
  PetscCall(VecAXPY(y, m->mass_weight, m->work)); /* + w *0 u */
  PetscCall(VecScale(y, m->scale));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMetricCreate(CSMesh mesh, PetscBool h2, CSMetric *m)
{
  PetscInt n, N;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(m, sizeof(*m)));
  m->mesh = mesh;
  m->h2   = h2;
  m->mass_weight = 1.0;
  m->scale       = 1.0;
  PetscCall(DMCreateGlobalVector(mesh->dmV3, &m->m3));
  PetscCall(VecDuplicate(m->m3, &m->minv3));
  PetscCall(VecDuplicate(m->m3, &m->work));
  PetscCall(VecGetLocalSize(m->m3, &n));
  PetscCall(VecGetSize(m->m3, &N));
  PetscCall(MatCreateShell(mesh->comm, n, n, N, N, m, &m->shell));
  PetscCall(MatShellSetOperation(m->shell, MATOP_MULT, (void (*)(void))H2ShellMult));
  PetscCall(MatSetOption(m->shell, MAT_SYMMETRIC, PETSC_TRUE));
  PetscFunctionReturn(0);
}

/* H^1 = scale sqrt(w) (sqrt(w) *0 + L) = scale (w *0 + sqrt(w) L): the metric of the area energy's order (its
   Hessian is ~ L, second order), so that its grid-scale modes are not slowed by h^2 as under H^2
   (docs/boundary_twist.md). With sqrt(w) = 1/s^2 both terms scale like length^-2, as H^2 does, so that t and the
   size scaling of t_mu (CSWFSetUpScaling) mean the same under both metrics (without the overall sqrt(w) the flow
   depended on the input's size: W after 8 steps 17.686 at unit size, 17.775 at 10x). */
static PetscErrorCode UpdateH1(CSMetric *m, Vec x)
{
  PetscBool first = m->L3 ? PETSC_FALSE : PETSC_TRUE;
  PetscReal sw    = PetscSqrtReal(m->mass_weight);
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLaplacian3(m->mesh, x, first ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, &m->L3));
  if (first) PetscCall(MatDuplicate(m->L3, MAT_COPY_VALUES, &m->H));
  else PetscCall(MatCopy(m->L3, m->H, SAME_NONZERO_PATTERN));
  PetscCall(VecScale(m->m3, sw));
  PetscCall(MatDiagonalSet(m->H, m->m3, ADD_VALUES));
  PetscCall(VecScale(m->m3, 1.0 / sw));
  PetscCall(MatScale(m->H, m->scale * sw));
  PetscCall(MatSetOption(m->H, MAT_SYMMETRIC, PETSC_TRUE));
  PetscFunctionReturn(0);
}

/* The product L *0^{-1} L couples two-rings, beyond the closure adjacency of the DM, so it is formed with
   MatMatMult (docs/solvers.md), symbolic product reused from the second call on. */
PetscErrorCode CSMetricUpdate(CSMetric *m, Vec x)
{
  CSMesh             mesh = m->mesh;
  Vec                a;
  const PetscScalar *aa;
  PetscScalar       *m3, *mi;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscCall(DMGetGlobalVector(mesh->dmV1, &a));
  PetscCall(CSOperatorMass(mesh, x, a));
  PetscCall(VecGetLocalSize(a, &n));
  PetscCall(VecGetArrayRead(a, &aa));
  PetscCall(VecGetArray(m->m3, &m3));
  PetscCall(VecGetArray(m->minv3, &mi));
  for (PetscInt i = 0; i < n; i++)
    for (int d = 0; d < 3; d++) {
      m3[3 * i + d] = aa[i];
      mi[3 * i + d] = 1.0 / aa[i];
    }
  PetscCall(VecRestoreArray(m->minv3, &mi));
  PetscCall(VecRestoreArray(m->m3, &m3));
  PetscCall(VecRestoreArrayRead(a, &aa));
  PetscCall(DMRestoreGlobalVector(mesh->dmV1, &a));
  if (m->h1) PetscCall(UpdateH1(m, x));
  else if (m->h2) {
    PetscBool first = m->L3 ? PETSC_FALSE : PETSC_TRUE;
    PetscCall(CSOperatorLaplacian3(mesh, x, first ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, &m->L3));
    if (first) PetscCall(MatDuplicate(m->L3, MAT_COPY_VALUES, &m->Ls));
    else PetscCall(MatCopy(m->L3, m->Ls, SAME_NONZERO_PATTERN));
    PetscCall(MatDiagonalScale(m->Ls, m->minv3, NULL));
    PetscCall(MatMatMult(m->L3, m->Ls, first ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, PETSC_DEFAULT, &m->H));
    PetscCall(VecScale(m->m3, m->mass_weight));
    PetscCall(MatDiagonalSet(m->H, m->m3, ADD_VALUES));
    PetscCall(VecScale(m->m3, 1.0 / m->mass_weight));
    if (m->scale != 1) PetscCall(MatScale(m->H, m->scale));
    PetscCall(MatSetOption(m->H, MAT_SYMMETRIC, PETSC_TRUE));
    if (first) PetscCall(CSH2PCCompose(m->H, m, m->scale, NULL));
  } else {
    if (!m->H) {
      PetscInt N;
      PetscCall(VecGetSize(m->m3, &N));
      PetscCall(MatCreateAIJ(mesh->comm, 3 * n, 3 * n, N, N, 1, NULL, 0, NULL, &m->H));
      PetscCall(MatSetOption(m->H, MAT_SYMMETRIC, PETSC_TRUE));
      PetscCall(MatSetUp(m->H));
    }
    PetscCall(VecScale(m->m3, m->scale * m->mass_weight));
    PetscCall(MatDiagonalSet(m->H, m->m3, INSERT_VALUES));
    PetscCall(VecScale(m->m3, 1.0 / (m->scale * m->mass_weight)));
  }
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMetricDestroy(CSMetric *m)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&m->L3));
  PetscCall(MatDestroy(&m->Ls));
  PetscCall(MatDestroy(&m->H));
  PetscCall(MatDestroy(&m->shell));
  PetscCall(VecDestroy(&m->m3));
  PetscCall(VecDestroy(&m->minv3));
  PetscCall(VecDestroy(&m->work));
  PetscFunctionReturn(0);
}
