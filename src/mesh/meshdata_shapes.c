/* Generated inputs of soliman2021's genus-0 examples: the spiky sphere (Fig. 8) and a Morin surface (Fig. 15). */
#include "meshdata_generate_impl.h"
#include <stdio.h>
#include <complex.h>

const char *const CSMorinKinds[] = {"apery", "kusner", "CSMorinKind", "CS_MORIN_", NULL};

/* -gen spiky: the icosphere of -gen_level L, radius 1, with a spike on each of the 12 icosahedron directions s_k
   (the first 12 vertices: the subdivision appends): r(x) = 1 + h sum_k max(0, 1 - theta_k / w)^2, theta_k the
   angle between x and s_k. The spike tips are mesh vertices (cone points of the discrete surface). With round,
   md->len holds the edge lengths of the round icosphere before the spikes: the flows' target class is then the
   round sphere's (Fig. 8: the spikes must go, which the class of the spiky mesh itself does not allow). */
PetscErrorCode CSMeshDataSpikySphere(PetscInt level, PetscReal height, PetscReal width, PetscBool round, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCheck(height > -1 && width > 0 && width < 0.55, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen spiky: -gen_spike_height %g must be > -1 and -gen_spike_width %g in (0, 0.55) radians (spikes that do not overlap: the icosahedron's directions are 1.107 apart)", (double)height, (double)width);
  PetscCall(CSMeshDataIcosphere(level, 1.0, PETSC_TRUE, md));
  if (round) {
    PetscCall(PetscMalloc1(3 * md->nf, &md->len));
    for (PetscInt f = 0; f < md->nf; f++)
      for (int k = 0; k < 3; k++) {
        const PetscReal *a = md->x + 3 * md->f[3 * f + (k + 1) % 3], *b = md->x + 3 * md->f[3 * f + (k + 2) % 3];
        md->len[3 * f + k] = PetscSqrtReal(PetscSqr(a[0] - b[0]) + PetscSqr(a[1] - b[1]) + PetscSqr(a[2] - b[2]));
      }
  }
  for (PetscInt v = 12; v < md->nv; v++) {
    PetscReal *p = md->x + 3 * v, r = 1;
    for (PetscInt k = 0; k < 12; k++) {
      const PetscReal *s = md->x + 3 * k;
      PetscReal        d = PetscMin(1.0, PetscMax(-1.0, p[0] * s[0] + p[1] * s[1] + p[2] * s[2]));
      PetscReal        b = PetscMax(0.0, 1.0 - PetscAcosReal(d) / width);
      r += height * b * b;
    }
    for (int c = 0; c < 3; c++) p[c] *= r;
  }
  for (PetscInt k = 0; k < 12; k++)
    for (int c = 0; c < 3; c++) md->x[3 * k + c] *= 1 + height;
  snprintf(md->name, sizeof(md->name), "spiky(level=%" PetscInt_FMT ",height=%g,width=%g%s)", level, (double)height, (double)width, round ? ",round class" : "");
  PetscFunctionReturn(0);
}

/* Apery's Morin surface of order 2 (mathcurve.com "Morin surface", k = 1): for u in [-pi/2, pi/2], v in [0, 2pi),
     K = cos u / (sqrt2 - sin 2u sin 2v),  X = K (2 cos u cos v + sqrt2 sin u cos v, 2 cos u sin v - sqrt2 sin u
     sin v, cos u),
   an immersed sphere (measured: the sine of the angle between X_u and X_v stays >= 0.12 away from the poles, which
   both map to the origin, tangent to z = 0) invariant under the rotation by pi/2 about z. The symmetry-breaking
   perturbation (soliman2021 Fig. 15: "slightly perturbed to break the symmetry") adds eps (sin(u + 0.3) cos v,
   cos^2 u sin 3v, 0.5 cos u sin(v + 1)) to every vertex, eps = -gen_morin_perturb. */
static void MorinPoint(PetscReal u, PetscReal v, PetscReal eps, PetscReal *x)
{
  const PetscReal s2 = PetscSqrtReal(2.0), cu = PetscCosReal(u), su = PetscSinReal(u);
  const PetscReal K  = cu / (s2 - PetscSinReal(2 * u) * PetscSinReal(2 * v));
  x[0] = K * (2 * cu * PetscCosReal(v) + s2 * su * PetscCosReal(v)) + eps * PetscSinReal(u + 0.3) * PetscCosReal(v);
  x[1] = K * (2 * cu * PetscSinReal(v) - s2 * su * PetscSinReal(v)) + eps * cu * cu * PetscSinReal(3 * v);
  x[2] = K * cu + eps * 0.5 * cu * PetscSinReal(v + 1);
}

/* Texture coordinates of the Morin grid (issue 38): (v / 2 pi, (u + pi/2) / pi) = (i/n, j/m) on the rings, unwrapped
   per face so the seam column i = n repeats i = 0 with u = 1; each fan face's pole corner gets its own UV
   ((i + 1/2)/n, 0 or 1), so no UV triangle is degenerate. Face order as CSMeshDataMorin makes them. */
static PetscErrorCode MorinUVs(PetscInt n, PetscInt m, CSMeshData *md)
{
  PetscInt R = n * (m - 1), nring = (n + 1) * (m - 1);
  PetscFunctionBeginUser;
  md->nuv = nring + 2 * n;
  PetscCall(PetscMalloc1(2 * md->nuv, &md->uv));
  PetscCall(PetscMalloc1(3 * md->nf, &md->fuv));
  for (PetscInt gi = 0; gi <= n; gi++)
    for (PetscInt J = 1; J < m; J++) {
      md->uv[2 * (gi * (m - 1) + J - 1)]     = (PetscReal)gi / n;
      md->uv[2 * (gi * (m - 1) + J - 1) + 1] = (PetscReal)J / m;
    }
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt p = 0; p < 2; p++) {
      md->uv[2 * (nring + p * n + i)]     = (i + 0.5) / n;
      md->uv[2 * (nring + p * n + i) + 1] = p;
    }
  for (PetscInt f = 0; f < md->nf; f++) {
    PetscBool fan = (PetscBool)(f >= 2 * n * (m - 2));
    PetscInt  qi  = fan ? (f - 2 * n * (m - 2)) / 2 : (f / 2) % n;
    for (int k = 0; k < 3; k++) {
      PetscInt w = md->f[3 * f + k];
      if (w >= R) md->fuv[3 * f + k] = nring + (w - R) * n + qi; /* a pole */
      else {
        PetscInt wi = w % n, gi = qi + (wi - qi + n + 1) % n - 1;
        md->fuv[3 * f + k] = gi * (m - 1) + w / n;
      }
    }
  }
  PetscFunctionReturn(0);
}

/* Kusner's Morin surface (Kusner 1987, "Conformal geometry and complete minimal surfaces"; the halfway model of the
   minimax sphere eversion, a Willmore sphere with W = 16 pi and a quadruple point): the minimal sphere with the four
   planar ends (p = 2)
     P(z) = Re[a(z) V(z)],  a = 1 / (z^2 - z^-2 + 2 sqrt3),  V = (i (z - 1/z), z + 1/z, (i/2) (z^2 + z^-2)),
   shifted by (0, 0, c) and inverted, X = c Q / |Q|^2 with Q = P + (0, 0, c) (c = 0.2: the most even vertex areas
   of c in {0.05 ... 1.5} on 32 x 16; both poles at (0, 0, 1), |X| <= 1; the ends meet at the origin). z is the
   stereographic coordinate of the round sphere's (u, v), z = tan(pi/4 + u/2) e^{iv}: this parametrisation is
   conformal, so the grid's discrete conformal class is the round UV sphere's up to O(h^2) (measured: the cross
   ratios differ by 0.108 rms on 16 x 8, 0.0285 on 32 x 16; Apery's grid by 0.9-1.0 on both). The symmetry-breaking
   perturbation is the ambient field eps (sin(2 pi y + 0.3), sin(2 pi z + 1), sin(2 pi x + 2)), smooth everywhere. */
static void MorinKusnerPoint(PetscReal u, PetscReal v, PetscReal eps, PetscReal *x)
{
  const PetscReal c = 0.2;
  PetscReal       q[3] = {0, 0, c}, q2;
  if (PetscAbsReal(u) < PETSC_PI / 2) { /* the poles z = 0, infinity: P = 0 */
    const PetscReal      r = PetscTanReal(PETSC_PI / 4 + u / 2);
    const double complex z = r * (PetscCosReal(v) + I * PetscSinReal(v)), zi = 1 / z;
    const double complex a = 1 / (z * z - zi * zi + 2 * PetscSqrtReal(3.0));
    q[0] += creal(a * I * (z - zi));
    q[1] += creal(a * (z + zi));
    q[2] += creal(a * 0.5 * I * (z * z + zi * zi));
  }
  q2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
  for (int k = 0; k < 3; k++) x[k] = c * q[k] / q2;
  {
    const PetscReal y[3] = {x[0], x[1], x[2]};
    x[0] += eps * PetscSinReal(2 * PETSC_PI * y[1] + 0.3);
    x[1] += eps * PetscSinReal(2 * PETSC_PI * y[2] + 1.0);
    x[2] += eps * PetscSinReal(2 * PETSC_PI * y[0] + 2.0);
  }
}

/* The round sphere's point of the grid's vertex v (the same rings and poles, radius 1). */
static void RoundGridPoint(PetscInt n, PetscInt m, PetscInt v, PetscReal *x)
{
  const PetscInt  R = n * (m - 1);
  const PetscReal u = v < R ? -PETSC_PI / 2 + (v / n + 1) * PETSC_PI / m : (v == R ? -PETSC_PI / 2 : PETSC_PI / 2);
  const PetscReal a = v < R ? 2 * PETSC_PI * (v % n) / n : 0;
  x[0] = PetscCosReal(u) * PetscCosReal(a), x[1] = PetscCosReal(u) * PetscSinReal(a), x[2] = PetscSinReal(u);
}

/* md->len: per face corner the length of the opposite edge on the round UV sphere of the same grid, the target
   class of -gen_morin_round_class (as -gen_spike_round_class). With Kusner's conformal parametrisation it is the
   class of the Morin surface itself up to O(h^2); with Apery's it is not (docs/triangle_fields.md, Fig. 15). */
static PetscErrorCode RoundGridLengths(PetscInt n, PetscInt m, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(3 * md->nf, &md->len));
  for (PetscInt f = 0; f < md->nf; f++)
    for (int k = 0; k < 3; k++) {
      PetscReal a[3], b[3];
      RoundGridPoint(n, m, md->f[3 * f + (k + 1) % 3], a);
      RoundGridPoint(n, m, md->f[3 * f + (k + 2) % 3], b);
      md->len[3 * f + k] = PetscSqrtReal(PetscSqr(a[0] - b[0]) + PetscSqr(a[1] - b[1]) + PetscSqr(a[2] - b[2]));
    }
  PetscFunctionReturn(0);
}

/* n around (v), m - 1 rings (u = -pi/2 + j pi/m, 0 < j < m) and the two poles: 2 + n(m - 1) vertices. */
PetscErrorCode CSMeshDataMorin(PetscInt n, PetscInt m, PetscReal eps, CSMorinKind kind, PetscBool round, CSMeshData *md)
{
  PetscInt R, *t;
  void (*point)(PetscReal, PetscReal, PetscReal, PetscReal *) = kind == CS_MORIN_KUSNER ? MorinKusnerPoint : MorinPoint;
  PetscFunctionBeginUser;
  PetscCheck(n >= 8 && m >= 4, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen morin needs -gen_n >= 8 and -gen_m >= 4, got %" PetscInt_FMT ", %" PetscInt_FMT, n, m);
  /* the sizes in floating point first: n (m - 1) overflowed PetscInt at 65536^2 ("-65534 vertices", issue 36) */
  PetscCall(CSMeshDataAlloc("-gen morin", (double)n * (double)(m - 1) + 2, 2 * (double)n * (m - 1), md));
  R = n * (m - 1);
  for (PetscInt j = 1; j < m; j++)
    for (PetscInt i = 0; i < n; i++) point(-PETSC_PI / 2 + j * PETSC_PI / m, 2 * PETSC_PI * i / n, eps, md->x + 3 * ((j - 1) * n + i));
  point(-PETSC_PI / 2, 0, eps, md->x + 3 * R);    /* south pole */
  point(PETSC_PI / 2, 0, eps, md->x + 3 * (R + 1)); /* north pole */
  t = md->f;
  for (PetscInt j = 1; j < m - 1; j++)
    for (PetscInt i = 0; i < n; i++) {
      PetscInt a = (j - 1) * n + i, b = (j - 1) * n + (i + 1) % n, c = j * n + (i + 1) % n, d = j * n + i;
      t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
      t += 6;
    }
  for (PetscInt i = 0; i < n; i++) { /* the fans, oriented as the quads */
    t[0] = R, t[1] = (i + 1) % n, t[2] = i;
    t[3] = R + 1, t[4] = (m - 2) * n + i, t[5] = (m - 2) * n + (i + 1) % n;
    t += 6;
  }
  if (round) PetscCall(RoundGridLengths(n, m, md));
  CSMeshDataOrientOutward(md); /* swaps md->len with the corners */
  PetscCall(MorinUVs(n, m, md));
  snprintf(md->name, sizeof(md->name), "morin(%s,n=%" PetscInt_FMT ",m=%" PetscInt_FMT ",perturb=%g%s)", CSMorinKinds[kind], n, m, (double)eps, round ? ",round class" : "");
  PetscFunctionReturn(0);
}
