/* Checkpoints of the triangle-field flow (willmore_state.c): what the loop carries from one iteration to the next besides
   the flow's scalars, in fields the checkpoint stores in natural order (src/mesh/checkpoint.c), in 1 + k slots:
   slot 0 the state (omega, the multipliers mu), slot 1 + j the initial guess W_j = [E; V] of the saddle solver's
   bordering solve j (its last solution, which the next step starts from: without it a resumed run differs at the
   Krylov tolerance), each
     per edge  [V or omega of its two halfedges (3 + 3), E or mu of their conformal rows (1 + 1, not with
               -flow_conformal false), of its lens row d1 omega (3)],
     per face  [its spinor psi (4: the signs followed along the flow), then per slot E or mu of its closure row (3)];
   and the scalars [restoration failed, spin weight, stage start, stages, the saddle's last Krylov
   its, wait, backoff (the schedule of kept factorisations)]. The checkpoint's fingerprint is that of the start omega's
   reconstruction (CSWillmoreFlowGetStart), so a resume from another -flow_init, -flow_seed, ... is refused like another input. The two halfedges
   of an edge are ordered by the natural numbers of their vertices (first the one from the lower to the higher), so
   the file does not depend on how the ranks orient their edges. The rest (lambda, D, X, the stars, the
   reconstruction xpos) is recomputed from omega at the top of the loop; the integrability schedule follows the
   iteration number. A kept factorisation (-flow_factor_reuse_its) is not stored: the resumed run's first step
   factors afresh. Not for -flow_variables spinor (other variables). */
#include "trianglefield_impl.h"
#include "cs_util.h"

#define TF_CK_NREAL 7 /* after the flow's own (willmore_state.c: t, t_mu, the -t_mu_final switch, ...) */

/* the local array index of the first dof of point p in the global vectors of dm (owned points only) */
typedef struct {
  PetscSection s;
  PetscInt     r0;
} Layout;

static PetscErrorCode LayoutGet(DM dm, Layout *l)
{
  Vec g;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &l->s));
  PetscCall(DMGetGlobalVector(dm, &g));
  PetscCall(VecGetOwnershipRange(g, &l->r0, NULL));
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscFunctionReturn(0);
}

static PetscErrorCode At(const Layout *l, PetscInt p, PetscInt *i)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetOffset(l->s, p, i));
  *i -= l->r0;
  PetscFunctionReturn(0);
}

/* n values between the state (a) and the packed field (b), in the direction of the pack */
static inline void Move(PetscScalar *a, PetscScalar *b, PetscInt n, PetscBool unpack)
{
  for (PetscInt i = 0; i < n; i++) {
    if (unpack) a[i] = b[i];
    else b[i] = a[i];
  }
}

/* Per owned edge, slot slot: omega (or V) and the conformal multipliers (or E) of its halfedges (natural order), the
   lens multipliers. mu = [conformal rows (dmH1 layout); lens rows 3 x (dmE1 layout); closure rows 3 x (dmF1)]. */
static PetscErrorCode PackEdges(CSWillmoreFlow F, CSTriangleField *d, PetscScalar *ox, PetscScalar *mu, PetscInt slot, PetscBool unpack)
{
  CSMesh       m = F->mesh;
  Layout       lH1, lH3, lE1, lK;
  PetscInt     eS, b = d->noconf ? 9 : 11;
  PetscScalar *pe;
  PetscFunctionBeginUser;
  PetscCall(LayoutGet(d->dmH1, &lH1));
  PetscCall(LayoutGet(d->dmH3, &lH3));
  PetscCall(LayoutGet(m->dmE1, &lE1));
  PetscCall(LayoutGet(d->dmCkE, &lK));
  PetscCall(DMPlexGetDepthStratum(m->dm, 1, &eS, NULL));
  PetscCall(VecGetArray(d->ckE, &pe));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt ih1, ih3, ie1, ik, s0 = m->vertNatural[m->edgeVert[2 * e]] > m->vertNatural[m->edgeVert[2 * e + 1]] ? 1 : 0;
    if (!m->edgeOwned[e]) continue;
    PetscCall(At(&lH1, eS + e, &ih1));
    PetscCall(At(&lH3, eS + e, &ih3));
    PetscCall(At(&lE1, eS + e, &ie1));
    PetscCall(At(&lK, eS + e, &ik));
    ik += b * slot;
    for (PetscInt j = 0; j < 2; j++) {
      PetscInt s = j ? 1 - s0 : s0;
      Move(ox + ih3 + 3 * s, pe + ik + 3 * j, 3, unpack);
      if (!d->noconf) Move(mu + ih1 + s, pe + ik + 6 + j, 1, unpack);
    }
    Move(mu + d->nH + 3 * ie1, pe + ik + b - 3, 3, unpack);
  }
  PetscCall(VecRestoreArray(d->ckE, &pe));
  PetscFunctionReturn(0);
}

/* Per face: the spinor (slot 0), the closure multipliers (or E) of slot slot. */
static PetscErrorCode PackFaces(CSWillmoreFlow F, CSTriangleField *d, PetscScalar *mu, PetscInt slot, PetscBool unpack)
{
  CSMesh       m = F->mesh;
  Layout       lF1, lF4, lK;
  DM           dmF4;
  PetscInt     fS;
  PetscScalar *pf, *psi;
  PetscFunctionBeginUser;
  PetscCall(CSSpinorSpaceGetDM(d->sp, &dmF4));
  PetscCall(LayoutGet(m->dmF1, &lF1));
  PetscCall(LayoutGet(dmF4, &lF4));
  PetscCall(LayoutGet(d->dmCkF, &lK));
  PetscCall(DMPlexGetDepthStratum(m->dm, 2, &fS, NULL));
  PetscCall(VecGetArray(d->ckF, &pf));
  PetscCall(VecGetArray(d->psi, &psi));
  for (PetscInt f = 0; f < m->nf; f++) {
    PetscInt if1, if4, ik;
    PetscCall(At(&lF1, fS + f, &if1));
    PetscCall(At(&lF4, fS + f, &if4));
    PetscCall(At(&lK, fS + f, &ik));
    if (!slot) Move(psi + if4, pf + ik, 4, unpack);
    Move(mu + d->nH + 3 * (d->nD1 + if1), pf + ik + 4 + 3 * slot, 3, unpack);
  }
  PetscCall(VecRestoreArray(d->psi, &psi));
  PetscCall(VecRestoreArray(d->ckF, &pf));
  PetscFunctionReturn(0);
}

/* slot slot between (x, mu) (layouts of omega and the multipliers) and (ckE, ckF) */
static PetscErrorCode PackSlot(CSWillmoreFlow F, CSTriangleField *d, Vec x, Vec mu, PetscInt slot, PetscBool unpack)
{
  PetscScalar *ox, *m;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(x, &ox));
  PetscCall(VecGetArray(mu, &m));
  PetscCall(PackEdges(F, d, ox, m, slot, unpack));
  PetscCall(PackFaces(F, d, m, slot, unpack));
  PetscCall(VecRestoreArray(mu, &m));
  PetscCall(VecRestoreArray(x, &ox));
  PetscFunctionReturn(0);
}

/* the fields between (omega, mu, psi, the saddle's W_j) and (ckE, ckF), created at the first call */
static PetscErrorCode Pack(CSWillmoreFlow F, CSTriangleField *d, PetscBool unpack)
{
  PetscInt nmu, b = d->noconf ? 9 : 11;
  Vec      E, V;
  PetscFunctionBeginUser;
  if (!d->ckE) {
    PetscCall(CSMeshCreateFieldDM(F->mesh->dm, 1, b * (1 + F->k), "trianglefield_checkpoint_edges", &d->dmCkE));
    PetscCall(CSMeshCreateFieldDM(F->mesh->dm, 2, 4 + 3 * (1 + F->k), "trianglefield_checkpoint_faces", &d->dmCkF));
    PetscCall(DMCreateGlobalVector(d->dmCkE, &d->ckE));
    PetscCall(DMCreateGlobalVector(d->dmCkF, &d->ckF));
  }
  PetscCall(VecGetLocalSize(F->mu, &nmu));
  PetscCheck(nmu == d->nH + d->nL && d->nL == 3 * (d->nD1 + F->mesh->nf), F->hdr.comm, PETSC_ERR_PLIB, "trianglefield checkpoint: multiplier layout %" PetscInt_FMT " != %" PetscInt_FMT " + %" PetscInt_FMT, nmu, d->nH, d->nL);
  PetscCall(PackSlot(F, d, F->x, F->mu, 0, unpack));
  PetscCall(VecDuplicate(F->mu, &E));
  PetscCall(VecDuplicate(F->x, &V));
  for (PetscInt j = 0; j < F->k; j++) {
    if (!unpack) PetscCall(CSSaddleGetGuess(&F->saddle, j, E, V));
    PetscCall(PackSlot(F, d, V, E, 1 + j, unpack));
    if (unpack) PetscCall(CSSaddleSetGuess(&F->saddle, j, E, V));
  }
  PetscCall(VecDestroy(&E));
  PetscCall(VecDestroy(&V));
  PetscFunctionReturn(0);
}

static PetscErrorCode GetState(CSWillmoreFlow F, PetscReal ck[], CSCheckpointFields *v)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  PetscCheck(!d->spinor, F->hdr.comm, PETSC_ERR_SUP, "-checkpoint/-resume with -%svariables spinor: the variables (u, psi) are not stored in checkpoints (only -%svariables omega)", F->hdr.prefix, F->hdr.prefix);
  PetscCall(Pack(F, d, PETSC_FALSE));
  v->x    = NULL;
  v->edge = d->ckE;
  v->face = d->ckF;
  if (!ck) PetscFunctionReturn(0);
  ck[0] = (PetscReal)F->restore_failed;
  ck[1] = d->wspin;
  ck[2] = (PetscReal)d->stage_it0;
  ck[3] = (PetscReal)d->nstages;
  ck[4] = (PetscReal)F->saddle.last_its;
  ck[5] = (PetscReal)F->saddle.wait;
  ck[6] = (PetscReal)F->saddle.backoff;
  PetscFunctionReturn(0);
}

/* after the resume overwrote ckE, ckF and ck */
static PetscErrorCode SetState(CSWillmoreFlow F, const PetscReal ck[])
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  F->restore_failed  = (PetscBool)(ck[0] != 0);
  d->wspin           = ck[1];
  d->stage_it0       = (PetscInt)ck[2];
  d->nstages         = (PetscInt)ck[3];
  F->saddle.last_its = (PetscInt)ck[4];
  F->saddle.wait     = (PetscInt)ck[5]; /* the first step's fresh factorisation counts as one (willmore_saddle.c) */
  F->saddle.backoff  = (PetscInt)ck[6];
  PetscCall(Pack(F, d, PETSC_TRUE));
  PetscFunctionReturn(0);
}

/* At the set-up, after the start omega is made: the checkpoints' fingerprint, and the hooks. The fingerprint is
   the start's Poisson reconstruction (positions; output.c weighs them by their natural numbers), not omega:
   the sums of omega cancel in halfedge pairs and its norm is that of a rotated copy too (issue 36). The spinor
   variables are not stored (refused by name), their start is kept as it is. */
PetscErrorCode CSTFStateSetUp(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscFunctionBeginUser;
  if (d->spinor) {
    PetscCall(VecDuplicate(F->x, &d->start));
    PetscCall(VecCopy(F->x, d->start));
  } else {
    PetscErrorCode ierr;
    PetscCall(VecDuplicate(d->xpos0, &d->start));
    /* a perturbed start may fold triangles: its *1 is then not positive definite and no step can be measured
       (issue 36: the flow ended in "CHOLMOD error -4"); refused here, naming the option */
    CSCaptureError(ierr, CSTriangleFieldReconstructionSolve(d->recon, F->x, d->xpos0, d->start));
    PetscCheck(!ierr, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sinit %s: the start triangle field has no Poisson reconstruction (its *1 is not positive definite: the perturbation folds triangles); lower -%sinit_amplitude (%g)", F->hdr.prefix, CSTriangleFieldInits[d->init], F->hdr.prefix, (double)d->amp);
  }
  F->xstart          = d->start;
  F->ops.state_nreal = TF_CK_NREAL;
  F->ops.get_state   = GetState;
  F->ops.set_state   = SetState;
  PetscFunctionReturn(0);
}

PetscErrorCode CSTFStateDestroy(CSTriangleField *d)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&d->start));
  PetscCall(VecDestroy(&d->ckE));
  PetscCall(VecDestroy(&d->ckF));
  PetscCall(DMDestroy(&d->dmCkE));
  PetscCall(DMDestroy(&d->dmCkF));
  PetscFunctionReturn(0);
}
