# Texture coordinates (issue 38): the generators' UVs have no face across a seam, distributed they reach every
# corner, and the texture distortion Q is 1 for identity UVs, s for a stretch by s, R/r on the torus (O(h^2)).
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_TESTS/test_texture"
