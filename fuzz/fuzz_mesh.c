/* libFuzzer target for one mesh reader (FORMAT obj, off or ply, chosen at compile time: fuzz/Makefile.inc): the
   input is parsed as a file of that format and, when it parses, validated, as CSMeshDataRead and the validation do
   for a real file. Errors are expected (PetscReturnErrorHandler keeps them quiet); crashes, sanitizer reports,
   leaks and hangs are findings. */
#include "../src/mesh/meshdata_reader.h"
#include <sanitizer/lsan_interface.h>
#include <stdint.h>
#include <string.h>

#define STR2(x) #x
#define STR(x)  STR2(x)

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  (void)argc;
  (void)argv;
  int bad;
  setenv("OMPI_MCA_plm", "isolated", 0); /* a singleton, no mpirun */
  __lsan_disable(); /* what MPI and PETSc keep from their start-up until exit is not a finding */
  bad = PetscInitializeNoArguments() || PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
  __lsan_enable();
  return bad;
}

static PetscErrorCode Parse(Reader *r)
{
  PetscFunctionBeginUser;
#if defined(FORMAT_obj)
  PetscCall(CSMeshDataReadOBJ(r));
#elif defined(FORMAT_off)
  PetscCall(CSMeshDataReadOFF(r));
#else
  PetscCall(CSMeshDataReadPLY(r));
#endif
  PetscFunctionReturn(0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  Reader         r;
  PetscErrorCode ierr;
  memset(&r, 0, sizeof(r));
  r.path = "fuzz." STR(FORMAT);
  if (PetscMalloc1(size + 1, &r.buf)) return 0;
  memcpy(r.buf, data, size);
  r.buf[size] = 0;
  r.len       = size;
  ierr        = Parse(&r);
  if (!ierr && !r.msg[0]) {
    CSMeshData md;
    CSTopology topo;
    memset(&md, 0, sizeof(md));
    (void)CSReaderTake(&r, &md); /* positions, faces and texture coordinates, as CSMeshDataRead */
    strcpy(md.name, r.path);
    (void)CSMeshDataValidate(&md, &topo);
    (void)CSMeshDataDestroy(&md);
  }
  (void)CSReaderFree(&r);
  return 0;
}
