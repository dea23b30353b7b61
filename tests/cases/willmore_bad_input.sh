# Every bad combination of the flow options gets a clear error, non-zero exit, no crash or hang (serial and np=2).
# nprocs: 1 2
source tests/lib.sh
F() { timeout 60 $MPIEXEC "$CS_BIN" -task flow "$@"; }
"$CS_BIN" -task info -gen icosphere -gen_level 2 -o "$TMP/ico2.obj" > /dev/null
printf '0 0 0 1\n5000 1 2 3\n' > "$TMP/range.txt"
printf '0 0 0 1\n1 abc 2 3\n' > "$TMP/garbage.txt"
printf '0 0 0 1\n0 0 0 1\n' > "$TMP/twice.txt"
EXPECT="-flow_target_mesh.*(face|connectivity|vert)" expect_fail F -gen icosphere -gen_level 3 -flow_target_mesh "$TMP/ico2.obj"
EXPECT="-flow_constraint_points.*cannot open" expect_fail F -gen icosphere -gen_level 3 -flow_constraint_points "$TMP/nonexistent.txt"
EXPECT="-flow_constraint_points.*out of range" expect_fail F -gen icosphere -gen_level 3 -flow_constraint_points "$TMP/range.txt"
EXPECT="-flow_constraint_points.*line 2" expect_fail F -gen icosphere -gen_level 3 -flow_constraint_points "$TMP/garbage.txt"
EXPECT="constrained twice" expect_fail F -gen icosphere -gen_level 3 -flow_constraint_points "$TMP/twice.txt"
EXPECT="-flow_boundary.*closed" expect_fail F -gen icosphere -gen_level 2 -flow_boundary dirichlet
EXPECT="-flow_constraint_volume.*boundary" expect_fail F -gen cylinder -flow_constraint_volume
EXPECT="-flow_metric" expect_fail F -gen icosphere -gen_level 2 -flow_metric h3
EXPECT="gd.*conformal" expect_fail F -gen icosphere -gen_level 2 -flow_type gd -flow_conformal
EXPECT="-flow_boundary normals.*conformal" expect_fail F -gen cylinder -flow_boundary normals -flow_type gd
EXPECT="unknown.*-flow_boundary|-flow_boundary.*unknown" expect_fail F -gen cylinder -flow_boundary neumann
EXPECT="-flow_factor_reuse_its -1" expect_fail F -gen icosphere -gen_level 1 -flow_factor_reuse_its -1
# options that only some flows take: refused by name where they would be ignored (review of 2026-12-02); a kind reads
# its own options (ops.setfromoptions), so another kind's are not read and the unused-option check names them
EXPECT="-flow_multiplier_ls_every 1: not read by -task flow -flow_type pgd" expect_fail F -gen icosphere -gen_level 1 -flow_type pgd -flow_multiplier_ls_every 1
EXPECT="-flow_multiplier_ls_every 1: not read by -task flow -flow_type trianglefield" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield -flow_multiplier_ls_every 1
EXPECT="-flow_multiplier_ls_every 1: only for -flow_type cgd with the conformal constraint" expect_fail F -gen icosphere -gen_level 1 -flow_type gd -flow_multiplier_ls_every 1
EXPECT="-flow_alm_rho 1: not read by -task flow -flow_type cgd" expect_fail F -gen icosphere -gen_level 1 -flow_alm_rho 1
EXPECT="-flow_newton_relax 0.1: not read by -task flow -flow_type gd" expect_fail F -gen icosphere -gen_level 1 -flow_type gd -flow_newton_relax 0.1
EXPECT="-flow_metric h1 with -flow_energy fairing" expect_fail F -gen icosphere -gen_level 1 -flow_energy fairing -flow_metric h1
EXPECT="-flow_metric h1: -flow_type trianglefield has its own metric" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield -flow_metric h1
EXPECT="-flow_spin_weight_decay 0.1: .*not -flow_variables spinor" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield -flow_variables spinor -flow_spin_weight_decay 0.1
# numeric options that used to make do-nothing runs exiting 0 (issue 18, item 10): nan, inf, out of range
# (the range table of src/methods/willmore/willmore_options.c, CSCheckOptionValues: every rank checks the same values in one
# call, so one of them on 2 ranks shows that every rank exits; the others, and -flow_max_area_ratio, -flow_soc_max_it,
# -flow_restore_above, -flow_fin_q of the same table, serially below)
EXPECT="^confsurf: error: -flow_rtol nan: must" expect_fail F -gen icosphere -gen_level 1 -flow_rtol nan
EXPECT="-bs_dt inf: must be > 0" expect_fail F -flow_type bs -gen icosphere -gen_level 2 -bs_dt inf
EXPECT="-flow_constraint_mobius.*-flow_conformal" expect_fail F -gen icosphere -gen_level 1 -flow_type gd -flow_constraint_mobius
# review of 2026-12-05: options that measured the wrong thing or were accepted out of range
EXPECT="-flow_max_step and -flow_fold_guard work on vertex positions, not on -flow_type trianglefield" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield -flow_fold_guard
# the rest serially (the same collective checks as above; a 2-rank process start costs ~1-2 s: make test's budget)
[ "$NP" = 1 ] || exit 0
for o in "-flow_iq_wmin -1" "-flow_max_it -1" "-flow_max_rejections 0" "-flow_t_mu -5" "-flow_t inf" "-flow_vmax nan"; do
  EXPECT="^confsurf: error: $o: must" expect_fail F -gen icosphere -gen_level 1 $o
done
EXPECT="-flow_max_area_ratio 0.5" expect_fail F -gen icosphere -gen_level 1 -flow_max_area_ratio 0.5
EXPECT="-flow_soc_max_it -1" expect_fail F -gen icosphere -gen_level 1 -flow_soc_max_it -1
EXPECT="-flow_restore_above -0.5" expect_fail F -gen icosphere -gen_level 1 -flow_restore_above -0.5
EXPECT="-flow_fin_q 0.5" expect_fail F -gen icosphere -gen_level 1 -flow_fin_q 0.5
EXPECT="-flow_max_step and -flow_fold_guard work on vertex positions" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield -flow_max_step 0.5
EXPECT="-flow_pgd_projection_max_it 0: must be >= 1" expect_fail F -gen icosphere -gen_level 1 -flow_type pgd -flow_pgd_projection_max_it 0
for o in "-flow_init_amplitude nan" "-flow_init_amplitude -1" "-flow_immersion_tol -1"; do
  EXPECT="$o.*: must be a finite number >= 0" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield $o
done
EXPECT="-flow_init_modes 20000: must lie in \[1, 10000\]" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield -flow_init smooth -flow_init_modes 20000
# a failed triangle-field run whose last state is not finite: the summary is written, -o is not (a NaN mesh before)
EXPECT="not a number" expect_fail F -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_type trianglefield -flow_init random -flow_init_amplitude 1e300 -o "$TMP/nan.obj" -summary "$TMP/nan.json"
[ ! -e "$TMP/nan.obj" ] || { echo "FAIL: -o was written for a non-finite state"; exit 1; }
[ "$(json stop_reason "$TMP/nan.json")" = error ] || { echo "FAIL: the summary of the failed run"; exit 1; }
# t grows up to -flow_t_max, also when t_max is not t times a power of 2 (it stopped at 2 before)
F -gen icosphere -gen_level 1 -flow_t_max 3 -flow_max_it 3 -summary "$TMP/tmax.json" > "$TMP/tmax.log" 2>&1 || { tail -3 "$TMP/tmax.log"; exit 1; }
[ "$(json t_final "$TMP/tmax.json")" = 3 ] || { echo "FAIL: t_final $(json t_final "$TMP/tmax.json"), expected 3 (-flow_t_max 3)"; exit 1; }
