/* The CSSpin object (crane2011): create, options with the object's prefix (default "spin_"), set-up, one spin
   transformation (CSSpinSolve: Sec. 5.5 eigenproblem, the global similarity, Sec. 5.6 Eq. 8 + Poisson, the
   area), its monitors, destroy. The factorisations made by the first solve are kept for the next ones. */
#include "spin_impl.h"
#include "cs_package.h"
#include "cs_util.h"

/* The object's own members (hdr.destroy: CSSpinDestroy cancels the monitors first and frees the header after) */
static PetscErrorCode DestroyMembers(CSObject obj)
{
  CSSpin s = (CSSpin)obj;
  PetscFunctionBeginUser;
  PetscCall(EPSDestroy(&s->eps));
  PetscCall(KSPDestroy(&s->kinv));
  PetscCall(KSPDestroy(&s->klap));
  PetscCall(MatDestroy(&s->Ls));
  PetscCall(KSPDestroy(&s->kpois));
  PetscCall(MatDestroy(&s->Kinv));
  PetscCall(MatDestroy(&s->Ks));
  PetscCall(MatDestroy(&s->L));
  PetscCall(MatDestroy(&s->X));
  PetscCall(MatDestroy(&s->K));
  PetscCall(MatDestroy(&s->Y));
  PetscCall(MatDestroy(&s->P));
  PetscCall(VecDestroy(&s->mass));
  PetscCall(VecDestroy(&s->v4));
  PetscCall(VecDestroy(&s->Ttarget));
  PetscCall(VecDestroy(&s->Vcur));
  PetscCall(VecDestroy(&s->start));
  PetscCall(VecDestroy(&s->lambda));
  PetscCall(VecDestroy(&s->xnew));
  PetscCall(VecDestroy(&s->xtarget));
  PetscCall(VecDestroy(&s->mu));
  PetscCall(DMDestroy(&s->dm));
  PetscCall(DMDestroy(&s->dmr));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinCreate(CSMesh mesh, CSSpin *spin)
{
  CSSpin s;
  PetscFunctionBeginUser;
  PetscCall(CSInitializePackage());
  PetscCall(CSObjectCreate(sizeof(*s), mesh->comm, "spin_", DestroyMembers, &s));
  s->mesh         = mesh;
  s->inverse_its  = 1;
  s->target       = 1e-2;
  s->scalar_pc    = PETSC_FALSE;
  s->lap_shift    = 1;
  s->restore_area = PETSC_TRUE;
  PetscCall(CSDiracCreateDM(mesh, NULL, &s->dm));
  *spin = s;
  PetscFunctionReturn(0);
}

/* SetOptionsPrefix, GetOptionsPrefix, MonitorSet, Destroy: the skeleton of every method object (include/cs_object.h) */
CS_OBJECT_DEFINE(CSSpin, CSSpinMonitorFn)
/* the transformed surface and the eigenvector of the last Solve (owned by the object) */
CS_OBJECT_GETTER_AFTER(CSSpin, Solution, Vec, xnew, setupcalled, "CSSpinSolve")
CS_OBJECT_GETTER_AFTER(CSSpin, Spinor, Vec, lambda, setupcalled, "CSSpinSolve")

PetscErrorCode CSSpinSubPrefix(CSSpin s, const char suffix[], char prefix[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(prefix, len, "%s%s", s->hdr.prefix, suffix));
  PetscFunctionReturn(0);
}

/* the combinations the solvers do not support, each a one-line error naming the options */
static PetscErrorCode CheckOptions(CSSpin s, const char *bname)
{
  MPI_Comm    comm = s->hdr.comm;
  const char *p    = s->hdr.prefix;
  PetscFunctionBeginUser;
  PetscCheck(s->lap_shift > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%slap_shift %g: must be positive (L + c M must be definite)", p, (double)s->lap_shift);
  PetscCheck(!(s->scalar_pc && s->generalized), comm, PETSC_ERR_SUP, "-%ssolver precond supports only -%sproblem standard", p, p);
  PetscCheck(!(s->scalar_pc && s->boundary != CS_SPIN_BOUNDARY_NONE), comm, PETSC_ERR_SUP, "-%ssolver precond does not support -%sboundary (use -%ssolver sinvert)", p, p, p);
  PetscCheck(s->inverse_its >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%siterations %" PetscInt_FMT ": need at least 1", p, s->inverse_its);
  PetscCheck(s->target > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sshift %g: must be positive (the target is -shift)", p, (double)s->target);
  PetscCheck(!(s->shell && s->generalized), comm, PETSC_ERR_SUP, "-%sdirac_type shell supports only -%sproblem standard", p, p);
  PetscCheck(!(s->shell && s->inverse), comm, PETSC_ERR_SUP, "-%sdirac_type shell needs -%ssolver eps (inverse iteration factors the assembled matrix)", p, p);
  if (s->boundary != CS_SPIN_BOUNDARY_NONE) {
    PetscCheck(s->mesh->topo.boundary_loops > 0, comm, PETSC_ERR_ARG_WRONG, "-%sboundary %s: mesh %s has no boundary", p, bname, s->mesh->name);
    PetscCheck(!s->shell, comm, PETSC_ERR_SUP, "-%sboundary %s needs -%sdirac_type aij (the reduced operator is a Galerkin product)", p, bname, p);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetFromOptions(CSSpin s)
{
  const char *problems[] = {"standard", "generalized"}, *types[] = {"aij", "shell"}, *solvers[] = {"precond", "sinvert", "inverse"};
  const char *bnames[] = {"none", "keep", "file", "target"};
  PetscInt    ip = s->generalized, it = s->shell, is = s->inverse ? 2 : (s->scalar_pc ? 0 : 1), ib = (PetscInt)s->boundary;
  PetscBool   solver_set;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  /* crane2011 Sec. 4.3: with a boundary, (D - rho) lambda = 0 needs boundary conditions; with a free boundary
     the kernel of D holds every discrete conformal-affine map (rho = 0 is then not the identity). So an open
     mesh keeps its boundary tangents unless told otherwise. */
  if (s->mesh->topo.boundary_loops > 0 && s->boundary == CS_SPIN_BOUNDARY_NONE) ib = CS_SPIN_BOUNDARY_KEEP;
  PetscOptionsBegin(s->hdr.comm, s->hdr.prefix, "Spin transformations (crane2011)", NULL);
  PetscCall(CSOptionsEList("-problem", "Eigenvalue problem: standard (Eq. 7) or generalized (Eq. 6)", NULL, problems, 2, problems[ip], &ip, NULL));
  PetscCall(CSOptionsEList("-dirac_type", "Dirac operator: assembled AIJ (block size 4) or matrix-free shell", NULL, types, 2, types[it], &it, NULL));
  PetscCall(CSOptionsEList("-solver", "Smallest eigenpair: EPS preconditioned by the scalar Laplacian (Davidson), EPS with shift-and-invert (a factorisation of K - sigma), or inverse iteration", NULL, solvers, 3, solvers[is], &is, &solver_set));
  PetscCall(CSOptionsInt("-iterations", "Inverse iteration steps", NULL, s->inverse_its, &s->inverse_its, NULL));
  PetscCall(PetscOptionsBool("-keep_inverse_factor", "Inverse iteration: keep the first factorisation as preconditioner for later solves", NULL, s->keep_factor, &s->keep_factor, NULL));
  PetscCall(CSOptionsReal("-shift", "Shift toward 0 (negative target), in units of the unit sphere's spectrum", NULL, s->target, &s->target, NULL));
  PetscCall(CSOptionsReal("-lap_shift", "-spin_solver precond: the mass shift c of L + c M, in units of 4 pi / area", NULL, s->lap_shift, &s->lap_shift, NULL));
  PetscCall(PetscOptionsBool("-pin_vertex", "Fix the translation by pinning the first vertex instead of matching the mean", NULL, s->pin, &s->pin, NULL));
  PetscCall(CSOptionsEList("-boundary", "Boundary condition (Sec. 5.7): none (free), keep tangents, tangents from a file, or from the target mesh (the driver's -spin_boundary_file, -spin_target_mesh)", NULL, bnames, 4, bnames[ib], &ib, NULL));
  PetscOptionsEnd();
  s->generalized = (PetscBool)(ip == 1);
  s->shell       = (PetscBool)(it == 1);
  s->inverse     = (PetscBool)(is == 2);
  s->boundary    = (CSSpinBoundary)ib;
  /* the scalar preconditioner (spin_precond.c) is made for the standard problem on the full space: elsewhere
     the default stays shift-and-invert */
  s->scalar_pc  = (PetscBool)(is == 0);
  s->solver_set = solver_set;
  /* the default factorisation of K - sigma is the quaternion Cholesky (csquat) where K has quaternionic blocks (not
     the reduced boundary space, not Eq. 6's non-Hermitian pencil), is assembled, and lives on one rank */
  PetscCallMPI(MPI_Comm_size(s->hdr.comm, &size));
  s->quat_factor = (PetscBool)(size == 1 && !s->generalized && s->boundary == CS_SPIN_BOUNDARY_NONE && !s->shell);
  PetscCall(CheckOptions(s, bnames[ib]));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetUp(CSSpin s)
{
  PetscFunctionBeginUser;
  if (s->setupcalled) PetscFunctionReturn(0);
  PetscCall(DMCreateGlobalVector(s->dm, &s->lambda));
  PetscCall(DMCreateGlobalVector(s->mesh->dmV3, &s->xnew));
  s->setupcalled = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSolve(CSSpin s, Vec x, Vec rho)
{
  CSRhoLocation loc = rho ? s->rho_loc : CS_RHO_NONE;
  PetscFunctionBeginUser;
  PetscCheck(!rho || loc != CS_RHO_NONE, s->hdr.comm, PETSC_ERR_ORDER, "CSSpinSolve: rho given without its location (CSSpinSetRhoLocation first)");
  PetscCall(CSSpinSetUp(s));
  PetscCall(CSSpinSolveEigen(s, x, loc, rho, s->lambda));
  /* the global similarity: fit mu (Sec. 7.2) or the identity; with prescribed boundary tangents only a scale,
     since a rotation would turn the prescribed tangents */
  PetscCall(CSSpinNormalize(s, s->lambda, s->mu, (PetscBool)(s->boundary == CS_SPIN_BOUNDARY_NONE)));
  PetscCall(CSSpinReconstruct(s, x, s->lambda, s->xtarget ? s->xtarget : x, s->xnew));
  /* a painted rho fixes the shape, not its size */
  if (!s->xtarget && s->restore_area) PetscCall(CSSpinRestoreArea(s, x, s->xnew));
  for (PetscInt i = 0; i < s->hdr.monitors.n; i++) PetscCall(((CSSpinMonitorFn)s->hdr.monitors.fn[i])(s, s->hdr.monitors.ctx[i]));
  PetscFunctionReturn(0);
}

