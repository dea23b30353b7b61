# The substructured CHOLMOD Cholesky (PC cssubchol, src/linalg/substructured_cholesky.c), the parallel default
# for the flow's Schur complement S: unit checks (tests/unit/test_subchol.c: direct-solve residual < 1e-11 on a
# two-ring 3-dof matrix with METIS/AMD/NESDIS interiors, a refactorisation on the same pattern, the interface size,
# an indefinite matrix ending the KSP with DIVERGED_PC_FAILED on every rank), then a cgd flow whose steps equal those
# with the Schur complement factored by Cholesky (MUMPS on several ranks, CHOLMOD on one): positions within 1e-9, W within 1e-10,
# one FGMRES iteration per linear solve (an exact factorisation), the same number of iterations; the automatic
# switch to MUMPS where the dense interface does not fit (forced by -pc_cssubchol_max_interface_ratio 0
# -pc_cssubchol_fits_mb 0): a note on several ranks (none serially, where there is no interface), and the same steps;
# unknown values of -pc_cssubchol_ordering / -pc_cssubchol_interface and a negative ratio fail with an error naming
# the option (on 1 and 2 ranks).
# nprocs: 1 2 3
source tests/lib.sh
P=tests/cases/spin_tools.py
$MPIEXEC "$CS_TESTS/test_subchol"
S="-task flow -gen icosphere -gen_level 3 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8 -flow_max_it 4 -flow_rtol 0 -flow_factor_reuse_its 0"
timeout 120 $MPIEXEC "$CS_BIN" $S -flow_saddle_fieldsplit_1_pc_type cssubchol -summary "$TMP/a.json" -o "$TMP/a.obj" > "$TMP/a.log" 2>&1 || { tail "$TMP/a.log"; exit 1; }
timeout 120 $MPIEXEC "$CS_BIN" $S -flow_saddle_fieldsplit_1_pc_type cholesky -summary "$TMP/b.json" -o "$TMP/b.obj" > "$TMP/b.log" 2>&1 || { tail "$TMP/b.log"; exit 1; }
grep -E "flow cgd: (NOT )?converged" "$TMP/a.log"
check_close "$(python3 $P rigid "$TMP/a.obj" "$TMP/b.obj")" 0 1e-9 "cssubchol vs Cholesky of S: positions after 4 steps"
# W to 1e-10: the two factorisations differ at round-off, and 4 steps with the dual step 1e5 t carry that to about
# 1e-11 in the positions (8.8e-12 here, 7.9e-12 on the CI machine, whose OpenBLAS kernels give MUMPS other round-off).
# W moves with the positions at |grad W| = O(1) per vertex: measured |dW| 4.2e-12 here and 1.45e-11 (1.1e-12
# relative) on CI, which failed the old 1e-12. 1e-10 is 10x tighter than the position bound 1e-9 implies.
WTOL=1e-10
check_close "$(json willmore "$TMP/a.json")" "$(json willmore "$TMP/b.json")" $WTOL "W"
solves=$(json linear_solves "$TMP/a.json") # the steps, rejected ones and second-order corrections included
its=$(json ksp_iterations "$TMP/a.json")
echo "FGMRES iterations $its for $solves linear solves"
[ "$its" = "$solves" ] || { echo "BAD: an exact factorisation needs one FGMRES iteration per solve"; exit 1; }
[ "$its" = "$(json ksp_iterations "$TMP/b.json")" ] || { echo "BAD: iteration counts differ from the Cholesky run"; exit 1; }
# the dense interface "does not fit": MUMPS instead of the substructuring, with a note, same flow
F="-flow_saddle_fieldsplit_1_pc_cssubchol_max_interface_ratio 0 -flow_saddle_fieldsplit_1_pc_cssubchol_fits_mb 0"
timeout 120 $MPIEXEC "$CS_BIN" $S -flow_saddle_fieldsplit_1_pc_type cssubchol $F -summary "$TMP/c.json" -o "$TMP/c.obj" > "$TMP/c.log" 2>&1 || { tail "$TMP/c.log"; exit 1; }
notes=$(grep -c "MUMPS Cholesky instead" "$TMP/c.log" || true)
echo "fallback notes: $notes"
if [ "$NP" = 1 ]; then [ "$notes" = 0 ] || { echo "BAD: a fallback note serially (no interface)"; exit 1; }
else [ "$notes" -ge 1 ] || { echo "BAD: no note of the switch to MUMPS on $NP ranks"; exit 1; }; fi
check_close "$(python3 $P rigid "$TMP/c.obj" "$TMP/b.obj")" 0 1e-9 "cssubchol falling back to MUMPS vs Cholesky of S: positions after 4 steps"
check_close "$(json willmore "$TMP/c.json")" "$(json willmore "$TMP/b.json")" $WTOL "W (fallback)"
[ "$(json ksp_iterations "$TMP/c.json")" = "$(json ksp_iterations "$TMP/b.json")" ] || { echo "BAD: fallback iteration counts differ from the Cholesky run"; exit 1; }
# bad option values: a clear error naming the option, non-zero exit; serially and on 2 ranks (the options are read
# the same way on every rank count; the three 3-rank launches, oversubscribed on 2 cores, cost ~1.4 CPU s)
[ "$NP" -le 2 ] || exit 0
EXPECT="Unknown option foo for -flow_saddle_fieldsplit_1_pc_cssubchol_ordering" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $S -flow_saddle_fieldsplit_1_pc_type cssubchol -flow_saddle_fieldsplit_1_pc_cssubchol_ordering foo
EXPECT="Unknown option middle for -flow_saddle_fieldsplit_1_pc_cssubchol_interface" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $S -flow_saddle_fieldsplit_1_pc_type cssubchol -flow_saddle_fieldsplit_1_pc_cssubchol_interface middle
EXPECT="-flow_saddle_fieldsplit_1_pc_cssubchol_max_interface_ratio -1.*must be >= 0" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $S -flow_saddle_fieldsplit_1_pc_type cssubchol -flow_saddle_fieldsplit_1_pc_cssubchol_max_interface_ratio -1
