/* Mesh-quality pre-check before a flow (issue 18, item 11): a sliver face (relative area 1e-10) passed the
   validation and then stopped the CGD flow at step 1 with "CHOLMOD ... not positive definite, failure at column
   1654", naming neither the face nor the cause. Here the faces whose area relative to the mean face area, or whose
   smallest angle, is below a threshold are reported (the worst of each, with their vertices) and the run refused,
   or warned about (-mesh_quality_action warn), before any solver meets them. Rank 0 checks the positions gathered
   in file order, so the face and vertex numbers are those of the input file. */
#include "cs_mesh.h"
#include "cs_util.h"

const char *const CSMeshQualityActions[] = {"refuse", "warn", "off", "CSMeshQualityAction", "CS_MESH_QUALITY_", NULL};
typedef enum {
  CS_MESH_QUALITY_REFUSE,
  CS_MESH_QUALITY_WARN,
  CS_MESH_QUALITY_OFF
} CSMeshQualityAction;

typedef struct {
  PetscReal min_area, min_angle; /* thresholds: relative area, degrees */
  PetscInt  nbad, worst_area, worst_angle;
  PetscReal area_worst, angle_worst;
} Quality;

/* area and smallest angle (degrees) of the triangle a b c */
static void Triangle(const PetscReal *a, const PetscReal *b, const PetscReal *c, PetscReal *area, PetscReal *angle)
{
  const PetscReal *p[3] = {a, b, c};
  *angle                = 180;
  for (int k = 0; k < 3; k++) {
    const PetscReal *o = p[k], *q = p[(k + 1) % 3], *r = p[(k + 2) % 3];
    PetscReal        u[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]}, v[3] = {r[0] - o[0], r[1] - o[1], r[2] - o[2]};
    PetscReal        n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    PetscReal        s = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    *area              = s / 2;
    *angle             = PetscMin(*angle, PetscAtan2Real(s, d) * 180 / PETSC_PI);
  }
}

/* rank 0: the faces below the thresholds (count, worst of each kind) */
static PetscErrorCode Scan(const CSMeshData *md, const PetscScalar *x, Quality *q)
{
  PetscReal *area, *angle, total = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(md->nf, &area, md->nf, &angle));
  for (PetscInt f = 0; f < md->nf; f++) {
    const PetscInt *t = md->f + 3 * f;
    PetscReal       p[3][3];
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 3; d++) p[k][d] = PetscRealPart(x[3 * t[k] + d]);
    Triangle(p[0], p[1], p[2], &area[f], &angle[f]);
    total += area[f];
  }
  q->nbad = 0;
  q->worst_area = q->worst_angle = 0;
  for (PetscInt f = 0; f < md->nf; f++) {
    area[f] /= total / md->nf;
    if (area[f] < area[q->worst_area]) q->worst_area = f;
    if (angle[f] < angle[q->worst_angle]) q->worst_angle = f;
    q->nbad += (area[f] < q->min_area || angle[f] < q->min_angle);
  }
  q->area_worst  = area[q->worst_area];
  q->angle_worst = angle[q->worst_angle];
  PetscCall(PetscFree2(area, angle));
  PetscFunctionReturn(0);
}

static PetscErrorCode Report(const CSMeshData *md, const char name[], const Quality *q, char msg[], size_t len)
{
  const PetscInt *a = md->f + 3 * q->worst_area, *b = md->f + 3 * q->worst_angle;
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(msg, len, "mesh %s: %" PetscInt_FMT " faces below -mesh_quality_min_area %g (area / mean face area) or -mesh_quality_min_angle %g (degrees); smallest relative area %.3g at face %" PetscInt_FMT " (vertices %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "), smallest angle %.3g deg at face %" PetscInt_FMT " (vertices %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT ")",
                          name, q->nbad, (double)q->min_area, (double)q->min_angle, (double)q->area_worst, q->worst_area, a[0], a[1], a[2], (double)q->angle_worst, q->worst_angle, b[0], b[1], b[2]));
  PetscFunctionReturn(0);
}

/* rank 0: refuse (an error) or warn */
static PetscErrorCode CheckRoot(CSMesh m, Vec nat, Quality *q, CSMeshQualityAction action)
{
  const PetscScalar *x;
  char               msg[PETSC_MAX_PATH_LEN + 512];
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(nat, &x));
  PetscCall(Scan(&m->serial, x, q));
  PetscCall(VecRestoreArrayRead(nat, &x));
  if (!q->nbad) PetscFunctionReturn(0);
  PetscCall(Report(&m->serial, m->name, q, msg, sizeof(msg)));
  PetscCheck(action != CS_MESH_QUALITY_REFUSE, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: a solver would fail on them (-mesh_quality_action warn runs anyway)", msg);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Warning: %s\n", msg));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshQualityCheck(CSMesh m, const char prefix[], Vec x)
{
  Quality             q      = {1e-8, 1e-5, 0, 0, 0, 0, 0}; /* the real meshes pass: triceratops_cgal has 1.7e-6 and 2e-4 deg */
  CSMeshQualityAction action = CS_MESH_QUALITY_REFUSE;
  Vec                 nat;
  PetscFunctionBeginUser;
  PetscOptionsBegin(m->comm, prefix, "Mesh quality before a flow", NULL);
  PetscCall(CSOptionsEnum("-mesh_quality_action", "Faces below the thresholds: refuse the run, warn, or no check", "CSMeshQualityCheck", CSMeshQualityActions, (PetscEnum)action, (PetscEnum *)&action, NULL));
  PetscCall(CSOptionsReal("-mesh_quality_min_area", "Smallest accepted face area relative to the mean face area", "CSMeshQualityCheck", q.min_area, &q.min_area, NULL));
  PetscCall(CSOptionsReal("-mesh_quality_min_angle", "Smallest accepted face angle (degrees)", "CSMeshQualityCheck", q.min_angle, &q.min_angle, NULL));
  PetscOptionsEnd();
  {
    const CSOptionCheck checks[] = {
      {"mesh_quality_min_area",  q.min_area,  (PetscBool)(q.min_area >= 0 && q.min_area < 1),    "must be in [0, 1)"  },
      {"mesh_quality_min_angle", q.min_angle, (PetscBool)(q.min_angle >= 0 && q.min_angle < 60), "must be in [0, 60)"}
    };
    PetscCall(CSCheckOptionValues(m->comm, prefix, 2, checks));
  }
  if (action == CS_MESH_QUALITY_OFF) PetscFunctionReturn(0);
  PetscCall(CSMeshGather(&m->natV3, x, &nat));
  CSRootCall(m->comm, CheckRoot(m, nat, &q, action));
  PetscFunctionReturn(0);
}
