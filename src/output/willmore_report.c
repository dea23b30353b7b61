/* The end of a Willmore flow run: the final checkpoint, the final line and the summary keys (unchanged since
   before the flow was an object), then mesh facts, -o and -summary (the ParaView series: willmore_viewer.c). */
#include "cs_output_willmore.h"

PETSC_INTERN PetscErrorCode CSWillmoreFlowCheckpointFinal(CSWillmoreFlow flow, CSOutput *out);

/* -flow_type trianglefield: its own keys (none for the other kinds) */
static PetscErrorCode TriangleFieldKeys(CSWillmoreFlow flow, CSOutput *out)
{
  CSWillmoreFlowTriangleFieldInfo tf;
  PetscBool                       is;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowTriangleFieldGetInfo(flow, &tf, &is));
  if (!is) PetscFunctionReturn(0);
  if (tf.integrability_violation >= 0) PetscCall(CSJSONAddReal(out->json, "integrability_violation", tf.integrability_violation));
  if (tf.pinch_edges >= 0) PetscCall(CSJSONAddInt(out->json, "pinch_edges", tf.pinch_edges));
  if (tf.pinch_vertices >= 0) PetscCall(CSJSONAddInt(out->json, "pinch_vertices", tf.pinch_vertices));
  if (tf.pinch_edges >= 0) PetscCall(CSJSONAddReal(out->json, "spin_energy", tf.spin_energy));
  PetscFunctionReturn(0);
}

static PetscErrorCode SummaryKeys(CSWillmoreFlow flow, CSOutput *out, const CSWillmoreFlowInfo *i)
{
  CSWillmoreFlowType            type;
  CSWillmoreFlowConvergedReason reason;
  const char                   *energy;
  PetscReal                     E0;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetType(flow, &type));
  PetscCall(CSWillmoreFlowGetConvergedReason(flow, &reason));
  PetscCall(CSWillmoreFlowGetEnergyName(flow, &energy));
  PetscCall(CSWillmoreFlowGetInitialEnergy(flow, &E0));
  PetscCall(CSJSONAddString(out->json, "flow_type", type));
  PetscCall(CSJSONAddString(out->json, "energy_name", energy));
  PetscCall(CSJSONAddInt(out->json, "iterations", i->it));
  PetscCall(CSJSONAddBool(out->json, "converged", (PetscBool)CSWillmoreFlowReasonConverged(reason)));
  PetscCall(CSJSONAddString(out->json, "stop_reason", CSWillmoreFlowStopReasons[reason]));
  PetscCall(CSJSONAddString(out->json, "degeneration", CSWillmoreFlowDegenerations[i->degeneration]));
  PetscCall(CSJSONAddReal(out->json, "energy_initial", E0)); /* of the input (after any -gen_deform_*) */
  PetscCall(CSJSONAddReal(out->json, "energy", i->energy));
  PetscCall(CSJSONAddReal(out->json, "area_spread", i->area_spread));
  PetscCall(CSJSONAddReal(out->json, "violation_max", i->violation_max)); /* a violation that grew and was projected away at the stop stays visible */
  PetscCall(CSJSONAddBool(out->json, "violation_grew", i->violation_grew)); /* issue 21: the violation never grows unreported */
  PetscCall(CSJSONAddReal(out->json, "violation_min", i->violation_min));
  PetscCall(CSJSONAddInt(out->json, "violation_min_iteration", i->violation_min_it));
  PetscCall(CSJSONAddInt(out->json, "violation_max_iteration", i->violation_max_it));
  PetscCall(CSJSONAddReal(out->json, "conformal_violation", i->conformal_violation));
  PetscCall(CSJSONAddReal(out->json, "constraint_violation", i->constraint_violation));
  PetscCall(CSJSONAddReal(out->json, "el_residual", i->el_residual));
  PetscCall(CSJSONAddReal(out->json, "el_residual_scaled", i->el_residual_scaled)); /* what -flow_rtol tests by default */
  /* which state -o and the keys above hold (-flow_keep_best), and the other one */
  PetscCall(CSJSONAddString(out->json, "state", i->best_used ? "best" : "last"));
  PetscCall(CSJSONAddInt(out->json, "best_iteration", i->best_it));
  if (i->best_it >= 0) PetscCall(CSJSONAddReal(out->json, "best_el_residual_scaled", i->best_el_residual_scaled));
  if (i->best_it >= 0) PetscCall(CSJSONAddReal(out->json, "best_energy", i->best_energy));
  PetscCall(CSJSONAddInt(out->json, "last_iteration", i->last_it));
  PetscCall(CSJSONAddReal(out->json, "last_energy", i->last_energy));
  PetscCall(CSJSONAddReal(out->json, "last_el_residual_scaled", i->last_el_residual_scaled));
  PetscCall(CSJSONAddReal(out->json, "el_min", i->el_min)); /* the smallest EL residual of the run, at it_el_min */
  PetscCall(CSJSONAddInt(out->json, "it_el_min", i->it_el_min));
  PetscCall(CSJSONAddReal(out->json, "energy_el_min", i->energy_el_min));
  PetscCall(CSJSONAddInt(out->json, "rejections", i->rejections));
  PetscCall(CSJSONAddInt(out->json, "ksp_iterations", i->ksp_its_total));
  PetscCall(CSJSONAddInt(out->json, "pc_setups", i->pc_setups));         /* preconditioner builds (factorisations) */
  PetscCall(CSJSONAddInt(out->json, "linear_solves", i->linear_solves)); /* steps, corrections, projections, bordering */
  PetscCall(CSJSONAddReal(out->json, "t_final", i->t));
  PetscCall(CSJSONAddReal(out->json, "seconds_per_iteration", i->it ? i->seconds / i->it : 0));
  PetscCall(TriangleFieldKeys(flow, out)); /* before constraint_values, as when they were CSWillmoreFlowInfo's */
  if (i->k) PetscCall(CSJSONAddRealArray(out->json, "constraint_values", i->k, i->constraint_values));
  PetscFunctionReturn(0);
}

/* A run that did not converge: how near a critical point its path came (the smallest EL residual, soliman2021
   Sec. 6.1.2's stopping measure) and whether it moved away from it while the energy kept falling
   (docs/real_meshes.md 0b: knot1_cgal reaches EL 2.48 at iteration 10, 13.8 at the guard's stop at 29). */
static PetscErrorCode PathLine(CSMesh mesh, const CSWillmoreFlowInfo *i)
{
  PetscFunctionBeginUser;
  if (!(i->el_min < PETSC_MAX_REAL) || i->it == 0) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(mesh->comm, "flow path: EL residual %.3e at the start, smallest %.3e at iteration %" PetscInt_FMT " (W %.10g), %.3e at the stop (W %.10g)", (double)i->el_first, (double)i->el_min, i->it_el_min, (double)i->energy_el_min, (double)i->el_residual, (double)i->energy));
  if (i->it_el_min < i->it && i->el_residual > 1.25 * i->el_min) PetscCall(PetscPrintf(mesh->comm, ": the path came nearest a critical point %" PetscInt_FMT " iterations before the stop and moved away from it, the residual growing %.3g-fold while W changed by %+.4g\n", i->it - i->it_el_min, (double)(i->el_residual / i->el_min), (double)(i->energy - i->energy_el_min)));
  else if (i->it_el_min < i->it) PetscCall(PetscPrintf(mesh->comm, ": at the stop within 25 %% of its smallest\n"));
  else PetscCall(PetscPrintf(mesh->comm, ": the residual is smallest at the stop\n"));
  PetscFunctionReturn(0);
}

/* -o of a triangle-field flow (-flow_type trianglefield) writes the Poisson reconstruction of omega, an immersion of
   omega only when omega is integrable: above -flow_immersion_tol (default 1e-6) of integrability violation the
   summary is written and the mesh is refused with one line (issue 15: a non-integrable omega where an immersion is
   required). */
static PetscErrorCode CheckImmersion(CSWillmoreFlow flow, CSOutput *out, CSMesh mesh)
{
  CSWillmoreFlowTriangleFieldInfo tf;
  const char                     *prefix;
  PetscBool                       is; /* another kind: tf says immersion */
  PetscFunctionBeginUser;
  if (!out->has_out) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowTriangleFieldGetInfo(flow, &tf, &is));
  if (CSWillmoreFlowTriangleFieldInfoIsImmersion(&tf)) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetOptionsPrefix(flow, &prefix));
  PetscCall(CSOutputAddRunFacts(out, mesh->comm));
  PetscCall(CSOutputWriteSummary(out, mesh->comm));
  SETERRQ(mesh->comm, PETSC_ERR_NOT_CONVERGED, "-o %s: the triangle field is not integrable (integrability violation %.2e > -%simmersion_tol %.1e), so its Poisson reconstruction is not an immersion of it; the mesh was not written (run the flow to convergence)", out->out, (double)tf.integrability_violation, prefix ? prefix : "", (double)tf.immersion_tol);
}
/* -flow_keep_best put the kept best state into -o; the last state goes beside it as <stem>_last<ext> (issue 35: nothing
   computed is thrown away; a guard stop's best can be an early state of small residual and the last one the state of
   lowest W), named in the summary (last_state_file). */
static PetscErrorCode WriteLastState(CSWillmoreFlow flow, CSOutput *out, CSMesh mesh)
{
  Vec  last;
  char path[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetLastSolution(flow, &last));
  if (!last || !out->has_out) PetscFunctionReturn(0);
  PetscCall(CSPathInsertSuffix(out->out, "_last", path, sizeof(path)));
  PetscCall(CSMeshWrite(mesh, last, path));
  PetscCall(PetscPrintf(mesh->comm, "wrote the last state of the run to %s (-o holds the best)\n", path));
  PetscCall(CSJSONAddString(out->json, "last_state_file", path));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowReport(CSWillmoreFlow flow, CSOutput *out)
{
  CSWillmoreFlowInfo            i, last;
  CSWillmoreFlowType            type;
  CSWillmoreFlowConvergedReason reason;
  CSMesh                        mesh;
  Vec                           x, x0;
  const char                   *prefix;
  PetscBool                     best;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowCheckpointFinal(flow, out)); /* the last state: a resume continues the iteration */
  PetscCall(CSWillmoreFlowGetInfo(flow, &last));       /* the path line is of the last state */
  PetscCall(CSWillmoreFlowUseBest(flow, &best));       /* -flow_keep_best: -o and the summary get the best state */
  PetscCall(CSWillmoreFlowGetOptionsPrefix(flow, &prefix));
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  PetscCall(CSWillmoreFlowGetType(flow, &type));
  PetscCall(CSWillmoreFlowGetConvergedReason(flow, &reason));
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(CSWillmoreFlowGetInitial(flow, &x0));
  PetscCall(PetscPrintf(mesh->comm, "flow %s: %s after %" PetscInt_FMT " iterations (%s; %" PetscInt_FMT " rejected steps, %" PetscInt_FMT " KSP iterations, %" PetscInt_FMT " edges with guarded I_Q weight), %.3f s; conformal violation %.2e, constraint violation %.2e (largest violation of the run %.2e), EL residual %.2e (scaled %.2e)%s\n", type, CSWillmoreFlowReasonConverged(reason) ? "converged" : "NOT converged", i.it, CSWillmoreFlowStopReasons[reason], i.rejections, i.ksp_its_total, i.nguard, i.seconds, (double)i.conformal_violation, (double)i.constraint_violation, (double)i.violation_max, (double)i.el_residual, (double)i.el_residual_scaled, best ? "; these are of the best state kept (-o writes it)" : ""));
  if (i.violation_grew) PetscCall(PetscPrintf(mesh->comm, "flow %s: the constraint violation GREW during the run: %.2e at the end against %.2e at iteration %" PetscInt_FMT " (largest %.2e at iteration %" PetscInt_FMT "); the result does not satisfy the constraints (conformal class, global rows) to -%sctol (summary key violation_grew)\n", type, (double)PetscMax(i.conformal_violation, i.constraint_violation), (double)i.violation_min, i.violation_min_it, (double)i.violation_max, i.violation_max_it, prefix ? prefix : ""));
  if (!CSWillmoreFlowReasonConverged(reason)) PetscCall(PathLine(mesh, &last));
  PetscCall(SummaryKeys(flow, out, &i));
  PetscCall(CSOutputAddMeshFacts(out, mesh, x, x0));
  PetscCall(CheckImmersion(flow, out, mesh));
  PetscCall(WriteLastState(flow, out, mesh));
  PetscCall(CSOutputFinish(out, mesh, x));
  PetscFunctionReturn(0);
}
