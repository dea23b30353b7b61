/* The two Cholesky factorisations of a quaternionic Hermitian matrix as PETSc MatSolverTypes (include/cs_linalg.h):
     csquat     quaternion arithmetic (quaternion_cholesky.c)
     cscholmod  CHOLMOD on the complex form (cholmod_factor.c)
   for MATSEQAIJ and MAT_FACTOR_CHOLESKY, so that any PCCHOLESKY takes them through
   -<prefix>pc_factor_mat_solver_type csquat|cscholmod. The matrix must be real AIJ with every 4x4 block the left
   multiplication by a quaternion (crane2011 Sec. 5.1), e.g. K of the spin method, factored as A - sigma I with the
   shift of MatCSQuatFactorSetShift (default 0); the fill-reducing
   ordering is CHOLMOD's, chosen by -<prefix>mat_csquat_ordering / -<prefix>mat_cscholmod_ordering
   amd|metis|nesdis|auto (PETSc's ordering is not used). Which one is faster where: docs/solvers.md. */
#include <petsc/private/matimpl.h> /* a MatSolverType of our own: the factor's ops table */
#include "cs_linalg.h"
#include "cs_cholmod.h"
#include "cs_quaternion_cholesky.h"
#include "cs_util.h"

static const char *const OrderingNames[] = {"amd", "metis", "nesdis", "auto"};

typedef struct {
  PetscBool      quat;     /* csquat, else cscholmod */
  PetscInt       ordering; /* index into OrderingNames */
  PetscReal      shift;    /* sigma: the factor is that of A - sigma I (MatCSQuatFactorSetShift), default 0 */
  CSQuatCholesky qc;
  CSCholmod      cf;
} Mat_CSQuatFactor;

static PetscErrorCode MatSolve_CSQuatFactor(Mat F, Vec b, Vec x)
{
  Mat_CSQuatFactor *q = (Mat_CSQuatFactor *)F->data;
  PetscFunctionBeginUser;
  if (q->quat) PetscCall(CSQuatCholeskySolve(q->qc, b, x));
  else PetscCall(CSCholmodSolve(q->cf, b, x));
  PetscFunctionReturn(0);
}

/* A - shift I, the shift subtracted from the diagonal blocks as the entries are read (no shifted copy of A) */
static PetscErrorCode MatCholeskyFactorNumeric_CSQuatFactor(Mat F, Mat A, const MatFactorInfo *info)
{
  Mat_CSQuatFactor *q = (Mat_CSQuatFactor *)F->data;
  PetscFunctionBeginUser;
  if (q->quat) PetscCall(CSQuatCholeskySetUp(q->qc, A, q->shift));
  else PetscCall(CSCholmodSetUpQuaternion(q->cf, A, q->shift));
  F->ops->solve          = MatSolve_CSQuatFactor;
  F->ops->solvetranspose = MatSolve_CSQuatFactor; /* Hermitian */
  F->assembled           = PETSC_TRUE;
  F->preallocated        = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* the ordering option; the analysis itself is done (and kept while A's pattern stays) by the numeric phase */
static PetscErrorCode MatCholeskyFactorSymbolic_CSQuatFactor(Mat F, Mat A, IS perm, const MatFactorInfo *info)
{
  Mat_CSQuatFactor *q = (Mat_CSQuatFactor *)F->data;
  PetscInt          ordering = q->ordering;
  PetscMPIInt       size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)A), &size));
  PetscCheck(size == 1, PetscObjectComm((PetscObject)A), PETSC_ERR_SUP, "-pc_factor_mat_solver_type %s is serial: the matrix lives on %d processes", F->solvertype, size);
  PetscOptionsBegin(PetscObjectComm((PetscObject)F), ((PetscObject)F)->prefix, "Quaternionic Cholesky factorisation", "Mat");
  if (q->quat) PetscCall(CSOptionsEList("-mat_csquat_ordering", "Fill-reducing ordering of the quaternion Cholesky, by CHOLMOD (auto: CHOLMOD tries several)", NULL, OrderingNames, 4, OrderingNames[ordering], &ordering, NULL));
  else PetscCall(CSOptionsEList("-mat_cscholmod_ordering", "Fill-reducing ordering of CHOLMOD's complex-form Cholesky (auto: CHOLMOD tries several)", NULL, OrderingNames, 4, OrderingNames[ordering], &ordering, NULL));
  PetscOptionsEnd();
  if (ordering != q->ordering) {
    PetscCall(CSQuatCholeskyDestroy(&q->qc));
    PetscCall(CSCholmodDestroy(&q->cf));
    q->ordering = ordering;
  }
  if (q->quat && !q->qc) PetscCall(CSQuatCholeskyCreate(OrderingNames[q->ordering], &q->qc));
  if (!q->quat && !q->cf) PetscCall(CSCholmodCreate(OrderingNames[q->ordering], &q->cf));
  F->ops->choleskyfactornumeric = MatCholeskyFactorNumeric_CSQuatFactor;
  PetscFunctionReturn(0);
}

static PetscErrorCode MatCSQuatFactorSetShift_CSQuatFactor(Mat F, PetscReal shift)
{
  Mat_CSQuatFactor *q = (Mat_CSQuatFactor *)F->data;
  PetscFunctionBeginUser;
  q->shift = shift;
  PetscFunctionReturn(0);
}

PetscErrorCode MatCSQuatFactorSetShift(Mat F, PetscReal shift)
{
  PetscFunctionBeginUser;
  PetscValidHeaderSpecific(F, MAT_CLASSID, 1);
  PetscUseMethod(F, "MatCSQuatFactorSetShift_C", (Mat, PetscReal), (F, shift));
  PetscFunctionReturn(0);
}

static PetscErrorCode MatDestroy_CSQuatFactor(Mat F)
{
  Mat_CSQuatFactor *q = (Mat_CSQuatFactor *)F->data;
  PetscFunctionBeginUser;
  PetscCall(CSQuatCholeskyDestroy(&q->qc));
  PetscCall(CSCholmodDestroy(&q->cf));
  PetscCall(PetscFree(F->data));
  PetscCall(PetscObjectComposeFunction((PetscObject)F, "MatFactorGetSolverType_C", NULL));
  PetscCall(PetscObjectComposeFunction((PetscObject)F, "MatCSQuatFactorSetShift_C", NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode MatView_CSQuatFactor(Mat F, PetscViewer viewer)
{
  Mat_CSQuatFactor *q = (Mat_CSQuatFactor *)F->data;
  PetscBool         ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii) PetscCall(PetscViewerASCIIPrintf(viewer, "%s, CHOLMOD ordering %s, shift %g\n", q->quat ? "supernodal Cholesky in quaternion arithmetic" : "CHOLMOD Cholesky of the complex form", OrderingNames[q->ordering], (double)q->shift));
  PetscFunctionReturn(0);
}

static PetscErrorCode MatGetInfo_CSQuatFactor(Mat F, MatInfoType flag, MatInfo *info)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(info, sizeof(*info)));
  info->block_size = 4;
  PetscFunctionReturn(0);
}

static PetscErrorCode MatFactorGetSolverType_CSQuatFactor(Mat F, MatSolverType *type)
{
  PetscFunctionBeginUser;
  *type = F->solvertype;
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateFactor(Mat A, MatFactorType ftype, PetscBool quat, Mat *F)
{
  Mat               B;
  Mat_CSQuatFactor *q;
  PetscInt          m, n;
  const char       *prefix, *name = quat ? MATSOLVERCSQUAT : MATSOLVERCSCHOLMOD;
  PetscFunctionBeginUser;
  PetscCheck(ftype == MAT_FACTOR_CHOLESKY, PetscObjectComm((PetscObject)A), PETSC_ERR_SUP, "%s provides Cholesky factorisations only", name);
  PetscCall(MatGetSize(A, &m, &n));
  PetscCall(MatCreate(PetscObjectComm((PetscObject)A), &B));
  PetscCall(MatSetSizes(B, PETSC_DECIDE, PETSC_DECIDE, m, n));
  PetscCall(PetscStrallocpy(name, &((PetscObject)B)->type_name));
  PetscCall(MatGetOptionsPrefix(A, &prefix));
  PetscCall(MatSetOptionsPrefix(B, prefix));
  PetscCall(MatSetUp(B));
  PetscCall(PetscNew(&q));
  q->quat                        = quat;
  B->data                        = q;
  B->ops->choleskyfactorsymbolic = MatCholeskyFactorSymbolic_CSQuatFactor;
  B->ops->destroy                = MatDestroy_CSQuatFactor;
  B->ops->view                   = MatView_CSQuatFactor;
  B->ops->getinfo                = MatGetInfo_CSQuatFactor;
  PetscCall(PetscObjectComposeFunction((PetscObject)B, "MatFactorGetSolverType_C", MatFactorGetSolverType_CSQuatFactor));
  PetscCall(PetscObjectComposeFunction((PetscObject)B, "MatCSQuatFactorSetShift_C", MatCSQuatFactorSetShift_CSQuatFactor));
  B->factortype     = MAT_FACTOR_CHOLESKY;
  B->assembled      = PETSC_TRUE;
  B->preallocated   = PETSC_TRUE;
  B->canuseordering = PETSC_FALSE; /* CHOLMOD orders */
  PetscCall(PetscFree(B->solvertype));
  PetscCall(PetscStrallocpy(name, &B->solvertype));
  *F = B;
  PetscFunctionReturn(0);
}

PetscErrorCode MatGetFactor_SeqAIJ_CSQuat(Mat A, MatFactorType ftype, Mat *F)
{
  PetscFunctionBeginUser;
  PetscCall(CreateFactor(A, ftype, PETSC_TRUE, F));
  PetscFunctionReturn(0);
}

PetscErrorCode MatGetFactor_SeqAIJ_CSCholmod(Mat A, MatFactorType ftype, Mat *F)
{
  PetscFunctionBeginUser;
  PetscCall(CreateFactor(A, ftype, PETSC_FALSE, F));
  PetscFunctionReturn(0);
}
