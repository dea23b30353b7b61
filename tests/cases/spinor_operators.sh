# Issue 15, App. C (tests/unit/test_spinor.c): discrete spinors of triangle fields on a bumpy icosphere and torus:
# the lift psi(df) is exact (S(l0, psi) = df to 1e-12), passes the pinch test on every edge with defects of the
# dihedral half-angle only, one flipped face spinor fails exactly its 3 edges; S_c(u, psi) is conformal by
# construction (C~ lambda = C~ lambda0 to 1e-12) and closes its faces; grad E_tau against central differences.
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_spinor" -malloc_dump
