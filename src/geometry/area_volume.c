/* Total area and enclosed volume; both are sums over faces, and every face lives on exactly one rank. */
#include "cs_geometry.h"

PetscErrorCode CSGeometryAreaVolume(CSMesh m, Vec x, PetscReal *area, PetscReal *volume)
{
  Vec              xl;
  const PetscReal *p;
  PetscReal        s[2] = {0, 0}, g[2];
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  for (PetscInt f = 0; f < m->nf; f++) {
    const PetscInt  *v    = m->faceVert + 3 * f;
    const PetscReal *c[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    PetscReal        an[3], jk[3];
    CSTriangleAreaVector(c, an);
    s[0] += CSVecNorm(an);
    CSVecCross(c[1], c[2], jk);
    s[1] += CSVecDot(c[0], jk) / 6; /* soliman2021 App. B.2 */
  }
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MPIU_Allreduce(s, g, 2, MPIU_REAL, MPIU_SUM, m->comm));
  if (area) *area = g[0];
  if (volume) *volume = g[1];
  PetscFunctionReturn(0);
}
