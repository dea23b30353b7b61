# Issues 13 and 15: the DEC operators and the harmonic 1-form basis (tests/unit/test_dec.c): d1 d0 = 0 exactly,
# d0^T *1 d0 = L, 2g forms on an icosphere (g = 0), a torus and knot1 (1), eight (2), elephant (3), closed and
# co-closed below 1e-12, *1-orthonormal, the same span for another seed and at doubled positions, face vectors
# tangent and reproducing the form, a mesh with boundary refused.
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_dec" -malloc_dump
