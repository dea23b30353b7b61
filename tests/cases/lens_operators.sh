# Issue 15, operators: the lens complex (tests/unit/test_lens.c): C~ A~ = 0 and rank C~ = |H| - |V| (soliman2021
# Lemma A.1) on a small icosphere and torus, C~ lambda(df) = C lambda(f), d1 df = 0 and one moved halfedge breaking
# exactly one lens, W~(df) = W(f) to 1e-12 (App. D.1), the face closure of df = 0 and the Poisson reconstruction
# L f = d*omega of df = f to 1e-12 (Algorithm 2).
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_lens" -malloc_dump
