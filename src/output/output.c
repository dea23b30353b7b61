/* Output options shared by every task, and the facts every summary carries. */
#include "cs_output.h"
#include "cs_geometry.h"
#include "cs_energy_bs.h"
#include "cs_util.h"

/* fail now rather than after hours of iterations: the checkpoint's folder takes a file, and the target is a
   regular file or absent (CSFile refuses to replace anything else) */
static PetscErrorCode CheckWritable(MPI_Comm comm, const char path[])
{
  CSFile      f;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(CSFileOpen(comm, (PetscBool)!rank, "-checkpoint", path, PETSC_TRUE, &f));
  PetscCall(CSFileDiscard(&f));
  PetscFunctionReturn(0);
}

/* Rank 0: every output file can be written, and no two name the same file (issue 36, items 13, 14): a run on a
   read-only target or a folder completed and then lost its result; -o s.obj -summary s.obj overwrote one with the
   other. PETSc's -history (opened at start-up, src/driver/startup.c) takes part in the comparison. */
static PetscErrorCode CheckOutputsLocal(const CSOutput *o)
{
  char        history[PETSC_MAX_PATH_LEN], ids[5][PETSC_MAX_PATH_LEN];
  PetscBool   has_history;
  const char *what[5] = {"-o", "-summary", "-history_csv", "-checkpoint", "-history"}, *path[5];
  PetscBool   has[5];
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-history", history, sizeof(history), &has_history));
  path[0] = o->out, path[1] = o->summary, path[2] = o->history, path[3] = o->checkpoint, path[4] = history;
  has[0] = o->has_out, has[1] = o->has_summary, has[2] = o->has_history, has[3] = o->has_checkpoint, has[4] = (PetscBool)(has_history && history[0]);
  for (int i = 0; i < 5; i++) {
    if (!has[i]) continue;
    if (i < 3) PetscCall(CSFileCheckTarget(what[i], path[i])); /* the checkpoint: CheckWritable; -history: at start-up */
    PetscCall(CSFileIdentity(path[i], ids[i], sizeof(ids[i])));
    for (int j = 0; j < i; j++) {
      char name[PETSC_MAX_PATH_LEN];
      if (!has[j] || strcmp(ids[i], ids[j])) continue;
      PetscCall(CSPathSanitize(path[i], name, sizeof(name)));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "%s %s: the same file as %s (one output would overwrite the other)", what[i], name, what[j]);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputFromOptions(MPI_Comm comm, CSOutput *o)
{
  const char *const exts[] = {"obj", "ply", NULL};
  PetscFunctionBeginUser;
  PetscCall(CSOutputFromOptionsFormats(comm, exts, "the final mesh is written as .obj or .ply", o));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputFromOptionsFormats(MPI_Comm comm, const char *const exts[], const char what[], CSOutput *o)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(o, sizeof(*o)));
  PetscCall(PetscTime(&o->t0));
  PetscOptionsBegin(comm, NULL, "confsurf output", NULL);
  PetscCall(CSOptionsString("-o", "Final mesh (.obj or .ply)", NULL, o->out, o->out, sizeof(o->out), &o->has_out));
  PetscCall(CSOptionsString("-viewer_dir", "Directory for the ParaView series (series.pvd)", NULL, o->viewer_dir, o->viewer_dir, sizeof(o->viewer_dir), &o->has_viewer));
  PetscCall(CSOptionsString("-summary", "JSON summary file", NULL, o->summary, o->summary, sizeof(o->summary), &o->has_summary));
  PetscCall(CSOptionsString("-history_csv", "Iterative tasks: per-iteration CSV history (columns in the header line)", NULL, o->history, o->history, sizeof(o->history), &o->has_history));
  PetscCall(CSOptionsString("-reference", "Mesh with the same connectivity for the quasi-conformal error", NULL, o->reference, o->reference, sizeof(o->reference), &o->has_reference));
  o->checkpoint_every = 10;
  PetscCall(CSOptionsString("-checkpoint", "Iterative tasks: write a checkpoint (positions and loop state) to this file", NULL, o->checkpoint, o->checkpoint, sizeof(o->checkpoint), &o->has_checkpoint));
  PetscCall(CSOptionsInt("-checkpoint_every", "Write the checkpoint every this many accepted iterations (and always at the end)", NULL, o->checkpoint_every, &o->checkpoint_every, NULL));
  PetscCall(CSOptionsString("-resume", "Iterative tasks: start from this checkpoint (the mesh still comes from -mesh/-gen, for the connectivity)", NULL, o->resume, o->resume, sizeof(o->resume), &o->has_resume));
  PetscOptionsEnd();
  PetscCheck(o->checkpoint_every >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-checkpoint_every %" PetscInt_FMT ": must be >= 1", o->checkpoint_every);
  if (o->has_out) {
    char      ext[16];
    PetscBool ok = PETSC_FALSE;
    PetscCall(CSPathExtension(o->out, ext, sizeof(ext)));
    for (PetscInt k = 0; exts[k]; k++) ok = (PetscBool)(ok || !strcmp(ext, exts[k]));
    PetscCheck(ok, comm, PETSC_ERR_ARG_WRONG, "-o %s: %s", o->out, what);
  }
  if (o->has_checkpoint) PetscCall(CheckWritable(comm, o->checkpoint));
  if (o->has_viewer) { /* read (and checked) now, as every option before the work; the viewer reads them again */
    CSViewerFormat format;
    PetscBool      single;
    PetscCall(CSViewerFormatFromOptions(comm, NULL, &format, &single));
  }
  CSRootCall(comm, CheckOutputsLocal(o));
  PetscCall(CSJSONCreate(comm, &o->json));
  { /* the threads of rank 0 (src/util/threads.c); "ranks" comes with CSOutputFinish */
    PetscInt omp, blas;
    PetscCall(CSGetThreadCounts(&omp, &blas));
    PetscCall(CSJSONAddInt(o->json, "omp_threads", omp));
    PetscCall(CSJSONAddInt(o->json, "blas_threads", blas));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputViewerEvery(MPI_Comm comm, const char prefix[], const char title[], const char help[], PetscBool zero_final, PetscInt *every)
{
  PetscFunctionBeginUser;
  *every = zero_final ? 0 : 1;
  PetscOptionsBegin(comm, prefix, title, NULL);
  PetscCall(CSOptionsInt("-viewer_every", help, NULL, *every, every, NULL));
  PetscOptionsEnd();
  if (zero_final) PetscCheck(*every >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sviewer_every %" PetscInt_FMT ": use 0 (the final state only) or a positive count", prefix, *every);
  else PetscCheck(*every >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sviewer_every %" PetscInt_FMT ": must be >= 1", prefix, *every);
  PetscFunctionReturn(0);
}

/* With texture coordinates: texture_q_mean, texture_q_max of x and of the input (keys *_input), CSGeometryTextureQ */
static PetscErrorCode AddTextureQ(CSOutput *o, CSMesh mesh, Vec x, Vec xin)
{
  PetscReal q[4];
  PetscFunctionBeginUser;
  PetscCall(CSGeometryTextureQ(mesh, x, NULL, &q[0], &q[1]));
  PetscCall(CSGeometryTextureQ(mesh, xin, NULL, &q[2], &q[3]));
  PetscCall(CSJSONAddReal(o->json, "texture_q_mean", q[0]));
  PetscCall(CSJSONAddReal(o->json, "texture_q_max", q[1]));
  PetscCall(CSJSONAddReal(o->json, "texture_q_mean_input", q[2]));
  PetscCall(CSJSONAddReal(o->json, "texture_q_max_input", q[3]));
  PetscCall(PetscPrintf(mesh->comm, "texture distortion (UV -> surface): texture_q_mean=%.12g texture_q_max=%.12g (input %.12g, %.12g)\n", (double)q[0], (double)q[1], (double)q[2], (double)q[3]));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputAddMeshFacts(CSOutput *o, CSMesh mesh, Vec x, Vec xref)
{
  PetscReal area, volume, W;
  CSEnergy  will;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryAreaVolume(mesh, x, &area, &volume));
  PetscCall(CSEnergyCreateWillmore(mesh, &will));
  PetscCall(CSEnergyValue(will, x, &W));
  PetscCall(CSEnergyDestroy(&will));
  PetscCall(CSJSONAddString(o->json, "mesh", mesh->name));
  PetscCall(CSJSONAddInt(o->json, "vertices", mesh->Nv));
  PetscCall(CSJSONAddInt(o->json, "edges", mesh->Ne));
  PetscCall(CSJSONAddInt(o->json, "faces", mesh->Nf));
  PetscCall(CSJSONAddInt(o->json, "genus", mesh->topo.genus));
  PetscCall(CSJSONAddInt(o->json, "boundary_loops", mesh->topo.boundary_loops));
  PetscCall(CSJSONAddInt(o->json, "components", mesh->topo.components));
  PetscCall(CSJSONAddInt(o->json, "euler_characteristic", mesh->Nv - mesh->Ne + mesh->Nf));
  PetscCall(CSJSONAddReal(o->json, "area", area));
  PetscCall(CSJSONAddReal(o->json, "volume", volume));
  PetscCall(CSJSONAddReal(o->json, "willmore", W));
  PetscCall(PetscPrintf(mesh->comm, "mesh %s: V=%" PetscInt_FMT " E=%" PetscInt_FMT " F=%" PetscInt_FMT " genus=%" PetscInt_FMT " boundary_loops=%" PetscInt_FMT " components=%" PetscInt_FMT "\n", mesh->name, mesh->Nv, mesh->Ne, mesh->Nf, mesh->topo.genus, mesh->topo.boundary_loops, mesh->topo.components));
  PetscCall(PetscPrintf(mesh->comm, "area=%.12g volume=%.12g willmore=%.12g (4pi=%.12g)\n", (double)area, (double)volume, (double)W, (double)(4 * PETSC_PI)));
  if (xref || o->has_reference) {
    Vec       r = xref;
    PetscReal qmean, qmax;
    if (!r) PetscCall(CSMeshLoadCompatiblePositions(mesh, "-reference", o->reference, &r));
    PetscCall(CSGeometryQuasiConformal(mesh, r, x, NULL, &qmean, &qmax));
    PetscCall(CSJSONAddReal(o->json, "q_mean", qmean));
    PetscCall(CSJSONAddReal(o->json, "q_max", qmax));
    PetscCall(PetscPrintf(mesh->comm, "quasi-conformal error: q_mean=%.12g q_max=%.12g\n", (double)qmean, (double)qmax));
    if (!xref) PetscCall(VecDestroy(&r));
  }
  if (mesh->faceUV) PetscCall(AddTextureQ(o, mesh, x, xref ? xref : mesh->x));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputAddTriangleQuality(CSOutput *o, CSMesh mesh, Vec x)
{
  CSTriangleQuality q;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryTriangleQuality(mesh, x, &q));
  PetscCall(CSJSONAddReal(o->json, "quality_min_angle_deg", q.min_angle_deg));
  PetscCall(CSJSONAddReal(o->json, "quality_obtuse_share", q.obtuse_share));
  PetscCall(CSJSONAddReal(o->json, "quality_nondelaunay_share", q.nondelaunay_share));
  PetscCall(CSJSONAddReal(o->json, "quality_edge_ratio", q.edge_ratio));
  PetscCall(CSJSONAddReal(o->json, "quality_face_edge_ratio_max", q.face_edge_ratio));
  PetscCall(PetscPrintf(mesh->comm, "triangle quality: min angle %.4g deg, obtuse faces %.2f %%, non-Delaunay edges %.2f %% of %" PetscInt_FMT " interior, edge length max/min %.4g (worst face %.4g)\n", (double)q.min_angle_deg, (double)(100 * q.obtuse_share), (double)(100 * q.nondelaunay_share), q.interior_edges, (double)q.edge_ratio, (double)q.face_edge_ratio));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputAddWillmoreBS(CSOutput *o, CSMesh mesh, Vec x)
{
  CSEnergy  bs;
  PetscReal Wbs;
  PetscFunctionBeginUser;
  /* the circle-angle energy of bobenko-schroeder2005 (boundary vertices excluded, as with -bs_boundary fixed) */
  PetscCall(CSEnergyCreateWillmoreBS(mesh, CS_BS_BOUNDARY_FIXED, 1e-6, &bs));
  PetscCall(CSEnergyValue(bs, x, &Wbs));
  PetscCall(CSEnergyDestroy(&bs));
  PetscCall(CSJSONAddReal(o->json, "willmore_bs", Wbs));
  PetscCall(PetscPrintf(mesh->comm, "willmore_bs=%.12g (bobenko-schroeder2005)\n", (double)Wbs));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputAddRunFacts(CSOutput *o, MPI_Comm comm)
{
  PetscLogDouble t1;
  PetscMPIInt    size;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t1));
  PetscCall(CSJSONAddReal(o->json, "seconds", (PetscReal)(t1 - o->t0)));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(CSJSONAddInt(o->json, "ranks", (PetscInt)size));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputWriteSummary(CSOutput *o, MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCall(CSOutputCaptureSummary(o->json, comm)); /* a caller of the library (src/api) takes it in memory */
  if (!o->has_summary) PetscFunctionReturn(0);
  PetscCall(CSJSONWrite(o->json, o->summary));
  PetscCall(PetscPrintf(comm, "wrote summary %s\n", o->summary));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputFinish(CSOutput *o, CSMesh mesh, Vec x)
{
  PetscFunctionBeginUser;
  PetscCall(CSOutputAddRunFacts(o, mesh->comm));
  if ((o->has_checkpoint || o->has_resume) && !o->checkpoint_used) PetscCall(PetscPrintf(mesh->comm, "WARNING: -checkpoint/-resume ignored: this task does not use checkpoints\n"));
  if (o->has_out) {
    PetscCall(CSMeshWrite(mesh, x, o->out));
    PetscCall(PetscPrintf(mesh->comm, "wrote mesh %s\n", o->out));
  }
  PetscCall(CSOutputCaptureMesh(mesh, x));
  PetscCall(CSOutputWriteSummary(o, mesh->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputDestroy(CSOutput *o)
{
  PetscFunctionBeginUser;
  PetscCall(CSJSONDestroy(&o->json));
  PetscFunctionReturn(0);
}

/* Two numbers that identify the start positions x0 (dmV3 layout) on any number of ranks (up to round-off): |x0|
   and sum_n w_n (x_n + sqrt2 y_n + sqrt3 z_n) over the vertices n in natural (file) order with fixed weights
   w_n = 1 + (7919 n mod 1009) / 1009, summed on rank 0: a rotated or renumbered copy of the input changes it
   (the plain sum did not see a rotation about the centroid; issue 36). */
static PetscErrorCode Fingerprint(CSMesh mesh, Vec x0, PetscReal fp[2])
{
  Vec                nat;
  PetscInt           n;
  const PetscScalar *a;
  PetscReal          s = 0;
  PetscFunctionBeginUser;
  fp[0] = fp[1] = 0;
  if (!x0) PetscFunctionReturn(0);
  PetscCall(VecNorm(x0, NORM_2, &fp[0]));
  PetscCall(CSMeshGather(&mesh->natV3, x0, &nat));
  PetscCall(VecGetLocalSize(nat, &n));
  PetscCall(VecGetArrayRead(nat, &a));
  for (PetscInt v = 0; v < n / 3; v++) {
    PetscReal w = 1 + (PetscReal)((7919 * (long long)v) % 1009) / 1009;
    s += w * (PetscRealPart(a[3 * v]) + PETSC_SQRT2 * PetscRealPart(a[3 * v + 1]) + PetscSqrtReal(3.0) * PetscRealPart(a[3 * v + 2]));
  }
  PetscCall(VecRestoreArrayRead(nat, &a));
  PetscCallMPI(MPI_Bcast(&s, 1, MPIU_REAL, 0, mesh->comm));
  fp[1] = s;
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputResume(CSOutput *o, CSMesh mesh, Vec x0, PetscInt *it, PetscInt nreal, PetscReal reals[], const CSCheckpointFields *v, PetscBool *resumed)
{
  PetscReal     *buf, fp[2];
  PetscBool      same = PETSC_TRUE;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  o->checkpoint_used = PETSC_TRUE;
  *resumed           = PETSC_FALSE;
  if (!o->has_resume) PetscFunctionReturn(0);
  /* the fingerprint of the input goes first: [fp0, fp1, task scalars] */
  PetscCall(PetscMalloc1(nreal + 2, &buf));
  ierr = CSCheckpointRead(mesh, o->resume, it, nreal + 2, buf, v);
  if (ierr) PetscCall(PetscFree(buf)); /* no leak on the error path */
  PetscCall(ierr);
  PetscCall(Fingerprint(mesh, x0, fp));
  for (int i = 0; i < 2; i++) same = (PetscBool)(same && PetscAbsReal(buf[i] - fp[i]) <= 1e-10 * PetscMax(1.0, PetscAbsReal(fp[i])));
  if (same) PetscCall(PetscArraycpy(reals, buf + 2, nreal));
  PetscCall(PetscFree(buf));
  PetscCheck(same, mesh->comm, PETSC_ERR_ARG_INCOMP, "-resume %s: the checkpoint was written by a run from other input positions (another -mesh/-gen, or options that change the input such as -flow_init_*)", o->resume);
  o->resumed = PETSC_TRUE;
  *resumed   = PETSC_TRUE;
  PetscCall(PetscPrintf(mesh->comm, "resumed from checkpoint %s at iteration %" PetscInt_FMT "\n", o->resume, *it));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputCheckpoint(CSOutput *o, CSMesh mesh, Vec x0, PetscInt it, PetscBool force, PetscInt nreal, const PetscReal reals[], const CSCheckpointFields *v)
{
  PetscReal *buf;
  PetscFunctionBeginUser;
  o->checkpoint_used = PETSC_TRUE;
  if (!o->has_checkpoint || (!force && it % o->checkpoint_every)) PetscFunctionReturn(0);
  PetscCall(PetscMalloc1(nreal + 2, &buf));
  PetscCall(Fingerprint(mesh, x0, buf));
  PetscCall(PetscArraycpy(buf + 2, reals, nreal));
  PetscCall(CSCheckpointWrite(mesh, o->checkpoint, it, nreal + 2, buf, v));
  PetscCall(PetscFree(buf));
  PetscCall(PetscPrintf(mesh->comm, "wrote checkpoint %s at iteration %" PetscInt_FMT "\n", o->checkpoint, it));
  PetscFunctionReturn(0);
}

/* Rank 0: the rows of the existing history file (same header) whose first column is below next. */
static PetscErrorCode ReadHistoryRows(const char path[], const char header[], PetscInt ncol, PetscInt next, PetscInt *nrows, PetscReal **rows)
{
  FILE    *fp = fopen(path, "r");
  char     line[4096];
  PetscInt cap = 0;
  PetscFunctionBeginUser;
  *nrows = 0;
  *rows  = NULL;
  if (!fp) PetscFunctionReturn(0);
  if (!fgets(line, sizeof(line), fp) || strncmp(line, header, strlen(header)) || (line[strlen(header)] != '\n' && line[strlen(header)] != 0)) {
    fclose(fp); /* another task's history: start afresh */
    PetscFunctionReturn(0);
  }
  while (fgets(line, sizeof(line), fp)) {
    char     *p = line, *end;
    PetscReal v[64];
    PetscInt  n = 0;
    for (; n < ncol && n < 64; n++, p = end + (*end == ',')) {
      v[n] = (PetscReal)strtod(p, &end);
      if (end == p) break;
    }
    if (n != ncol || v[0] >= (PetscReal)next) continue; /* not a row, or recomputed by the resumed run */
    if (*nrows == cap) {
      cap = 2 * cap + 64;
      PetscCall(PetscRealloc(sizeof(PetscReal) * cap * ncol, rows));
    }
    PetscCall(PetscArraycpy(*rows + *nrows * ncol, v, ncol));
    (*nrows)++;
  }
  fclose(fp);
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputHistoryCreate(CSOutput *o, MPI_Comm comm, const char header[], PetscInt next, CSHistory *h)
{
  PetscInt    ncol = 1, nrows = 0;
  PetscReal  *rows = NULL;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  *h = NULL;
  if (!o->has_history && !CSHistoryCaptureActive()) PetscFunctionReturn(0);
  for (const char *c = header; *c; c++) ncol += (*c == ',');
  PetscCheck(ncol <= 64, comm, PETSC_ERR_SUP, "history with %" PetscInt_FMT " columns: at most 64", ncol);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (o->resumed && !rank) PetscCall(ReadHistoryRows(o->history, header, ncol, next, &nrows, &rows));
  PetscCallMPI(MPI_Bcast(&nrows, 1, MPIU_INT, 0, comm)); /* appending is collective; the rows are read on rank 0 */
  PetscCall(CSHistoryCreate(comm, o->has_history ? o->history : NULL, header, h)); /* NULL: the capture only (src/api) */
  for (PetscInt i = 0; i < nrows; i++) PetscCall(CSHistoryAppend(*h, ncol, rows ? rows + i * ncol : NULL));
  PetscCall(PetscFree(rows));
  PetscFunctionReturn(0);
}

/* A solver error during a run (issue 18, item 11: a CHOLMOD failure at step 1 left no -o and no -summary): the
   state of the last accepted iteration it (x: a flow changes its state only when it accepts a step) is written to
   -o and -summary with stop_reason "error" and the message of ierr, returned in msg for the caller to raise after
   its clean-up. Collective. */
PetscErrorCode CSOutputSaveAfterError(CSOutput *o, CSMesh mesh, Vec x, PetscInt it, PetscErrorCode ierr, char msg[], size_t len)
{
  const char *text;
  char       *specific = NULL;
  PetscFunctionBeginUser;
  PetscCall(PetscErrorMessage(ierr, &text, &specific));
  PetscCall(PetscStrncpy(msg, specific ? specific : (text ? text : "unknown error"), len));
  PetscCall(PetscPrintf(mesh->comm, "flow: failed after iteration %" PetscInt_FMT ": %s\nflow: the last accepted state goes to %s\n", it, msg, o->has_out ? "-o and -summary" : "-summary"));
  PetscCall(CSJSONAddInt(o->json, "iterations", it));
  PetscCall(CSJSONAddBool(o->json, "converged", PETSC_FALSE));
  PetscCall(CSJSONAddString(o->json, "stop_reason", "error"));
  PetscCall(CSJSONAddString(o->json, "error", msg));
  PetscCall(CSOutputFinish(o, mesh, x));
  PetscFunctionReturn(0);
}
