/* Discrete Willmore flow of Bobenko-Schroeder (bobenko-schroeder2005 Sec. 4): -task flow -flow_type bs.
   Schemes (-bs_scheme):
     semi  semi-implicit steps (1/dt I + K) dx = -grad W, one n x n solve per coordinate with the KSP of
           prefix "bs_" (K: the linearised Hessian of Eq. 1, symmetric, indefinite only by a few small
           negative eigenvalues; default MUMPS LDL^T with AMD ordering, 5x faster than CG + BoomerAMG on
           the bunny, runs/bench_bs.sh; -bs_ksp_type cg -bs_pc_type hypre is the iterative alternative). A
           failed solve or an energy increase rejects the step and divides dt by 4 (at most
           -bs_max_rejections in a row, default 30); accepted steps grow dt by -bs_dt_grow up to -bs_dt_max;
     tao   TAO of prefix "bs_" (any -bs_tao_type; objective/gradient = W, Hessian = K on each coordinate as
           a 3V x 3V AIJ with block size 3, plus I/dt: K alone gives the Newton step -x, a homothety, useless
           for the scale-invariant W): -bs_tao_mode static minimises W in one TaoSolve (the static problem;
           dt grows by -bs_dt_grow per Hessian), -bs_tao_mode euler does backward Euler steps
           min W(x) + |x - x_n|^2 / (2 dt). Default NLS with CG + BoomerAMG (-bs_tao_nls_ksp_type/pc_type).
   Boundaries (-bs_boundary fixed|free, Sec. 3.3), heuristic threshold -bs_beta_eps (Sec. 3.2).
   -bs_perturb f moves the free vertices randomly by f mean edge lengths first (breaks the co-circular
   diamonds, beta = 0, of grid-like meshes); -bs_hessian_eps s leaves diamonds with sin beta < s out of K
   (our option; near beta = 0 Eq. 1's coefficients grow like 1/sin beta).
   -bs_monotone false accepts steps that increase W (the paper's plain stepping). With many diamonds at
   beta = 0 (W has a kink there) the heuristic's direction is not a descent direction: the monotone control
   then stalls (dt -> 1e-8), the plain stepping moves but W first rises (generator torus: 67 -> 200+).
   Stopping: W < -bs_atol, or a relative decrease (W_n - W_{n+1}) / W_n < -bs_rtol, or -bs_max_it steps.
   dt has units of length^2 (K ~ 1/length^2); the default -bs_dt_rel 1 takes dt = (mean edge length)^2.
   seconds_per_step: wall time of the stepping loop (with the first assembly of K and grad W) divided by the
   attempted steps (accepted + rejected).
   Summary keys: willmore_bs, iterations, converged, seconds, rejected, dt_final, seconds_per_step, scheme,
   boundary, and the mesh facts (xref = initial positions). History: it,willmore_bs,willmore,area,dt,
   ksp_its,seconds. ParaView (-viewer_dir): per step, vertex field W_i. */
#ifndef CS_METHODS_BS_H
#define CS_METHODS_BS_H
#include "cs_output.h"
#include "cs_energy_bs.h"

PETSC_EXTERN PetscErrorCode CSFlowBS(MPI_Comm comm, CSOutput *out);

#endif
