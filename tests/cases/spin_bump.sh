# crane2011 Sec. 6.3 / Fig. 12: a smooth bump rho on the unit icosphere gives q_mean close to 1, decreasing
# about linearly with the edge length (levels 2, 3, 4: q_mean - 1 halves per level); the shell and AIJ Dirac
# operators give the same result to round-off; so do the eigensolvers (shift-and-invert with the quaternion
# Cholesky factorisation csquat, the default; with CHOLMOD's complex-form factorisation cscholmod; with the real
# 4V x 4V factorisation cholmod; Generalised Davidson preconditioned by the scalar Laplacian, factored or one
# AMG V-cycle per quaternion component: GAMG, or hypre BoomerAMG under LOBPCG; issue 16), each with an eigen
# residual within the EPS tolerance.
# nprocs: 1
source tests/lib.sh
P=tests/cases/spin_tools.py
B="-rho_bump_center 0,0,1 -rho_bump_radius 0.5 -rho_bump_height 3"
prev=""
for L in 2 3 4; do
  timeout 60 $MPIEXEC "$CS_BIN" -task spin -gen icosphere -gen_level $L $B -summary "$TMP/s$L.json" -o "$TMP/o$L.obj" > /dev/null
  q=$(json q_mean "$TMP/s$L.json"); echo "level $L: q_mean $q"
  python3 -c "import sys; q=float(sys.argv[1]); sys.exit(0 if 1 < q < 1.1 else 1)" "$q" || { echo "BAD q_mean $q"; exit 1; }
  if [ -n "$prev" ]; then
    python3 - "$prev" "$q" <<'PY'
import sys
a, b = float(sys.argv[1]) - 1, float(sys.argv[2]) - 1
r = a / b
print(("ok  " if 1.5 <= r <= 2.5 else "BAD ") + "(q_prev-1)/(q-1) = %.3f (linear convergence: 2)" % r)
sys.exit(0 if 1.5 <= r <= 2.5 else 1)
PY
  fi
  prev=$q
done
timeout 60 $MPIEXEC "$CS_BIN" -task spin -gen icosphere -gen_level 3 $B -spin_dirac_type shell -summary "$TMP/sh.json" -o "$TMP/sh.obj" > /dev/null
check_close "$(json eigenvalue "$TMP/sh.json")" "$(json eigenvalue "$TMP/s3.json")" 1e-9 "shell vs AIJ: gamma"
check_close "$(json q_mean "$TMP/sh.json")" "$(json q_mean "$TMP/s3.json")" 1e-9 "shell vs AIJ: q_mean"
check_close "$(python3 $P rigid "$TMP/sh.obj" "$TMP/o3.obj")" 0 1e-8 "shell vs AIJ: positions"
for alt in "-spin_st_pc_factor_mat_solver_type cscholmod" "-spin_st_pc_factor_mat_solver_type cholmod" "-spin_solver precond" \
           "-spin_solver precond -spin_lap_pc_type gamg" "-spin_solver precond -spin_lap_pc_type hypre -spin_eps_type lobpcg"; do
  timeout 60 $MPIEXEC "$CS_BIN" -task spin -gen icosphere -gen_level 3 $B $alt -summary "$TMP/alt.json" -o "$TMP/alt.obj" > /dev/null
  python3 -c "import sys; r=float(sys.argv[1]); print(('ok  ' if r <= 1e-10 else 'BAD ') + 'eigen residual %.2e' % r); sys.exit(r > 1e-10)" "$(json eigen_residual "$TMP/alt.json")"
  check_close "$(json eigenvalue "$TMP/alt.json")" "$(json eigenvalue "$TMP/s3.json")" 1e-9 "$alt vs default: gamma"
  check_close "$(python3 $P rigid "$TMP/alt.obj" "$TMP/o3.obj")" 0 1e-8 "$alt vs default: positions"
done
