/* bobenko-schroeder2005 Sec. 3.2, "Gradient Singularity", several vanishing betas at a vertex: the steepest
   descent direction from the paper's delta minimisation

     delta = min_{|G| = 1, <G, g> >= 0}  sum_n |R_n x G| - <G, g>,

   g the sum of the regular negative gradients, R_n = R_n t_n the rate vector of the n-th vanishing beta (t_n the
   unit tangent of its circle C_n at v_i, R_n the rate at which beta grows for a unit move orthogonal to C_n).
   The paper solves this non-linear minimisation over the sphere; it is the same as a small convex problem:
   h(G) = sum_n R_n |P_n G| - <G, g> (P_n = I - t_n t_n^T) is positively homogeneous and convex, the support
   function of the convex set S = -g + sum_n R_n D_n, D_n the unit disk orthogonal to t_n (|P_n G| = max over
   s in D_n of <s, G>). By the minimax theorem min_{|G| <= 1} h(G) = min_G max_{y in S} <y, G> =
   max_{y in S} (-|y|) = -dist(0, S). So with p the point of S nearest 0:
     p != 0: delta = -|p| < 0, attained at G = -p/|p| (where <G, g> > 0 holds, since the sum term is >= 0):
             the steepest descent is d = -p = g - sum_n R_n s_n, of magnitude |delta|, as the paper asks;
     p == 0: h >= 0 everywhere, delta >= 0: "no motion exists which decreases the energy", d = 0.
   p = -g + sum_n R_n s_n minimises |g - sum_n R_n s_n|^2 over s_n in D_n: block coordinate descent, each block
   exactly (the part of the residual orthogonal to t_n, divided by R_n, clipped to the unit disk). For one
   vanishing beta this is the paper's closed form: s = g_o/R if R > |g_o| (d = g_p), else s = g_o/|g_o|
   (d = g_p + g_o (1 - R/|g_o|)). */
#include "cs_energy_bs.h"
#include "cs_geometry.h"

/* d <- g - sum_n R_n s_n, the descent direction for the disks' points s */
static void Residual(PetscInt n, const PetscReal g[3], const PetscReal R[], const PetscReal s[], PetscReal d[3])
{
  for (int c = 0; c < 3; c++) d[c] = g[c];
  for (PetscInt k = 0; k < n; k++)
    for (int c = 0; c < 3; c++) d[c] -= R[k] * s[3 * k + c];
}

PetscErrorCode CSBSSingularDescent(const PetscReal g[3], PetscInt n, const PetscReal t[], const PetscReal R[], PetscReal d[3], PetscInt *its)
{
  PetscReal s[3 * CS_BS_SINGULAR_MAX] = {0}, scale = CSVecNorm(g);
  PetscInt  it;
  PetscFunctionBeginUser;
  PetscCheck(n >= 0 && n <= CS_BS_SINGULAR_MAX, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%" PetscInt_FMT " vanishing betas at one vertex: at most %d", n, CS_BS_SINGULAR_MAX);
  for (PetscInt k = 0; k < n; k++) {
    PetscCheck(R[k] > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "rate R of a vanishing beta must be > 0, got %g", (double)R[k]);
    scale += R[k];
  }
  for (it = 0; it < 10000; it++) {
    PetscReal change = 0;
    for (PetscInt k = 0; k < n; k++) {
      const PetscReal *tk = t + 3 * k;
      PetscReal        q[3], qt, nq = 0, f;
      Residual(n, g, R, s, q);
      for (int c = 0; c < 3; c++) q[c] += R[k] * s[3 * k + c]; /* the residual without block k */
      qt = CSVecDot(q, tk);
      for (int c = 0; c < 3; c++) {
        q[c] = (q[c] - qt * tk[c]) / R[k]; /* P_k q / R_k */
        nq += q[c] * q[c];
      }
      nq = PetscSqrtReal(nq);
      f  = nq > 1 ? 1 / nq : 1; /* clip to the unit disk */
      for (int c = 0; c < 3; c++) {
        change = PetscMax(change, PetscAbsReal(R[k] * (f * q[c] - s[3 * k + c])));
        s[3 * k + c] = f * q[c];
      }
    }
    if (change <= 1e-15 * scale) break;
  }
  Residual(n, g, R, s, d);
  if (CSVecNorm(d) <= 1e-12 * scale) /* 0 in S up to rounding (the sweeps stop at 1e-15 scale): delta >= 0 */
    for (int c = 0; c < 3; c++) d[c] = 0;
  if (its) *its = it;
  PetscFunctionReturn(0);
}
