# Readers, writers, validation and generators of the serial mesh-data layer (tests/unit/test_meshdata.c).
# nprocs: 1
source tests/lib.sh
"$CS_TESTS/test_meshdata" -shared_meshes "$CS_SHARED/meshes"
