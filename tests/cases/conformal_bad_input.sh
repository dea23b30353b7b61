# Bad input to the conformal flow: a mesh with boundary without a boundary mode (Sec. 6.3), V = +-N, a boundary mode
# on a closed mesh, a target of other connectivity, tau <= 0, a bad filter order,
# an unknown eigensolver: one clear line naming the mesh or the option, non-zero exit. Under 2 ranks only the first
# two (every rank exits non-zero, no hang; a process start costs ~2 s there).
# nprocs: 1 2
source tests/lib.sh
run() { timeout 60 $MPIEXEC "$CS_BIN" -task flow -flow_type conformal "$@"; }
EXPECT="boundary loop.*Sec. 6.3" expect_fail run -gen disk -gen_rings 4
EXPECT="-flow_tau 0: must lie in \[1e-14, 1e3\]" expect_fail run -gen icosphere -gen_level 1 -flow_tau 0
[ "$NP" = 1 ] || exit 0
EXPECT="-flow_tau -1: must lie in \[1e-14, 1e3\]" expect_fail run -gen icosphere -gen_level 1 -flow_tau -1
EXPECT="-flow_filter_k 7: must lie in 0..4" expect_fail run -gen icosphere -gen_level 1 -flow_filter_k 7
EXPECT="-flow_filter_sigma -1" expect_fail run -gen icosphere -gen_level 1 -flow_filter_sigma -1
EXPECT="eigensolver" expect_fail run -gen icosphere -gen_level 1 -flow_eigensolver lanczos
EXPECT="-flow_boundary_frame 1.*V = .-N is not allowed" expect_fail run -gen disk -gen_rings 4 -flow_boundary vector -flow_boundary_frame 1,0,0
EXPECT="-flow_boundary fixed: mesh .* has no boundary" expect_fail run -gen icosphere -gen_level 1 -flow_boundary fixed
EXPECT="-flow_target_mesh" expect_fail run -gen disk -gen_rings 4 -flow_boundary fixed -flow_target_mesh meshes/bunny_lowres_npm.obj
EXPECT="checkpoint" expect_fail run -gen icosphere -gen_level 1 -checkpoint "$TMP/c.bin"
# review of 2026-12-05: a frame of fewer or more than three numbers (1 was read as 1,0,1), balancing with a boundary
EXPECT="-flow_boundary_frame: give exactly three numbers cN,cT,cB \(1 given\)" expect_fail run -gen disk -flow_boundary vector -flow_boundary_frame 1
EXPECT="-flow_boundary_frame: give exactly three numbers cN,cT,cB \(more given\)" expect_fail run -gen disk -flow_boundary vector -flow_boundary_frame 1,0,0,5
EXPECT="-flow_mobius with -flow_boundary vector" expect_fail run -gen disk -flow_boundary vector -flow_mobius
