# Issue 37: the triangle field's state and options belong to its kind (src/methods/willmore/impls/trianglefield/).
# tests/unit/test_trianglefield_info.c: its getter CSWillmoreFlowTriangleFieldGetInfo (another kind: a flag or an
# error; the kind: the integrability violation, pinch edges, E_tau and -flow_immersion_tol). Then bin/confsurf: the
# kind's options read in its ops.setfromoptions, shown by its ops.view below the flow's line: the resolution guard
# -flow_max_area_ratio is opt-in for this kind (0 unless given, 200 for cgd), the options of its schedule and
# continuation refused out of range with one line naming them.
# nprocs: 1 2
source tests/lib.sh
timeout 60 $MPIEXEC "$CS_TESTS/test_trianglefield_info" -malloc_dump || exit 1
B="-task flow -gen icosphere -gen_level 1 -flow_max_it 0"
view() { # expected regex of the kind's second view line, options
  local want=$1; shift
  timeout 60 $MPIEXEC "$CS_BIN" $B "$@" > "$TMP/v.log" 2>&1 || { cat "$TMP/v.log"; echo "BAD: $*"; exit 1; }
  grep -qE -- "$want" "$TMP/v.log" || { head -4 "$TMP/v.log"; echo "BAD: $* does not show /$want/"; exit 1; }
  echo "ok  $*: $(grep -oE -- "$want" "$TMP/v.log")"
}
view "^  integrability weight 0.0001 .*max area ratio 0\.?$" -flow_type trianglefield
view "^  integrability weight 0.001 from iteration 3 .*max area ratio 50\.?$" -flow_type trianglefield -flow_max_area_ratio 50 -flow_integrability_weight 1e-3 -flow_integrability_start 3
view "^  triangle field: variables omega, start random \(seed 4, amplitude 0.01\)" -flow_type trianglefield -flow_init random -flow_seed 4 -flow_init_amplitude 0.01
# cgd keeps the guard's default and prints no triangle-field lines
timeout 60 $MPIEXEC "$CS_BIN" $B -flow_type cgd > "$TMP/c.log" 2>&1 || { cat "$TMP/c.log"; exit 1; }
! grep -q "triangle field" "$TMP/c.log" || { echo "BAD: cgd shows triangle-field lines"; exit 1; }
echo "ok  cgd: no triangle-field lines"
EXPECT="-flow_integrability_start -1: must be >= 0" expect_fail $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -flow_integrability_start -1 || exit 1
EXPECT="-flow_spin_stage_max_it -2: must be >= 0" expect_fail $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -flow_spin_stage_max_it -2 || exit 1
EXPECT="-flow_t_mu_final with -flow_spin_weight_decay 0.5" expect_fail $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -flow_t_mu_final 1e6 -flow_spin_weight_decay 0.5 || exit 1
