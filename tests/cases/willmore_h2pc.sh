# The factored H^2 preconditioner (PC type csh2, src/operators/h2_pc.c), the default of the metric-only solve
# (gd): P = (sM + L) M^-1 (sM + L) is spectrally equivalent to I_H2 = wM + L M^-1 L with condition <= 2, so CG
# needs few iterations independent of the mesh (asserted: <= 15 per step at rtol 1e-9, at 20480 faces at most 2
# more than at 1280; measured 10 and 10), and the
# steps equal those of CG + a Cholesky factorisation of I_H2 itself (positions after 3 steps within 1e-7), also
# with a Dirichlet boundary (identity rows) and with the hypre AMG inner solve.
# nprocs: 1 2
source tests/lib.sh
P=tests/cases/spin_tools.py
# -flow_max_step 0: one solve per iteration (gd's geometric step cap would add rejected trials to the counts)
run() { timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type gd -flow_max_step 0 -flow_max_it 3 -flow_rtol 0 "$@" > "$TMP/log" 2>&1 || { tail "$TMP/log"; exit 1; }; }
maxits() { python3 -c 'import csv,sys; print(max(int(r["ksp_its"]) for r in csv.DictReader(open(sys.argv[1])) if int(r["it"]) > 0))' "$1"; }
for L in 3 5; do
  S="-gen icosphere -gen_level $L -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8"
  run $S -summary "$TMP/a$L.json" -history_csv "$TMP/a$L.csv" -o "$TMP/a$L.obj"
  its=$(maxits "$TMP/a$L.csv"); echo "level $L: CG iterations per step (csh2) $its"
  [ "$its" -le 15 ] || { echo "BAD: more than 15 CG iterations"; exit 1; }
  [ -z "${its3:-}" ] || [ "$its" -le $((its3 + 2)) ] || { echo "BAD: iterations grow with the mesh ($its3 -> $its)"; exit 1; }
  its3=$its
  run $S -flow_saddle_pc_type cholesky -flow_saddle_pc_factor_mat_solver_type mumps -o "$TMP/b$L.obj"
  check_close "$(python3 $P rigid "$TMP/a$L.obj" "$TMP/b$L.obj")" 0 1e-7 "level $L: csh2 vs Cholesky of I_H2, positions"
done
C="-gen cylinder -gen_n 24 -gen_m 12 -gen_height 2 -flow_energy area -flow_boundary dirichlet"
run $C -o "$TMP/c1.obj"
run $C -flow_saddle_pc_type cholesky -flow_saddle_pc_factor_mat_solver_type mumps -o "$TMP/c2.obj"
check_close "$(python3 $P rigid "$TMP/c1.obj" "$TMP/c2.obj")" 0 1e-7 "Dirichlet cylinder: csh2 vs Cholesky, positions"
# the level-3 input of the loop above: its Cholesky run b3 is the reference (one launch fewer)
S="-gen icosphere -gen_level 3 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8"
run $S -flow_saddle_h2_ksp_type preonly -flow_saddle_h2_pc_type hypre -o "$TMP/h.obj"
check_close "$(python3 $P rigid "$TMP/h.obj" "$TMP/b3.obj")" 0 1e-7 "csh2 with hypre inner solves vs Cholesky, positions"
