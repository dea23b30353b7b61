#!/usr/bin/env bash
# soliman2021 Fig. 17 (issue 39): the 4-lobed critical tori continued in the class b on 96 x 24, from b = 3.9 (just above
# the smooth branch point sqrt 15 = 3.873; the grid's discrete one is 3.811) to 4.4 (the class of options/cgd_fig17_n4.opts):
#   bash runs/fig17_lobed_n4_continue.sh [B_END [STEP]]   (default 4.4 0.025; serially ~5 min under load)
# Newton from the homogeneous torus of b = 3.9 with the 4-wave 0.35, then in steps of STEP from the previous result
# (Newton from a wave at b = 4.4 does not converge: 0.6 folded; a step of 0.1 from 3.9 lands on the homogeneous torus).
# The method, its checks and exit status: runs/fig17_branch_continue.sh (any n). Results in runs/results/fig17_lobed_n4_cont/.
# Numbers: docs/triangle_fields.md "Fig. 17".
set -euo pipefail
cd "$(dirname "$0")/.."
exec bash runs/fig17_branch_continue.sh 4 96 24 3.9 0.35 "${1:-4.4}" "${2:-0.025}" runs/results/fig17_lobed_n4_cont
