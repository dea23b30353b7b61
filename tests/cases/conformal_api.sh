# The conformal curvature flow (crane2013 Sec. 6) through the library API alone (tests/unit/test_conformal_api.c):
# Sec. 4's filter gain on spherical harmonics of degree 1-4 against s w^k / (1 + s w^k) for k = 0..3 to 1 %, and
# a noisy icosphere stepped in code with W falling and the direction orthogonal to 1 and N.
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_conformal_api"
