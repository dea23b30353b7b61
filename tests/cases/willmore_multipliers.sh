# The conformal multiplier made visible (issue 21, item 5; soliman2021 Eq. 6-8): tests/unit/test_multipliers.c
# checks sum_j q_ij = 0 at every vertex, |grad W + force| = the reported EL residual (CGD and ALM), and
# force = -Lf inside the constrained minimal cylinder (to the absolute residual rtol: -cyl_el_norm absolute); then the ParaView series of a CGD run carries the fields.
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_multipliers" -cyl_energy area -cyl_t_max 10 -cyl_el_norm absolute -alm_alm_metric gauss_newton || exit 1
d=$(mktemp -d); trap 'rm -rf "$d"' EXIT
timeout 60 $MPIEXEC bin/confsurf -task flow -gen icosphere -gen_level 2 -gen_deform_bump 0.1 -flow_max_it 3 -flow_viewer_every 1 -viewer_dir "$d/vtu" > "$d/log" || { cat "$d/log"; exit 1; }
for f in conformal_force stress_direction stress_max stress_min el_residual; do
  grep -q "Name=\"$f\"" "$d"/vtu/*.pvtu || { echo "FAIL: field $f missing in the ParaView series"; exit 1; }
done
echo "ok   ParaView fields conformal_force, stress_direction, stress_max, stress_min, el_residual at every step"
