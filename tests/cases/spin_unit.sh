# Unit programs of issue 4: quaternion kernels, crane2013 App. G closed form, AIJ == shell == A^T M_F A,
# Y = B^T M_F A, symmetry, kernel (tests/unit/test_spin_dirac.c); repeated solves with reused EPS objects and
# with inverse iteration on a kept factorisation (tests/unit/test_spin_reuse.c).
# nprocs: 1 2
source tests/lib.sh
timeout 60 $MPIEXEC "$CS_TESTS/test_spin_dirac" -gen_level 2
timeout 60 $MPIEXEC "$CS_TESTS/test_spin_reuse"
