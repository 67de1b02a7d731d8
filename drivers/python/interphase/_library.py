"""The shared library libinterphase (the C interface of include/interphase.h) through ctypes.

Where it is looked for, in this order:

1. the file named by the environment variable INTERPHASE_LIBRARY;
2. next to an installed package: the path `cmake --install` wrote into _installed.py;
3. in a build tree of the source tree this package sits in (build/release, build/debug);
4. by the system's loader (libinterphase.so.0 on LD_LIBRARY_PATH or in the loader's cache).
"""

import ctypes
import hashlib
import os
import pathlib
import threading
import time

from . import _status

_c_double_p = ctypes.POINTER(ctypes.c_double)
_c_size_t_p = ctypes.POINTER(ctypes.c_size_t)

#: bytes of a detail buffer: every message of the library fits in 256 characters and a NUL
DETAIL_LEN = 257


def _candidates():
    """(where, path) pairs to try, in order."""
    here = pathlib.Path(__file__).resolve().parent
    env = os.environ.get("INTERPHASE_LIBRARY")
    if env:
        yield "INTERPHASE_LIBRARY", env
        return
    try:
        from . import _installed  # written by cmake --install
        yield "the installation", str((here / _installed.LIBRARY).resolve())
    except ImportError:
        pass
    # drivers/python/interphase in a source tree: its build directories
    root = here.parents[2]
    for build in ("build/release", "build/debug"):
        yield "the source tree's " + build, str(root / build / "libinterphase.so")
    yield "the system's loader", "libinterphase.so.0"


def _load():
    tried = []
    for where, path in _candidates():
        try:
            return ctypes.CDLL(path), path
        except OSError as error:
            tried.append(f"{path} ({where}): {error}")
    raise ImportError(
        "interphase: cannot load the shared library libinterphase; build it (cmake --build BUILD, "
        "target interphase_shared) and set INTERPHASE_LIBRARY=BUILD/libinterphase.so, or install "
        "interphase (docs/python.md). Tried:\n  " + "\n  ".join(tried))


lib, path = _load()

_int, _size, _ptr, _dbl = ctypes.c_int, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_double

lib.interphase_update_dt.restype = _int
lib.interphase_update_dt.argtypes = [_ptr, _int, _int, _ptr, _ptr, _dbl, _ptr, _ptr, _ptr, _c_double_p,
                                     ctypes.c_char_p, _size]
lib.interphase_update_increment.restype = _int
lib.interphase_update_increment.argtypes = [_ptr, _int, _int, _ptr, _ptr, _ptr, _c_double_p, _ptr, _ptr, _ptr,
                                            _c_double_p, ctypes.c_char_p, _size]
lib.interphase_update.restype = _int
lib.interphase_update.argtypes = [_ptr, _int, _int, _ptr, _ptr, _ptr, _ptr, _ptr, _c_double_p,
                                  ctypes.c_char_p, _size]
lib.interphase_run.restype = _int
lib.interphase_run.argtypes = [_ptr, _int, _int, _size, _ptr, _ptr, _ptr, _ptr, _ptr, _ptr, _ptr,
                               _c_size_t_p, ctypes.c_char_p, _size]
lib.interphase_run_history.restype = _int
lib.interphase_run_history.argtypes = [_ptr, _int, _int, _size, _ptr, _ptr, _ptr, _int, _dbl, _int, _size,
                                       _ptr, _ptr, _ptr, _ptr, _ptr, _ptr, _ptr, _c_size_t_p,
                                       ctypes.c_char_p, _size]
lib.interphase_status_message.restype = _size
lib.interphase_status_message.argtypes = [_int, ctypes.c_char_p, _size]
lib.interphase_load_table.restype = _int
lib.interphase_load_table.argtypes = [ctypes.c_char_p, ctypes.c_char_p, _size]
lib.interphase_load_rcurve.restype = _int
lib.interphase_load_rcurve.argtypes = [ctypes.c_char_p, ctypes.c_char_p, _size]


def status_message(status):
    """The library's generic message of a status code (interphase_status_message)."""
    n = lib.interphase_status_message(int(status), None, 0)
    buf = ctypes.create_string_buffer(n + 1)
    lib.interphase_status_message(int(status), buf, n + 1)
    return buf.value.decode("utf-8", "replace")


class InterphaseError(ValueError):
    """A status of the library (or of the keyword checks that stand for it), with its message.

    Attributes: `status` (the code, one of interphase.STATUS_*), `name` (its symbolic name),
    `reason` (the generic message of the code) and `detail` (which value, where, which range).
    """

    def __init__(self, status, detail=""):
        self.status = int(status)
        self.name = next((n for n, v in _status.STATUS_CODES.items() if v == self.status), str(status))
        self.reason = status_message(self.status)
        self.detail = detail
        text = f"{self.reason} ({self.name} = {self.status})"
        super().__init__(text + (": " + detail if detail else ""))

    def __reduce__(self):
        # (pickled as its status and detail, with its attributes, e.g. the rows of a failed run in
        # `result`: the default would call InterphaseError(message) and fail on int(message), so an
        # error raised in a worker process of multiprocessing or concurrent.futures would break the
        # pool, or hang multiprocessing.Pool's map, instead of being raised in the caller)
        return (type(self), (self.status, self.detail), dict(self.__dict__))


def detail_buffer():
    return ctypes.create_string_buffer(DETAIL_LEN)


def text_of(buffer):
    return buffer.value.decode("utf-8", "replace")


# The custom RVE table and the tabulated R-curve are library-wide data (the loaders are not
# thread-safe, hence data_lock below): this package loads each file when a material that names it
# is used, again when another file is named or the file has changed since it was loaded (its
# modification time, size or inode; while it is recent, its contents: a file edited and saved
# under the same name), and not otherwise.
_loaded = {"table": None, "rcurve": None}

#: Held while a table or an R-curve is loaded, and by a material that reads one (a custom table, a
#: tabulated R-curve) from the loading of its files through its library calls: another thread's
#: material can then neither replace the data under it nor load a file at the same time (the
#: loaders share Fortran units). Materials that read no file do not take it and run in parallel.
data_lock = threading.RLock()


def _new_data_lock():
    # (in a child process forked while another thread held the lock, the lock would stay held for
    # ever: the child starts with a free one; a load the fork interrupted left _loaded[kind] None,
    # so the child loads that file again before using it)
    global data_lock
    data_lock = threading.RLock()


os.register_at_fork(after_in_child=_new_data_lock)


#: how recent a modification makes a loaded file count as changed at its next use (ns): two
#: seconds, the coarsest modification-time tick of common file systems (FAT; NFS and old kernels
#: round to a second)
RACY_NS = 2_000_000_000


def _signature(path):
    """What identifies a file's contents as loaded: its absolute path and the stat fields an edit
    changes (None where it cannot be read: the loader then says why)."""
    path = os.path.abspath(path)
    try:
        st = os.stat(path)
    except OSError:
        return (path, None)
    return (path, st.st_mtime_ns, st.st_size, st.st_ino, st.st_dev, st.st_ctime_ns)


def _path_text(name, value, who="Material"):
    """The text of a path entry (os.fspath): a str, bytes or os.PathLike without a null
    character (no file name holds one), else TypeError / ValueError naming the entry."""
    if not isinstance(value, (str, bytes, os.PathLike)):
        raise TypeError(f"{who}: {name} must be a path (str, bytes or os.PathLike), got {value!r} "
                        f"({type(value).__name__})")
    path = os.fspath(value)
    if ("\0" if isinstance(path, str) else b"\0") in path:
        raise ValueError(f"{who}: {name} = {value!r} holds a null character, which no file name can hold")
    return path


def load_table(path):
    """Load the custom RVE table (tables/README.md format) for the micromechanical model."""
    _load_file("table", lib.interphase_load_table, _path_text("path", path, "load_table"))


def load_rcurve(path):
    """Load the tabulated R-curve ("D G_cI G_cII" rows) of the fracture-mechanics law."""
    _load_file("rcurve", lib.interphase_load_rcurve, _path_text("path", path, "load_rcurve"))


def _load_file(kind, loader, path):
    with data_lock:
        detail = detail_buffer()
        # (the signature and the digest before the read: an edit during it reloads)
        signature = _signature(path)
        digest = _racy_digest(path, signature)
        _loaded[kind] = None                                      # (after a failed load the next use tries again)
        status = loader(os.fsencode(path), detail, DETAIL_LEN)  # (the bytes of the name, any encoding)
        if status != _status.STATUS_OK:
            error = InterphaseError(status, text_of(detail))
            error.file_kind = kind          # (which file: read_case names its entry)
            raise error
        _loaded[kind] = (signature, digest)


def _racy_digest(path, signature):
    """The digest of a file modified within RACY_NS of now, None for an older one. Such a file may
    be rewritten again within one tick of the file system's clock with the same size, and its
    signature would not change: its contents are compared too until it is older than that (git's
    "racily clean" rule)."""
    if signature[1] is None or signature[1] < time.time_ns() - RACY_NS:
        return None
    try:
        with open(path, "rb") as file:
            return hashlib.sha256(file.read()).digest()
    except OSError:
        return b""


def loaded_path(kind):
    """The absolute path of the table or R-curve this package loaded last ("table", "rcurve"), or
    None when none is loaded (or its last load failed)."""
    entry = _loaded[kind]
    return None if entry is None else entry[0][0]


def ensure_loaded(kind, path):
    """Load `path` as the table or R-curve unless it is the one loaded, unchanged since."""
    if path is None:
        return
    with data_lock:
        signature = _signature(path)
        entry = _loaded[kind]
        if signature[1] is None or entry is None or entry[0] != signature:
            (load_table if kind == "table" else load_rcurve)(path)
        elif entry[1] is not None:
            # loaded when it had just been modified: its contents decide while it is that recent
            digest = _racy_digest(path, signature)
            if digest is None:
                _loaded[kind] = (signature, None)
            elif digest != entry[1]:
                (load_table if kind == "table" else load_rcurve)(path)
