/* The mesh source from the options database: a file (-mesh) or a generator (-gen). Options are read on every
   rank; the data is made and validated on rank 0 only, and an error there is raised on every rank. */
#include "cs_meshdata.h"
#include "cs_util.h"

typedef enum {
  GEN_ICOSPHERE,
  GEN_TORUS,
  GEN_FLATTORUS,
  GEN_CYLINDER,
  GEN_DISK,
  GEN_LATTICE,
  GEN_SPIKY,
  GEN_MORIN
} GenType;
static const char *const GenNames[] = {"icosphere", "torus", "flattorus", "cylinder", "disk", "lattice", "spiky", "morin"};

typedef struct {
  char      path[PETSC_MAX_PATH_LEN];
  PetscBool file;
  PetscBool arrays; /* the mesh of CSMeshDataSetArraySource (the library's callers, src/api) */
  GenType   gen;
  PetscInt  level, n, m, rings;
  PetscReal radius, R, r, tau_re, tau_im, height, tau[2]; /* tau: -gen lattice */
  PetscReal spike_h, spike_w, morin_eps;                 /* -gen spiky, -gen morin */
  PetscBool spike_round;                                  /* -gen_spike_round_class */
  CSMorinKind morin_kind;                                 /* -gen_morin_kind */
  PetscBool   morin_round;                                /* -gen_morin_round_class */
  PetscBool project;
  PetscInt  refine;      /* -mesh_refine: 1-to-4 splits after validation (meshdata_refine.c) */
  PetscBool refine_loop; /* -mesh_refine_type loop (default) or midpoint */
  PetscInt  remesh_faces, remesh_iterations; /* -mesh_remesh N (0: off), -mesh_remesh_iterations (meshdata_remesh.c) */
  PetscReal remesh_h;                        /* -mesh_remesh_edge_length (0: off) */
  char      lengths[PETSC_MAX_PATH_LEN]; /* -mesh_lengths FILE: an intrinsic metric (the target conformal class) */
  char      crossratios[PETSC_MAX_PATH_LEN]; /* -mesh_cross_ratios FILE: the target class as cross ratios */
  PetscReal crtol;                            /* -mesh_cross_ratios_tol */
} MeshSource;
static const char *const RefineNames[] = {"midpoint", "loop"};

/* The arrays of a caller of the library (src/api: the Python interface's V, F), on rank 0, while set. */
static const CSMeshData *ArraySource = NULL;

PetscErrorCode CSMeshDataSetArraySource(const CSMeshData *md)
{
  PetscFunctionBeginUser;
  ArraySource = md;
  PetscFunctionReturn(0);
}

/* Rank 0, under PetscReturnErrorHandler: on failure nothing stays allocated in md. */
static PetscErrorCode MeshSourceLoad(const MeshSource *src, CSMeshData *md, CSTopology *topo)
{
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  if (src->arrays) PetscCall(CSMeshDataDuplicate(ArraySource, md)); /* validated below as a file is */
  else if (src->file) PetscCall(CSMeshDataRead(src->path, md));
  else {
    switch (src->gen) {
    case GEN_ICOSPHERE: PetscCall(CSMeshDataIcosphere(src->level, src->radius, src->project, md)); break;
    case GEN_TORUS: PetscCall(CSMeshDataTorus(src->R, src->r, src->n, src->m, md)); break;
    case GEN_FLATTORUS: PetscCall(CSMeshDataFlatTorus(src->tau_re, src->tau_im, src->n, src->m, md)); break;
    case GEN_CYLINDER: PetscCall(CSMeshDataCylinder(src->radius, src->height, src->n, src->m, md)); break;
    case GEN_DISK: PetscCall(CSMeshDataDisk(src->radius, src->rings, md)); break;
    case GEN_LATTICE: PetscCall(CSMeshDataLattice(src->tau[0], src->tau[1], src->n, src->m, md)); break;
    case GEN_SPIKY: PetscCall(CSMeshDataSpikySphere(src->level, src->spike_h, src->spike_w, src->spike_round, md)); break;
    case GEN_MORIN: PetscCall(CSMeshDataMorin(src->n, src->m, src->morin_eps, src->morin_kind, src->morin_round, md)); break;
    }
  }
  if (md->fuv && !src->file && !src->arrays && (src->remesh_faces || src->remesh_h > 0)) {
    /* a generator's UVs are its parameters, not the user's texture: -mesh_remesh (which has no UV transfer and
       refuses a file's UVs, meshdata_remesh.c) drops them with a note rather than refusing -gen torus -mesh_remesh */
    PetscCall(PetscInfo(NULL, "%s: -mesh_remesh drops the generator's %" PetscInt_FMT " texture coordinates\n", md->name, md->nuv));
    PetscCall(PetscFree(md->uv));
    PetscCall(PetscFree(md->fuv));
    md->nuv = 0;
  }
  ierr = CSMeshDataValidate(md, topo);
  if (!ierr && (src->remesh_faces || src->remesh_h > 0)) ierr = CSMeshDataRemesh(md, topo, src->remesh_faces, src->remesh_h, src->remesh_iterations);
  if (!ierr && src->lengths[0]) ierr = CSMeshDataReadLengths("-mesh_lengths", src->lengths, md);
  if (!ierr && src->crossratios[0]) ierr = CSMeshDataReadCrossRatios("-mesh_cross_ratios", src->crossratios, src->crtol, md);
  if (!ierr && src->refine) {
    ierr = CSMeshDataRefine(md, src->refine, src->refine_loop);
    if (!ierr) ierr = CSMeshDataValidate(md, topo);
  }
  if (ierr) { /* keep the validation message (CSSyncError reads it) and free the data */
    PetscCall(CSMeshDataDestroy(md));
    return ierr;
  }
  PetscFunctionReturn(0);
}

/* -mesh_remesh N | -mesh_remesh_edge_length h, -mesh_remesh_iterations k: read and checked on every rank (the
   readers refuse 'abc', 2.5 for a count and values PetscInt cannot hold, naming the option; the table the ranges) */
static PetscErrorCode RemeshOptions(MPI_Comm comm, const char prefix[], MeshSource *src)
{
  PetscInt  n = 0, k = 5; /* 5 iterations: see docs/remeshing.md (min angle on cow/triceratops by k) */
  PetscReal h = 0;
  PetscBool setn = PETSC_FALSE, seth = PETSC_FALSE;
  char      want[128];
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix, "Isotropic remeshing (CGAL) of the input", NULL);
  PetscCall(CSOptionsInt("-mesh_remesh", "Remesh the input isotropically to about N faces (CGAL isotropic_remeshing, before -mesh_refine; docs/remeshing.md)", "CSMeshDataRemesh", n, &n, &setn));
  PetscCall(CSOptionsReal("-mesh_remesh_edge_length", "Remesh the input isotropically to this target edge length (instead of -mesh_remesh N)", "CSMeshDataRemesh", h, &h, &seth));
  PetscCall(CSOptionsInt("-mesh_remesh_iterations", "Iterations of the isotropic remeshing (split, collapse, flip, relax, project)", "CSMeshDataRemesh", k, &k, NULL));
  PetscOptionsEnd();
  PetscCall(PetscSNPrintf(want, sizeof(want), "want an integer face count in [%d, %.0e]", CS_REMESH_MIN_FACES, (double)CS_REMESH_MAX_FACES));
  {
    const CSOptionCheck checks[] = {
      {"mesh_remesh", (PetscReal)n, !setn || (n >= CS_REMESH_MIN_FACES && n <= CS_REMESH_MAX_FACES), want},
      {"mesh_remesh_edge_length", h, !seth || (h > 0 && h <= PETSC_MAX_REAL), "want a finite length > 0"},
      {"mesh_remesh_iterations", (PetscReal)k, k >= 1 && k <= 100, "want an integer in [1, 100]"},
    };
    PetscCall(CSCheckOptionValues(comm, prefix, sizeof(checks) / sizeof(checks[0]), checks));
  }
  PetscCheck(!(setn && seth), comm, PETSC_ERR_ARG_INCOMP, "-%smesh_remesh %" PetscInt_FMT " with -%smesh_remesh_edge_length %g: give one of them", prefix ? prefix : "", n, prefix ? prefix : "", (double)h);
  src->remesh_faces      = setn ? n : 0;
  src->remesh_h          = seth ? h : 0;
  src->remesh_iterations = k;
  PetscFunctionReturn(0);
}

/* Every generator real in a finite range, with its reason (issue 36, item 5: nan or 1e300 was written as a mesh of
   nan coordinates with exit 0). Lengths in [1e-6, 1e6]: the mesh checks and the flows' tolerances are set for
   sizes near 1 (a coordinate beyond 1e100 is refused anyway). Checked on every run, whichever -gen is chosen. */
static PetscErrorCode CheckGeneratorValues(MPI_Comm comm, const char pre[], const MeshSource *s)
{
  const CSOptionCheck checks[] = {
    {"gen_radius", s->radius, s->radius >= 1e-6 && s->radius <= 1e6, "must lie in [1e-6, 1e6] (a length)"},
    {"gen_torus_R", s->R, s->R >= 1e-6 && s->R <= 1e6, "must lie in [1e-6, 1e6] (a length)"},
    {"gen_tube_r", s->r, s->r >= 1e-6 && s->r <= 1e6, "must lie in [1e-6, 1e6] (a length)"},
    {"gen_height", s->height, s->height >= 1e-6 && s->height <= 1e6, "must lie in [1e-6, 1e6] (a length)"},
    {"gen_tau_re", s->tau_re, PetscAbsReal(s->tau_re) <= 1e3, "must lie in [-1e3, 1e3]"},
    {"gen_tau_im", s->tau_im, s->tau_im >= 1e-3 && s->tau_im <= 1e3, "must lie in [1e-3, 1e3] (the torus' aspect ratio)"},
    /* tau and tau + n are the same class; |tau| beyond 1e3 is a lattice no -gen_n resolves */
    {"gen_tau (RE)", s->tau[0], PetscAbsReal(s->tau[0]) <= 1e3, "must lie in [-1e3, 1e3]"},
    {"gen_tau (IM)", s->tau[1], PetscAbsReal(s->tau[1]) <= 1e3, "must lie in [-1e3, 1e3] (Im tau > 0 is checked by the lattice)"},
    {"gen_spike_height", s->spike_h, PetscAbsReal(s->spike_h) <= 1e3, "must lie in (-1, 1e3] (the spikes' height, radius 1)"},
    {"gen_spike_width", s->spike_w, PetscAbsReal(s->spike_w) <= 1, "must lie in (0, 0.55) radians"},
    {"gen_morin_perturb", s->morin_eps, PetscAbsReal(s->morin_eps) <= 1, "must lie in [-1, 1] (a perturbation of a unit-size surface)"},
    {"mesh_cross_ratios_tol", s->crtol, s->crtol > 0 && s->crtol <= 1e3, "must lie in (0, 1e3]"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(comm, pre, sizeof(checks) / sizeof(checks[0]), checks));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataFromOptions(MPI_Comm comm, const char prefix[], CSMeshData *md, CSTopology *topo)
{
  MeshSource  src;
  PetscBool   genset = PETSC_FALSE, tauset = PETSC_FALSE;
  PetscInt    ntau   = 2;
  PetscInt    gen    = GEN_ICOSPHERE, rtype = 1;
  const char *pre    = prefix ? prefix : "";

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(md, sizeof(*md)));
  PetscCall(PetscMemzero(topo, sizeof(*topo)));
  PetscCall(PetscMemzero(&src, sizeof(src)));
  src.level   = 3;
  src.crtol   = 1e-8;
  src.radius  = 1;
  src.project = PETSC_TRUE;
  src.R       = PetscSqrtReal(2.0); /* with r = 1: the Clifford torus' conformal class (square) */
  src.r       = 1;
  src.n       = 32;
  src.m       = 16;
  src.tau_re  = 0;
  src.tau_im  = 1;
  src.tau[0]  = 0;
  src.tau[1]  = 1;
  src.height  = 2;
  src.rings   = 8;
  src.spike_h   = 1.0;
  src.spike_w   = 0.5;
  src.morin_eps = 0.02;
  PetscOptionsBegin(comm, prefix, "Mesh source", NULL);
  PetscCall(CSOptionsString("-mesh", "Mesh file (.obj, .off, .ply)", "CSMeshDataFromOptions", src.path, src.path, sizeof(src.path), &src.file));
  PetscCall(CSOptionsEList("-gen", "Generated mesh", "CSMeshDataFromOptions", GenNames, 8, GenNames[gen], &gen, &genset));
  PetscCall(CSOptionsInt("-gen_level", "Icosphere: subdivision level", "CSMeshDataIcosphere", src.level, &src.level, NULL));
  PetscCall(CSOptionsReal("-gen_radius", "Icosphere, cylinder, disk: radius", "CSMeshDataIcosphere", src.radius, &src.radius, NULL));
  PetscCall(PetscOptionsBool("-gen_project", "Icosphere: project the new vertices to the sphere", "CSMeshDataIcosphere", src.project, &src.project, NULL));
  PetscCall(CSOptionsReal("-gen_torus_R", "Torus: radius R of the big circle (PETSc option names ignore case, hence not -gen_R)", "CSMeshDataTorus", src.R, &src.R, NULL));
  PetscCall(CSOptionsReal("-gen_tube_r", "Torus: radius r of the tube", "CSMeshDataTorus", src.r, &src.r, NULL));
  PetscCall(CSOptionsInt("-gen_n", "Torus, flat torus, cylinder: segments around", "CSMeshDataTorus", src.n, &src.n, NULL));
  PetscCall(CSOptionsInt("-gen_m", "Torus, flat torus: segments around the tube; cylinder: rows", "CSMeshDataTorus", src.m, &src.m, NULL));
  PetscCall(CSOptionsReal("-gen_tau_re", "Flat torus: real part of the conformal class tau (must be 0)", "CSMeshDataFlatTorus", src.tau_re, &src.tau_re, NULL));
  PetscCall(CSOptionsReal("-gen_tau_im", "Flat torus: imaginary part of tau", "CSMeshDataFlatTorus", src.tau_im, &src.tau_im, NULL));
  PetscCall(PetscOptionsRealArray("-gen_tau", "Lattice: the conformal class tau = RE,IM (Im tau > 0) of C/(Z + tau Z)", "CSMeshDataLattice", src.tau, &ntau, &tauset));
  PetscCall(CSOptionsReal("-gen_height", "Cylinder: height", "CSMeshDataCylinder", src.height, &src.height, NULL));
  PetscCall(CSOptionsReal("-gen_spike_height", "Spiky sphere: height of the 12 spikes (radius 1)", "CSMeshDataSpikySphere", src.spike_h, &src.spike_h, NULL));
  PetscCall(CSOptionsReal("-gen_spike_width", "Spiky sphere: angular half-width of a spike (radians)", "CSMeshDataSpikySphere", src.spike_w, &src.spike_w, NULL));
  PetscCall(PetscOptionsBool("-gen_spike_round_class", "Spiky sphere: the target conformal class is the round icosphere's (its edge lengths), not the spiky mesh's", "CSMeshDataSpikySphere", src.spike_round, &src.spike_round, NULL));
  PetscCall(CSOptionsReal("-gen_morin_perturb", "Morin surface: size of the symmetry-breaking perturbation", "CSMeshDataMorin", src.morin_eps, &src.morin_eps, NULL));
  PetscCall(CSOptionsEnum("-gen_morin_kind", "Morin surface: Apery's parametrisation (not conformal: its grid's class holds no round sphere) or Kusner's Willmore halfway model (W = 16 pi, conformal: the grid's class is the round sphere's up to O(h^2); docs/triangle_fields.md, Fig. 15)", "CSMeshDataMorin", CSMorinKinds, (PetscEnum)src.morin_kind, (PetscEnum *)&src.morin_kind, NULL));
  PetscCall(PetscOptionsBool("-gen_morin_round_class", "Morin surface: the target conformal class is the round UV sphere's on the same grid (its edge lengths), not the Morin mesh's", "CSMeshDataMorin", src.morin_round, &src.morin_round, NULL));
  PetscCall(CSOptionsInt("-gen_rings", "Disk: number of rings", "CSMeshDataDisk", src.rings, &src.rings, NULL));
  PetscCall(CSOptionsString("-mesh_lengths", "File of 3 |F| edge lengths (per face, opposite corners 0, 1, 2): the conformal class the flows' conformal rows target", "CSMeshDataReadLengths", src.lengths, src.lengths, sizeof(src.lengths), NULL));
  PetscCall(CSOptionsString("-mesh_cross_ratios", "File of lines 'i j c0' (1-based vertices as in OBJ), the log length cross ratio of every interior edge: the conformal class the flows' conformal rows target", "CSMeshDataReadCrossRatios", src.crossratios, src.crossratios, sizeof(src.crossratios), NULL));
  PetscCall(CSOptionsReal("-mesh_cross_ratios_tol", "-mesh_cross_ratios: largest part of the cross ratios outside im C (max norm) that is projected away rather than refused", "CSMeshDataReadCrossRatios", src.crtol, &src.crtol, NULL));
  PetscCall(CSOptionsInt("-mesh_refine", "Regular 1-to-4 refinements of the input (file or generator); the refined mesh's conformal class is a flow's constraint", "CSMeshDataRefine", src.refine, &src.refine, NULL));
  PetscCall(CSOptionsEList("-mesh_refine_type", "Positions of the refined vertices: midpoint (shape kept) or loop (Loop subdivision)", "CSMeshDataRefine", RefineNames, 2, RefineNames[rtype], &rtype, NULL));
  PetscOptionsEnd();
  PetscCall(CheckGeneratorValues(comm, pre, &src));
  PetscCheck(src.refine >= 0 && src.refine <= 6, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%smesh_refine %" PetscInt_FMT ": not in [0, 6] (each level multiplies the faces by 4)", pre, src.refine);
  PetscCheck(!tauset || ntau == 2, comm, PETSC_ERR_ARG_WRONG, "-%sgen_tau: give two numbers RE,IM (got %" PetscInt_FMT ")", pre, ntau);
  PetscCheck(!src.refine || !(gen == GEN_SPIKY && src.spike_round), comm, PETSC_ERR_ARG_INCOMP, "-%smesh_refine with -%sgen_spike_round_class: refine with -%sgen_level instead (the lengths are not refined)", pre, pre, pre);
  PetscCheck(!src.refine || !(gen == GEN_MORIN && src.morin_round), comm, PETSC_ERR_ARG_INCOMP, "-%smesh_refine with -%sgen_morin_round_class: refine with -%sgen_n, -%sgen_m instead (the lengths are not refined)", pre, pre, pre, pre);
  PetscCheck(!src.refine || gen != GEN_LATTICE, comm, PETSC_ERR_ARG_INCOMP, "-%smesh_refine with -%sgen lattice: refine with -%sgen_n, -%sgen_m instead (the lattice's lengths are not refined)", pre, pre, pre, pre);
  PetscCheck(!src.refine || !src.lengths[0], comm, PETSC_ERR_ARG_INCOMP, "-%smesh_refine with -%smesh_lengths: the lengths are given for the unrefined faces", pre, pre);
  PetscCheck(!src.refine || !src.crossratios[0], comm, PETSC_ERR_ARG_INCOMP, "-%smesh_refine with -%smesh_cross_ratios: the cross ratios are given for the unrefined edges", pre, pre);
  PetscCheck(!src.lengths[0] || !src.crossratios[0], comm, PETSC_ERR_ARG_INCOMP, "-%smesh_lengths with -%smesh_cross_ratios: give the target class once", pre, pre);
  src.refine_loop = rtype == 1 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(RemeshOptions(comm, prefix, &src));
  PetscCheck(!(src.remesh_faces || src.remesh_h > 0) || (!src.lengths[0] && !src.crossratios[0]), comm, PETSC_ERR_ARG_INCOMP, "-%smesh_remesh with -%smesh_lengths or -%smesh_cross_ratios: the target class is given for the input's own edges", pre, pre, pre);
  src.arrays = (PetscBool)(ArraySource != NULL); /* set on every rank */
  PetscCheck(!src.arrays || (!src.file && !genset), comm, PETSC_ERR_ARG_WRONG, "-%s%s: the mesh is given as arrays (V, F); -%smesh and -%sgen are for the command line", pre, src.file ? "mesh" : "gen", pre, pre);
  PetscCheck(src.arrays || src.file != genset, comm, PETSC_ERR_ARG_WRONG, "give exactly one of -%smesh FILE and -%sgen icosphere|torus|flattorus|cylinder|disk|lattice|spiky|morin (%s)", pre, pre, src.file ? "both were given" : "neither was given");
  src.gen = (GenType)gen;
  CSRootCall(comm, MeshSourceLoad(&src, md, topo));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataRefuseTargetClass(MPI_Comm comm, const char prefix[], const char task[])
{
  const char *opts[] = {"-mesh_lengths", "-mesh_cross_ratios"};
  PetscFunctionBeginUser;
  for (int i = 0; i < 2; i++) {
    PetscBool has;
    PetscCall(PetscOptionsHasName(NULL, prefix, opts[i], &has));
    PetscCheck(!has, comm, PETSC_ERR_ARG_INCOMP, "-%s%s: %s keeps the conformal class of the positions and has no target class to take from it (a target class is for -task flow -flow_type cgd|pgd|gd|newton|alm|trianglefield)", prefix ? prefix : "", opts[i] + 1, task);
  }
  PetscFunctionReturn(0);
}
