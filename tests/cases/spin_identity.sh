# crane2011: rho = 0 gives the identity up to a similarity (q_max - 1 < 1e-8, gamma ~ 0), for the EPS and the
# inverse-iteration solvers, mean-zero and pinned translation, and with kept boundary tangents on a disk.
# Q is recomputed by spin_tools.py with a cancellation-free formula (the summary's q_max has a sqrt(eps) ~ 2e-8
# floor: it takes sqrt(fro^4 - 4 det^2)).
# nprocs: 1 2
source tests/lib.sh
P=tests/cases/spin_tools.py
$MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 3 -o "$TMP/in.obj" > /dev/null
$MPIEXEC "$CS_BIN" -task info -gen disk -gen_rings 8 -o "$TMP/disk.obj" > /dev/null
identity() { # label mesh options...
  local label=$1 mesh=$2; shift 2
  timeout 60 $MPIEXEC "$CS_BIN" -task spin -mesh "$mesh" -o "$TMP/out.obj" -summary "$TMP/s.json" "$@" > "$TMP/log" || { cat "$TMP/log"; return 1; }
  check_close "$(json eigenvalue "$TMP/s.json")" 0 1e-9 "$label: gamma"
  read -r qm qx < <(python3 $P q "$mesh" "$TMP/out.obj")
  check_close "$qx" 1 1e-8 "$label: q_max"
  # the output is the input itself (lambda normalised to 1, mean position kept)
  d=$(python3 $P rigid "$mesh" "$TMP/out.obj"); check_close "$d" 0 1e-8 "$label: distance to the input"
}
identity "sphere, EPS" "$TMP/in.obj"
identity "sphere, inverse iteration, pinned" "$TMP/in.obj" -spin_solver inverse -spin_pin_vertex
identity "disk, default boundary condition (kept tangents)" "$TMP/disk.obj"
identity "disk, kept boundary tangents" "$TMP/disk.obj" -spin_boundary keep
