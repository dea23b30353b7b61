static const char help[] = "Benchmark of the triangle-field Poisson reconstruction (soliman2021 Algorithm 2, last line): mesh from\n"
                           "-mesh/-gen, omega_k = df + 0.01 k-th random field; -bench_repeat reconstructions one-shot\n"
                           "(CSTriangleFieldReconstruct: operators, KSP, symbolic and numeric factorisation every call) and with\n"
                           "the kept CSTriangleFieldReconstruction (operators refilled in place, numeric factorisation only), in\n"
                           "-bench_rounds alternating rounds; prints CPU and wall milliseconds per call (medians over the rounds)\n"
                           "and the largest difference of the two answers.\n";
#include <time.h>
#include "cs_operators_lens.h"
#include "cs_package.h"

static int CmpDouble(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* one round of repeat reconstructions (kept: through R) of the fields om[k]; CPU and wall seconds per call */
static PetscErrorCode Round(CSMesh m, DM dmH1, DM dmH3, CSTriangleFieldReconstruction R, PetscInt repeat, Vec om[], Vec x, double *cpu, double *wall)
{
  clock_t        c0;
  PetscLogDouble t0, t1;
  PetscFunctionBeginUser;
  c0 = clock();
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < repeat; k++) {
    if (R) PetscCall(CSTriangleFieldReconstructionSolve(R, om[k], m->x, x));
    else PetscCall(CSTriangleFieldReconstruct(m, dmH1, dmH3, om[k], m->x, x));
  }
  PetscCall(PetscTime(&t1));
  *cpu  = (double)(clock() - c0) / CLOCKS_PER_SEC / repeat;
  *wall = (t1 - t0) / repeat;
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  CSMesh                        m;
  DM                            dmH1, dmH3;
  CSTriangleFieldReconstruction R;
  PetscRandom                   rnd;
  Vec                           om[64], dir, x, y;
  PetscInt                      repeat = 20, rounds = 3;
  double                        c[2][16], w[2][16];
  PetscReal                     d;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(CSInitializePackage());
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "Reconstruction benchmark", NULL);
  PetscCall(PetscOptionsInt("-bench_repeat", "Reconstructions per round (<= 64)", NULL, repeat, &repeat, NULL));
  PetscCall(PetscOptionsInt("-bench_rounds", "Alternating rounds (<= 16)", NULL, rounds, &rounds, NULL));
  PetscOptionsEnd();
  PetscCheck(repeat >= 1 && repeat <= 64 && rounds >= 1 && rounds <= 16, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-bench_repeat 1..64, -bench_rounds 1..16");
  PetscCall(CSMeshCreateFromOptions(PETSC_COMM_WORLD, NULL, &m));
  PetscCall(CSLensCreateHalfedgeDM(m, 1, &dmH1));
  PetscCall(CSLensCreateHalfedgeDM(m, 3, &dmH3));
  PetscCall(DMCreateGlobalVector(dmH3, &dir));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1, 1));
  for (PetscInt k = 0; k < repeat; k++) {
    PetscCall(VecDuplicate(dir, &om[k]));
    PetscCall(CSTriangleFieldFromPositions(m, m->x, dmH3, om[k]));
    PetscCall(VecSetRandom(dir, rnd));
    PetscCall(VecAXPY(om[k], 0.01, dir));
  }
  PetscCall(VecDuplicate(m->x, &x));
  PetscCall(VecDuplicate(m->x, &y));
  PetscCall(CSTriangleFieldReconstructionCreate(m, dmH1, dmH3, &R));
  for (PetscInt r = 0; r < rounds; r++) {
    PetscCall(Round(m, dmH1, dmH3, NULL, repeat, om, y, &c[0][r], &w[0][r]));
    PetscCall(Round(m, dmH1, dmH3, R, repeat, om, x, &c[1][r], &w[1][r]));
  }
  PetscCall(VecAXPY(y, -1.0, x)); /* both hold the reconstruction of om[repeat - 1] */
  PetscCall(VecNorm(y, NORM_INFINITY, &d));
  for (PetscInt i = 0; i < 2; i++) {
    qsort(c[i], rounds, sizeof(double), CmpDouble);
    qsort(w[i], rounds, sizeof(double), CmpDouble);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "faces %" PetscInt_FMT " one-shot cpu_ms %.3f wall_ms %.3f | kept cpu_ms %.3f wall_ms %.3f | max |diff| %.1e\n", m->Nf, 1e3 * c[0][rounds / 2], 1e3 * w[0][rounds / 2], 1e3 * c[1][rounds / 2], 1e3 * w[1][rounds / 2], (double)d));
  PetscCall(CSTriangleFieldReconstructionDestroy(&R));
  for (PetscInt k = 0; k < repeat; k++) PetscCall(VecDestroy(&om[k]));
  PetscCall(VecDestroy(&dir));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(DMDestroy(&dmH1));
  PetscCall(DMDestroy(&dmH3));
  PetscCall(CSMeshDestroy(&m));
  PetscCall(PetscFinalize());
  return 0;
}
