# Conformal-constraint operators (issue 3): X = C Dlambda vs finite differences, C A u = 0, X f = X t = X (w x f) = 0,
# vertex-star sums of C lambda = 0, H^2 shell = assembled, H 1 = *0 1, I_Q > 0, fairing gradient (tests/unit).
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_TESTS/test_willmore_operators"
