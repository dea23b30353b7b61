#!/usr/bin/env bash
# soliman2021 Fig. 17 (issue 39): the 3-lobed critical tori continued in the class b up to 3.2, the class of
# options/cgd_fig17_n3.opts (above the smooth branch point sqrt 8 = 2.828):
#   bash runs/fig17_lobed_n3_continue.sh   (serially 4-10 min under load)
# 1. On 96 x 30 (b = 3.2 gives near-square triangles): Newton from the homogeneous torus of b = 2.85 with the 3-wave
#    0.25 (the grid's discrete branch point is 2.79, by runs/fig17_mode_history.py), continued in steps of 0.025 to 3.15.
#    Beyond it 96 x 30 stalls (3.175 from 3.15; 3.18 from 3.17): the necks are squeezed (face areas spread 230).
# 2. The torus of 3.15 moved to 144 x 45 (runs/fig17_regrid.py, trigonometric interpolation), Newton there at 3.15 and
#    continued to 3.2 in steps of 0.025.
# The method, its checks and exit status (non-zero unless every step is converged, 3-fold symmetric to 1e-8 and
# lobed): runs/fig17_branch_continue.sh. Results in runs/results/fig17_lobed_n3_{96x30,144x45}/.
# Numbers: docs/triangle_fields.md "Fig. 17", "The 3-lobed tori".
set -euo pipefail
cd "$(dirname "$0")/.."
d=runs/results/fig17_lobed_n3_144x45
bash runs/fig17_branch_continue.sh 3 96 30 2.85 0.25 3.15 0.025
mkdir -p $d
nice -n 10 timeout 60 bin/confsurf -task flow -flow_type cgd -gen lattice -gen_tau 0,0.3125 -gen_n 144 -gen_m 45 -flow_max_it 0 \
  -o $d/grid.obj > /dev/null
/usr/bin/python3 runs/fig17_regrid.py 96 30 runs/results/fig17_lobed_n3_96x30/b3.15.obj 144 45 $d/grid.obj $d/start_b3.15.obj
bash runs/fig17_branch_continue.sh 3 144 45 3.15 $d/start_b3.15.obj 3.2 0.025 $d
