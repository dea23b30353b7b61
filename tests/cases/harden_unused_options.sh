# Issue 36, item 18: an option given and not used (a misspelling) is refused before the work starts, on every task:
# one line naming it (with the closest option read: "did you mean -flow_max_it?"), non-zero exit on every rank, no
# signal, fast on inputs whose run takes minutes, no step taken and nothing written (-o, -summary not created, an
# existing -history_csv not truncated). Options that are read later legitimately (PETSc's solver options under the
# objects' prefixes, the saddle's and the viewer's own options) are not refused; a misspelled solver option is
# still refused by the end-of-run check.
# nprocs: 1 2
source tests/lib.sh
T="timeout 60"
serial() { [ "$NP" = 1 ]; }
mkdir "$TMP/w" && cd "$TMP/w"
OUT="-o out.obj -summary s.json -history_csv h.csv"
# refuse PATTERN CMD...: fails within the timeout, exit in 1..123, no signal or PETSc block, $PATTERN in exactly one
# line, no step in stdout (a line starting with a step number, or "... step N"), nothing written, h.csv untouched
refuse() {
  local pat=$1 out rc=0 n; shift
  printf 'keep\n' > h.csv
  out=$($T $MPIEXEC "$CS_BIN" "$@" $OUT 2>&1) || rc=$?
  n=$(grep -cE -- "$pat" <<< "$out" || true)
  if [ "$rc" = 0 ] || [ "$rc" -ge 124 ] || [ "$n" != 1 ] || grep -qE "PETSC ERROR|Caught signal|Sanitizer|runtime error:|signal [0-9]" <<< "$out"; then
    echo "$out" | head -20; echo "BAD (exit $rc, $n lines /$pat/): $*"; exit 1
  fi
  if grep -qE "^ +[0-9]+ E |step +[0-9]+ |^spin: gamma|^spectrum: [0-9]" <<< "$out"; then echo "$out" | head; echo "BAD: the work started: $*"; exit 1; fi
  if [ -e out.obj ] || [ -e s.json ] || [ "$(cat h.csv)" != keep ]; then ls -l; echo "BAD: a refused run wrote an output: $*"; exit 1; fi
  echo "ok  refused (exit $rc): $(cut -c1-140 <<< "$*")"
}
# accept CMD...: a run whose options are all legitimate (some read only at the first solve) exits 0
accept() {
  local out rc=0
  out=$($T $MPIEXEC "$CS_BIN" "$@" 2>&1) || rc=$?
  [ "$rc" = 0 ] || { echo "$out" | tail -5; echo "BAD: refused a valid run (exit $rc): $*"; exit 1; }
  echo "ok  accepted: $(cut -c1-140 <<< "$*")"
}
# inputs on which the run itself takes minutes (2562 vertices, thousands of steps), refused in seconds
ICO="-gen icosphere -gen_level 4 -gen_deform_bump 0.2"
t0=$(date +%s)
refuse "unknown option -flow_maxit 3 \(did you mean -flow_max_it\?\): not read by -task flow -flow_type cgd" -task flow $ICO -flow_maxit 3
refuse "unknown option -flow_tua 0.5 \(did you mean -flow_tau\?\)" -task flow -flow_type conformal $ICO -flow_max_it 100000 -flow_rtol 0 -flow_tua 0.5
refuse "unknown option -bs_dt_min_rell 1e-9 \(did you mean -bs_dt_min_rel\?\)" -task flow -flow_type bs $ICO -bs_max_it 100000 -bs_dt_min_rell 1e-9
refuse "unknown option -rho_bump_hieght 2 \(did you mean -rho_bump_height\?\)" -task spin $ICO -rho_bump_center 0,0,1 -rho_bump_hieght 2
refuse "unknown option -spectrum_neb 40 \(did you mean -spectrum_nev\?\)" -task spectrum $ICO -spectrum_neb 40
refuse "unknown option -curve_tua 0.5 \(did you mean -curve_tau\?\)" -task curveflow -gen_curve star -curve_max_it 100000 -curve_tua 0.5
refuse "unknown option -gen_levle 2 \(did you mean -gen_level\?\): not read by -task info" -task info -gen icosphere -gen_levle 2
secs=$(( $(date +%s) - t0 ))
[ "$secs" -le 90 ] || { echo "BAD: seven refusals took $secs s: the work ran first"; exit 1; }
echo "ok  seven tasks refused in $secs s (under load)"
if serial; then
  refuse "unknown option -flow_integrability_wieght 1 \(did you mean -flow_integrability_weight\?\): not read by -task flow -flow_type trianglefield" -task flow -flow_type trianglefield -gen torus -flow_max_it 100000 -flow_integrability_wieght 1
  refuse "unknown option -flow_newton_rtoll .*not read by -task flow -flow_type newton" -task flow -flow_type newton -gen torus -flow_max_it 100000 -flow_newton_rtoll 1
  refuse "unknown option -flow_tmax 3 \(did you mean -flow_t_max\?\)" -task flow -flow_type gd $ICO -flow_tmax 3
  refuse "unknown option -spin_flow_stesp 5 \(did you mean -spin_flow_steps\?\)" -task spin -gen disk -spin_flow_steps 3 -spin_flow_stesp 5
  # several at once: all named in the one line; an unrelated name gets no suggestion
  refuse "unknown options -(foo 1, -xyzzy|xyzzy, -foo 1): not read by" -task info -gen icosphere -foo 1 -xyzzy
  # from an options file and from PETSC_OPTIONS, as from the command line
  printf -- '-task flow\n-gen icosphere\n-gen_level 4\n-flow_maxit 3\n' > typo.opts
  refuse "unknown option -flow_maxit 3 \(did you mean -flow_max_it\?\)" -options_file typo.opts
  PETSC_OPTIONS="-flow_maxit 3" refuse "unknown option -flow_maxit 3 \(did you mean" -task flow $ICO
fi
# read late, legitimately: PETSc's options of the saddle KSP and its fieldsplit (PCSetUp at the first solve), the
# saddle's Schur options (read with the set-up), the viewer's format and iterations, SLEPc's EPS of the spin task
F="-task flow -gen icosphere -gen_level 1 -flow_max_it 2"
accept $F -flow_saddle_ksp_rtol 1e-9 -flow_saddle_fieldsplit_1_ksp_type preonly -flow_saddle_schur_rtol 1e-3 -flow_constraint_area -flow_saddle_reuse_borders 0
accept $F -viewer_dir v -viewer_format ascii -viewer_precision single -flow_viewer_iterations 1
accept -task spin -gen icosphere -gen_level 2 -rho_bump_center 0,0,1 -spin_eps_tol 1e-9
accept -task flow -flow_type bs -gen icosphere -gen_level 1 -bs_max_it 2 -bs_semi_ksp_type cg -bs_semi_pc_type jacobi
# a misspelled solver option is left to the end-of-run check: the run ends with exit 2 naming it
rc=0; out=$($T $MPIEXEC "$CS_BIN" $F -flow_saddle_ksp_rtoll 1e-9 2>&1) || rc=$?
[ "$rc" = 2 ] && grep -q "unknown or unused option -flow_saddle_ksp_rtoll 1e-9" <<< "$out" || { echo "$out" | tail -3; echo "BAD: end-of-run check (exit $rc)"; exit 1; }
echo "ok  a misspelled solver option is refused at the end (exit 2)"
# -help of a task still lists its options (it sets every task's max_it option: no check there)
serial && { $T "$CS_BIN" -task flow -help > help.txt || { echo "BAD: -task flow -help"; exit 1; }; grep -q -- "-flow_max_it" help.txt || { echo "BAD: help"; exit 1; }; echo "ok  -task flow -help"; }
exit 0
