# crane2011 Sec. 7.2 / Fig. 21: similarity interpolation (-spin_interpolate N) from a flat disk to a conformal bump
# of it (a spin transformation, q_mean 1.037): the ends are the input and the target to 1e-9, and every
# intermediate mesh is closer to conformal (q_mean against the start) than the linear interpolation of positions
# (measured 1.031/1.040/1.033 against 1.079/1.113/1.084). A target of other connectivity is a clear error.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task info -gen disk -gen_rings 12 -o "$TMP/disk.obj" > /dev/null
$MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -spin_boundary none -rho_bump_center 0,0,0 -rho_bump_height 3 -rho_bump_radius 0.5 -o "$TMP/bump.obj" > /dev/null
$MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -spin_target_mesh "$TMP/bump.obj" -spin_interpolate 4 -spin_interpolate_prefix "$TMP/i" -summary "$TMP/s.json" | grep "t=0.500"
python3 - "$TMP/s.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
qi, ql = s["interpolation_q_mean"], s["linear_q_mean"]
bad = 0
checks = [(s["interpolation_start_error"] < 1e-9 and s["interpolation_end_error"] < 1e-9, "ends reproduced: %.1e, %.1e" % (s["interpolation_start_error"], s["interpolation_end_error"])),
          (ql[-1] > 1.01, "the target is not a similarity of the start (q_mean %.4f)" % ql[-1])]
checks += [(qi[k] <= ql[k], "t=%.2f: q_mean %.5f <= linear %.5f" % (k / 4, qi[k], ql[k])) for k in range(1, 4)]
for ok, msg in checks:
    print(("ok  " if ok else "BAD ") + msg); bad += not ok
sys.exit(bad)
PY
for k in 0 1 2 3 4; do test -s "$TMP/i_$k.obj"; done && echo "ok  5 meshes written"
$MPIEXEC "$CS_BIN" -task info -gen disk -gen_rings 11 -o "$TMP/other.obj" > /dev/null
EXPECT="-spin_target_mesh .*other.obj.*not the same connectivity" expect_fail $MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -spin_target_mesh "$TMP/other.obj" -spin_interpolate 4
# Fig. 22 baseline (-spin_least_squares: positions from mu by least squares, no eigenproblem) against the nearest
# spin transformation, for a stretched sphere: the baseline is further from conformal (q_mean 1.056 against 1.008
# on level 3, docs/spin_applications.md).
$MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 2 -o "$TMP/ico.obj" > /dev/null
$MPIEXEC "$CS_BIN" -task flow -gen icosphere -gen_level 2 -gen_deform_stretch 1.3,1,1 -flow_max_it 0 -o "$TMP/ico_t.obj" > /dev/null 2>&1
$MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/ico.obj" -spin_target_mesh "$TMP/ico_t.obj" -summary "$TMP/spin.json" > /dev/null
$MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/ico.obj" -spin_target_mesh "$TMP/ico_t.obj" -spin_least_squares -summary "$TMP/lsq.json" > /dev/null
python3 -c "
import json, sys
a, b = json.load(open('$TMP/spin.json')), json.load(open('$TMP/lsq.json'))
ok = b['q_mean'] > a['q_mean'] + 0.01 and b['target_distance_max'] < 0.2
print(('ok  ' if ok else 'BAD ') + 'least squares q_mean %.4f (distance %.3f) vs spin %.4f (distance %.3f)' % (b['q_mean'], b['target_distance_max'], a['q_mean'], a['target_distance_max'])); sys.exit(not ok)"
[ "$NP" = 1 ] || exit 0
EXPECT="-spin_interpolate needs -spin_target_mesh" expect_fail "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -spin_interpolate 4
