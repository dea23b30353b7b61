/* Edge lengths, dual lengths, turning angles and curvature of a distributed curve (include/cs_curve_geometry.h,
   crane2013 Sec. 5.2). Every kernel reads the owned block and the two ghost vertices (CSCurveGhosts). */
#include "cs_curve_geometry.h"
#include "cs_log.h"

/* position of local vertex i in [-1, n] (the ghosts at -1 and n) */
static inline const PetscReal *Pos(const PetscReal *a, const PetscReal lr[4], PetscInt i, PetscInt n)
{
  return i < 0 ? lr : (i >= n ? lr + 2 : a + 2 * i);
}

/* a value per owned vertex from the positions p, q, r of the vertices i-1, i, i+1 (gi: the global index of i) */
typedef PetscReal (*VertexStencil)(CSCurve c, PetscInt gi, const PetscReal p[], const PetscReal q[], const PetscReal r[]);

/* out[i] = f(vertex i) for every owned vertex i, the neighbours across ranks and the wrap-around from the ghosts */
static PetscErrorCode ApplyStencil(CSCurve c, Vec x, Vec out, VertexStencil f)
{
  const PetscScalar *a;
  PetscScalar       *o;
  PetscReal          lr[4];
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscCall(CSCurveGhosts(c, x, lr));
  PetscCall(VecGetArrayRead(x, &a));
  PetscCall(VecGetArray(out, &o));
  for (PetscInt i = 0; i < c->n; i++) o[i] = f(c, c->rstart + i, Pos(a, lr, i - 1, c->n), Pos(a, lr, i, c->n), Pos(a, lr, i + 1, c->n));
  PetscCall(VecRestoreArray(out, &o));
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscCall(PetscLogEventEnd(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* edge i, from vertex i to i+1; zero for the last vertex of an open curve */
static PetscReal EdgeLength(CSCurve c, PetscInt gi, const PetscReal p[], const PetscReal q[], const PetscReal r[])
{
  return (!c->closed && gi == c->N - 1) ? 0 : PetscSqrtReal(PetscSqr(r[0] - q[0]) + PetscSqr(r[1] - q[1]));
}

PetscErrorCode CSCurveEdgeLengths(CSCurve c, Vec x, Vec len)
{
  PetscFunctionBeginUser;
  PetscCall(ApplyStencil(c, x, len, EdgeLength));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveDualLengths(CSCurve c, Vec len, Vec d)
{
  const PetscScalar *l;
  PetscScalar       *w;
  PetscReal          lr[4];
  PetscFunctionBeginUser;
  PetscCall(CSCurveGhosts(c, len, lr)); /* lr[0] = l_{rstart-1} (0 at an open start) */
  PetscCall(VecGetArrayRead(len, &l));
  PetscCall(VecGetArray(d, &w));
  for (PetscInt i = 0; i < c->n; i++) w[i] = 0.5 * ((i ? l[i - 1] : lr[0]) + l[i]);
  PetscCall(VecRestoreArray(d, &w));
  PetscCall(VecRestoreArrayRead(len, &l));
  PetscFunctionReturn(0);
}

/* the signed angle from edge i-1 to edge i; zero at the ends of an open curve */
static PetscReal TurningAngle(CSCurve c, PetscInt gi, const PetscReal p[], const PetscReal q[], const PetscReal r[])
{
  PetscReal u[2] = {q[0] - p[0], q[1] - p[1]}, v[2] = {r[0] - q[0], r[1] - q[1]};
  return (!c->closed && (gi == 0 || gi == c->N - 1)) ? 0 : PetscAtan2Real(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]);
}

PetscErrorCode CSCurveTurningAngles(CSCurve c, Vec x, Vec phi)
{
  PetscFunctionBeginUser;
  PetscCall(ApplyStencil(c, x, phi, TurningAngle));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveCurvature(CSCurve c, Vec x, Vec d, Vec kappa)
{
  PetscFunctionBeginUser;
  PetscCall(CSCurveTurningAngles(c, x, kappa));
  PetscCall(VecPointwiseDivide(kappa, kappa, d));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFirstEdgeAngle(CSCurve c, Vec x, PetscReal *theta0)
{
  PetscReal lr[4], t = 0;
  PetscFunctionBeginUser;
  PetscCall(CSCurveGhosts(c, x, lr)); /* collective: every rank takes part */
  if (c->rstart == 0) {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(x, &a));
    {
      const PetscReal *q = c->n > 1 ? a + 2 : lr + 2;
      t                  = PetscAtan2Real(q[1] - a[1], q[0] - a[0]);
    }
    PetscCall(VecRestoreArrayRead(x, &a));
  }
  PetscCallMPI(MPI_Allreduce(&t, theta0, 1, MPIU_REAL, MPIU_SUM, c->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveDot(CSCurve c, Vec w, Vec a, Vec b, PetscReal *dot)
{
  const PetscScalar *pw = NULL, *pa, *pb;
  PetscReal          s  = 0;
  PetscFunctionBeginUser;
  if (w) PetscCall(VecGetArrayRead(w, &pw));
  PetscCall(VecGetArrayRead(a, &pa));
  PetscCall(VecGetArrayRead(b, &pb));
  for (PetscInt i = 0; i < c->n; i++) s += (pw ? pw[i] : 1) * pa[i] * pb[i];
  PetscCall(VecRestoreArrayRead(b, &pb));
  PetscCall(VecRestoreArrayRead(a, &pa));
  if (w) PetscCall(VecRestoreArrayRead(w, &pw));
  PetscCallMPI(MPI_Allreduce(&s, dot, 1, MPIU_REAL, MPIU_SUM, c->comm));
  PetscFunctionReturn(0);
}
