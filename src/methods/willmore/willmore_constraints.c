/* The flow's global constraints as a growing list (CSWFAddConstraint), and the registered constraints a caller
   adds by name (CSWillmoreFlowConstraintRegister / CSWillmoreFlowAddConstraint): the built-in area, volume,
   Moebius balance and rotation gauge (src/energy/constraints_global.c) and any registered later, each built at
   the input positions. Their rows join the saddle system's bordered rows (willmore_saddle.c) like the others. */
#include "willmore_impl.h"
#include "cs_util.h"

static PetscFunctionList CSWillmoreFlowConstraints           = NULL;
static PetscBool         CSWillmoreFlowConstraintsRegistered = PETSC_FALSE;

/* Append a global constraint to the flow's list (grown as needed; the flow owns g from here on). */
PetscErrorCode CSWFAddConstraint(CSWillmoreFlow F, CSGlobalConstraint g)
{
  PetscFunctionBeginUser;
  PetscCall(CSArrayGrow(sizeof(CSGlobalConstraint), F->ng, 8, &F->ngmax, (void **)&F->gc));
  F->gc[F->ng++] = g;
  PetscFunctionReturn(0);
}

/* The built-ins with the input's values as targets (the defaults of -flow_constraint_area/volume). */
static PetscErrorCode CreateArea(CSMesh m, Vec x0, const char prefix[], CSGlobalConstraint *g)
{
  PetscReal A;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryAreaVolume(m, x0, &A, NULL));
  PetscCall(CSConstraintCreateArea(m, A, g));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateVolume(CSMesh m, Vec x0, const char prefix[], CSGlobalConstraint *g)
{
  PetscReal V;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryAreaVolume(m, x0, NULL, &V));
  PetscCall(CSConstraintCreateVolume(m, V, g));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateMobius(CSMesh m, Vec x0, const char prefix[], CSGlobalConstraint *g)
{
  PetscFunctionBeginUser;
  PetscCall(CSConstraintCreateMobiusBalance(m, x0, g));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateRotation(CSMesh m, Vec x0, const char prefix[], CSGlobalConstraint *g)
{
  PetscFunctionBeginUser;
  PetscCall(CSConstraintCreateRotationGauge(m, x0, g));
  PetscFunctionReturn(0);
}

static PetscErrorCode ConstraintListDestroy(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&CSWillmoreFlowConstraints));
  CSWillmoreFlowConstraintsRegistered = PETSC_FALSE;
  PetscFunctionReturn(0);
}

static PetscErrorCode ConstraintRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (CSWillmoreFlowConstraintsRegistered) PetscFunctionReturn(0);
  CSWillmoreFlowConstraintsRegistered = PETSC_TRUE;
  PetscCall(PetscRegisterFinalize(ConstraintListDestroy));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowConstraints, "area", CreateArea));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowConstraints, "volume", CreateVolume));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowConstraints, "mobius", CreateMobius));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowConstraints, "rotation", CreateRotation));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowConstraintRegister(const char name[], PetscErrorCode (*create)(CSMesh, Vec, const char[], CSGlobalConstraint *))
{
  PetscFunctionBeginUser;
  PetscCall(ConstraintRegisterAll());
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowConstraints, name, create));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowConstraintList(PetscFunctionList *list)
{
  PetscFunctionBeginUser;
  PetscCall(ConstraintRegisterAll());
  *list = CSWillmoreFlowConstraints;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowAddConstraint(CSWillmoreFlow F, const char name[])
{
  PetscErrorCode (*create)(CSMesh, Vec, const char[], CSGlobalConstraint *);
  char names[256];
  PetscFunctionBeginUser;
  PetscCheck(!F->setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowAddConstraint(%s): call it before CSWillmoreFlowSetUp", name);
  PetscCall(CSWillmoreFlowConstraintList(&F->constraint_list));
  PetscCall(PetscFunctionListFind(F->constraint_list, name, &create));
  if (!create) PetscCall(CSFunctionListJoin(F->constraint_list, "|", names, sizeof(names)));
  PetscCheck(create, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "CSWillmoreFlowAddConstraint(%s): unknown constraint (%s)", name, names);
  for (PetscInt j = 0; j < F->nadded; j++) { /* once: a repeat would only add dependent rows */
    PetscBool same;
    PetscCall(PetscStrcmp(F->added[j], name, &same));
    if (same) PetscFunctionReturn(0);
  }
  PetscCall(CSArrayGrow(sizeof(char *), F->nadded, 4, &F->naddedmax, (void **)&F->added));
  PetscCall(PetscStrallocpy(name, &F->added[F->nadded++]));
  PetscFunctionReturn(0);
}


/* A built-in given both by its own option and by name would add its rows twice (a singular bordered system): one
   way only. */
static PetscErrorCode RefuseTwice(CSWillmoreFlow F, const char name[])
{
  const char *opt[]  = {"area", "volume", "mobius", "rotation"};
  PetscBool   made[] = {F->area_set, F->vol_set, F->mobius, F->rotation};
  PetscFunctionBeginUser;
  for (int i = 0; i < 4; i++) {
    PetscBool same;
    PetscCall(PetscStrcmp(name, opt[i], &same));
    PetscCheck(!same || !made[i], F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%sconstraint_add %s and -%sconstraint_%s: the same constraint twice; give it one way", F->hdr.prefix, name, F->hdr.prefix, opt[i]);
  }
  PetscFunctionReturn(0);
}
/* The constraints added by name, after the built-in ones of the options (willmore_setup.c). */
PetscErrorCode CSWFSetUpAddedConstraints(CSWillmoreFlow F)
{
  PetscErrorCode (*create)(CSMesh, Vec, const char[], CSGlobalConstraint *);
  CSGlobalConstraint g;
  char               prefix[128];
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < F->nadded; j++) {
    PetscCall(RefuseTwice(F, F->added[j]));
    PetscCall(PetscFunctionListFind(F->constraint_list, F->added[j], &create));
    PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%sconstraint_%s_", F->hdr.prefix, F->added[j]));
    PetscCall((*create)(F->mesh, F->x0, prefix, &g));
    PetscCall(CSWFAddConstraint(F, g));
  }
  PetscFunctionReturn(0);
}

/* The flow's constraints and the names added (CSWillmoreFlowDestroy). */
PetscErrorCode CSWFConstraintsDestroy(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < F->ng; j++) PetscCall(CSGlobalConstraintDestroy(&F->gc[j]));
  PetscCall(PetscFree(F->gc));
  for (PetscInt j = 0; j < F->nadded; j++) PetscCall(PetscFree(F->added[j]));
  PetscCall(PetscFree(F->added));
  PetscFunctionReturn(0);
}
