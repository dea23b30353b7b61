/* The conformal curvature flow (crane2013 Sec. 6) through the library API alone, no bin/confsurf:
   1. Sec. 4's spectral filter v <- v - (id + s A^k)^{-1} v on the unit icosphere (level 4): its gain on the
      spherical harmonics x (l = 1), xy (2), xyz (3), x^4 + y^4 + z^4 - 3/5 (4), measured as <<F v, v>> / <<v, v>>
      in the vertex-area inner product, against s w^k / (1 + s w^k), w = l (l + 1), s = sigma (area/4pi)^k, for
      k = 0..3, to 1 %;
   2. a noisy icosphere (level 3) flowed with CSConformalFlowStep in code (tau 0.5 set before SetFromOptions):
      W falls at every step, the monitor sees every state, the projected direction is orthogonal to 1 and N
      to 1e-12.
   Exit status = number of failures. Run: build/tests/test_conformal_api (also mpirun -n 2) */
#include <petscsys.h>
#include "cs_methods_conformal.h"
#include "cs_geometry.h"
#include "cs_test.h"

/* Y_l(f): the test fields of the conformal flow's checks (l = 1, 2, 3: x, xy, xyz; else x^4 + y^4 + z^4 - 3/5) */
static PetscReal Harmonic(const PetscReal f[3], PetscReal l)
{
  const PetscReal p = f[0], q = f[1], r = f[2];
  return l == 1 ? p : l == 2 ? p * q : l == 3 ? p * q * r : p * p * p * p + q * q * q * q + r * r * r * r - 0.6;
}

static PetscErrorCode FilterGains(MPI_Comm comm)
{
  CSMesh          mesh;
  CSConformalFlow flow;
  Vec             v, w, M;
  PetscReal       A, vol, sig[4] = {0.5, 0.1, 0.01, 0.001};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_ICOSPHERE, 4, 0, 0, 0}, 0, 0, &mesh));
  PetscCall(CSGeometryAreaVolume(mesh, mesh->x, &A, &vol));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &v));
  PetscCall(VecDuplicate(v, &w));
  PetscCall(VecDuplicate(v, &M));
  PetscCall(CSGeometryVertexAreas(mesh, mesh->x, M));
  for (PetscInt k = 0; k < 4; k++) {
    PetscCall(CSConformalFlowCreate(mesh, &flow));
    PetscCall(CSConformalFlowSetFilter(flow, sig[k], k));
    PetscCall(CSConformalFlowSetFromOptions(flow));
    PetscCall(CSConformalFlowSetUp(flow));
    for (PetscInt l = 1; l <= 4; l++) {
      PetscReal s = sig[k] * PetscPowReal(A / (4 * PETSC_PI), (PetscReal)k), sw = s * PetscPowReal((PetscReal)(l * (l + 1)), (PetscReal)k), want = sw / (1 + sw), num, den, gain;
      char      what[64];
      PetscCall(CSTestVertexField(mesh, Harmonic, (PetscReal)l, v));
      PetscCall(VecCopy(v, w));
      PetscCall(CSConformalFlowApplyFilter(flow, w));
      PetscCall(VecPointwiseMult(w, w, M));
      PetscCall(VecDot(w, v, &num));
      PetscCall(VecPointwiseMult(w, v, M));
      PetscCall(VecDot(w, v, &den));
      gain = num / den;
      PetscCall(PetscSNPrintf(what, sizeof(what), "filter k=%" PetscInt_FMT " l=%" PetscInt_FMT ": |gain/formula - 1| (gain %.4f)", k, l, (double)gain));
      PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(gain / want - 1) < 0.01), what, PetscAbsReal(gain / want - 1), 0.01));
    }
    PetscCall(CSConformalFlowDestroy(&flow));
  }
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&M));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt  states, increases;
  PetscReal W, res;
} Watch;

static PetscErrorCode WatchStates(CSConformalFlow flow, const CSConformalMonitorInfo *s, void *ctx)
{
  Watch *w = (Watch *)ctx;
  PetscFunctionBeginUser;
  if (s->event == CS_CONFORMAL_MONITOR_END) PetscFunctionReturn(0);
  if (w->states && s->W > w->W) w->increases++;
  w->W   = s->W;
  w->res = PetscMax(w->res, PetscMax(s->res_total, s->res_inversion));
  w->states++;
  PetscFunctionReturn(0);
}

static PetscErrorCode FlowNoisySphere(MPI_Comm comm)
{
  CSMesh                         mesh;
  CSConformalFlow                flow;
  CSConformalFlowConvergedReason reason = CS_CONFORMAL_ITERATING;
  CSConformalFlowInfo            info;
  Watch                          w = {0, 0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_ICOSPHERE, 3, 0, 0, 0}, 0.02, 7, &mesh));
  PetscCall(CSConformalFlowCreate(mesh, &flow));
  PetscCall(CSConformalFlowSetOptionsPrefix(flow, "test_"));
  PetscCall(CSConformalFlowSetTimeStep(flow, 0.5));
  PetscCall(CSConformalFlowSetTolerances(flow, 0, 0, 4));
  PetscCall(CSConformalFlowMonitorSet(flow, WatchStates, &w, NULL));
  PetscCall(CSConformalFlowSetFromOptions(flow));
  while (reason == CS_CONFORMAL_ITERATING) {
    PetscCall(CSConformalFlowStep(flow));
    PetscCall(CSConformalFlowGetConvergedReason(flow, &reason));
  }
  PetscCall(CSConformalFlowGetInfo(flow, &info));
  PetscCall(CSTestCheck(comm, (PetscBool)(reason == CS_CONFORMAL_DIVERGED_MAX_IT && info.state.it == 4), "noisy sphere: 4 steps (max_it)", (PetscReal)info.state.it, 4));
  PetscCall(CSTestCheck(comm, (PetscBool)(w.states == 5), "monitor saw every state", (PetscReal)w.states, 5));
  PetscCall(CSTestCheck(comm, (PetscBool)(w.increases == 0 && info.state.W < info.W_initial), "W fell at every step (increases)", (PetscReal)w.increases, 0));
  PetscCall(CSTestCheck(comm, (PetscBool)(w.res < 1e-12), "direction orthogonal to 1, N^x,y,z", w.res, 1e-12));
  PetscCall(CSConformalFlowDestroy(&flow));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(FilterGains(PETSC_COMM_WORLD));
  PetscCall(FlowNoisySphere(PETSC_COMM_WORLD));
  return CSTestFinalize(PETSC_COMM_WORLD, PetscFinalize);
}
