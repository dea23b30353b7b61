"""ctypes bindings of build/libconfsurf.so (include/cs_api.h): loading, PETSc start-up once per process."""
import atexit
import ctypes
import os

_c_double_p = ctypes.POINTER(ctypes.c_double)
_c_long_p = ctypes.POINTER(ctypes.c_long)


def _find():
    """CONFSURF_LIB, else build/libconfsurf.so of the checkout this package lies in (python/confsurf/..)."""
    path = os.environ.get("CONFSURF_LIB")
    if path:
        return path
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    return os.path.join(root, "build", "libconfsurf.so")


def _declare(lib):
    sig = {
        "CSApiInitialize": (ctypes.c_int, []),
        "CSApiFinalize": (ctypes.c_int, []),
        "CSApiRank": (ctypes.c_int, []),
        "CSApiSize": (ctypes.c_int, []),
        "CSApiRun": (ctypes.c_int, [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_int,
                                    ctypes.c_long, _c_double_p, ctypes.c_long, _c_long_p,
                                    ctypes.c_long, _c_double_p, _c_long_p,
                                    ctypes.c_long, _c_double_p,
                                    ctypes.c_long, _c_double_p, ctypes.c_int, ctypes.c_char_p]),
        "CSApiLastError": (ctypes.c_char_p, []),
        "CSApiLastErrorIsInput": (ctypes.c_int, []),
        "CSApiResultSummary": (ctypes.c_char_p, []),
        "CSApiResultPositions": (_c_double_p, [_c_long_p, _c_long_p]),
        "CSApiResultFaces": (_c_long_p, [_c_long_p]),
        "CSApiResultHistory": (_c_double_p, [ctypes.POINTER(ctypes.c_char_p), _c_long_p, _c_long_p]),
        "CSApiRelease": (ctypes.c_int, []),
        "CSApiGlobalOptionsCount": (ctypes.c_long, []),
        "CSApiPetscMemory": (ctypes.c_double, []),
    }
    for name, (res, args) in sig.items():
        f = getattr(lib, name)
        f.restype, f.argtypes = res, args


def _load():
    """The library (RTLD_GLOBAL: Open MPI's plugins need libmpi's symbols); at import, so that a missing build fails
    there with the command that makes it."""
    path = _find()
    if not os.path.exists(path):
        raise ImportError(f"confsurf: {path} not found: run `make` in the checkout (or set CONFSURF_LIB)")
    handle = ctypes.CDLL(path, mode=ctypes.RTLD_GLOBAL)
    _declare(handle)
    return handle


_handle = _load()
_started = False


def lib():
    """The library, PETSc/SLEPc (and MPI, unless mpi4py started it) initialised on first use."""
    global _started
    if not _started:
        rc = _handle.CSApiInitialize()
        if rc:
            raise RuntimeError(f"confsurf: PETSc/SLEPc initialisation failed (error {rc})")
        atexit.register(_handle.CSApiFinalize)
        _started = True
    return _handle
