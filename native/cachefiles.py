"""The compile cache on disk: where it is, whether it may be trusted, files that carry
their own checksum, shared libraries loaded only once verified, and pruning.

**Where.**  :func:`root` is ``$ACAUSAL_CACHE`` or ``~/.cache/acausal``, created private
(mode 0700).  It is used only when it is a directory of this user that no one else may
write (not group- or world-writable), and so is every sub-directory and file read from
it: a file owned by another user is never loaded.  A cache that cannot be created,
written or trusted is skipped, with one :class:`~acausal.errors.CacheWarning` per
process naming the directory and why; the compile, the run and the step loop then work
without it (a C library is then built in a private temporary directory, loaded, and the
directory removed at once, :func:`transient_build_dir`).

**Sealed files.**  A model's entry and its side file are written as :func:`seal` makes
them: a header, the SHA-256 of the payload and the payload.  :func:`read_sealed` checks
the header, the owner and the checksum before anything is unpickled; a file that fails
is removed, with one line saying so, and the model is compiled again.

**Libraries.**  A shared library is written with a side file ``<library>.sha256`` (the
SHA-256 of its bytes, written before the library is renamed into place, both
atomically: gcc builds the same bytes from the same source wherever the build directory
is, so concurrent builds of one source agree).  :func:`load_library` loads a library
only when its bytes have that checksum; a library that fails is removed (with one line
saying so; one without a checksum, quietly) and the caller builds it again.  A flipped byte,
a truncated library or a foreign one is therefore rebuilt, never mapped: a library that
dlopen would accept could compute wrong numbers, and a truncated one crashes the process
on first use (SIGBUS), which no exception handler survives.

**Pruning** (:func:`prune`): least recently used entries and libraries (each with its
side files) until the cache fits ``$ACAUSAL_CACHE_SIZE`` (:func:`size_limit`: bytes, or
with a suffix K, M, G, T, binary multiples; a malformed value is a
:class:`~acausal.errors.CacheError`), and the leftovers of killed processes (build
directories, temporary files, markers) once they are an hour old.
"""
from __future__ import annotations

import contextlib
import ctypes
import hashlib
import os
import re
import shutil
import stat
import tempfile
import time
import warnings

from ..errors import CacheError, CacheWarning

__all__ = ["root", "subdir", "seal", "unseal", "read_sealed", "write_sealed",
           "publish_library", "library_ok", "load_library", "transient_build_dir",
           "prune", "size_limit", "DEFAULT_SIZE", "LEFTOVER_AGE"]

DEFAULT_SIZE = 512 * 2**20
LEFTOVER_AGE = 3600.0        # s: a build directory or temporary file older is a leftover
_HEADER = b"acausal cache entry 1\n"
_DIGEST = hashlib.sha256().digest_size
_SUM = ".sha256"             # a library's checksum file: <library>.sha256
_LEFTOVERS = ("build_", ".tmp-", "cbdf-building")

_refused: dict = {}          # directory -> why it is not used (warned once)
_verified: dict = {}         # library path -> (inode, size, mtime) of the bytes checked
_transient: dict = {}        # library path -> handle: built outside a cache, loaded, removed


# -- where, and whether it may be trusted --------------------------------------------------
def _configured() -> str:
    return os.environ.get("ACAUSAL_CACHE") or os.path.join(
        os.path.expanduser("~"), ".cache", "acausal")


def root() -> str | None:
    """The cache directory, created private (0700) if need be, or None when it cannot be
    used (warned once per directory, naming it and why)."""
    return _usable(_configured())


def subdir(name: str) -> str | None:
    """A sub-directory of the cache (created private), or None as :func:`root`."""
    top = root()
    return None if top is None else _usable(os.path.join(top, name))


def _usable(path: str) -> str | None:
    if path in _refused:
        return None
    try:
        os.makedirs(path, mode=0o700, exist_ok=True)
        st = os.stat(path)
        why = _untrusted(st, directory=True)
        if why is None and not os.access(path, os.W_OK | os.X_OK):
            why = "it is not writable"
    except OSError as exc:
        why = exc.strerror or str(exc)
    if why is not None:
        refuse(path, why)
        return None
    return path


def _untrusted(st, directory: bool = False) -> str | None:
    """Why a file or directory with this stat is not trusted, or None."""
    if hasattr(os, "getuid") and st.st_uid != os.getuid():
        return f"it belongs to user {st.st_uid}, not to this user ({os.getuid()})"
    if directory and not stat.S_ISDIR(st.st_mode):
        return "it is not a directory"
    if directory and st.st_mode & (stat.S_IWGRP | stat.S_IWOTH):
        return f"others may write to it (mode {stat.S_IMODE(st.st_mode):o})"
    return None


def refuse(path: str, why: str) -> None:
    """Stop using the cache directory ``path`` in this process, with one warning."""
    if path in _refused:
        return
    _refused[path] = why
    warnings.warn(f"the compile cache {path} cannot be used ({why}); compiling and "
                  "running without it", CacheWarning, stacklevel=4)


def _say(what: str) -> None:
    warnings.warn(what, CacheWarning, stacklevel=4)


# -- sealed files: header, checksum, payload ------------------------------------------------
def seal(data: bytes) -> bytes:
    return _HEADER + hashlib.sha256(data).digest() + data


def unseal(blob: bytes) -> bytes | None:
    """The payload of a sealed file, or None when it is not whole."""
    head = len(_HEADER) + _DIGEST
    if len(blob) < head or not blob.startswith(_HEADER):
        return None
    data = blob[head:]
    if hashlib.sha256(data).digest() != blob[len(_HEADER):head]:
        return None
    return data


def read_sealed(path: str, what: str = "entry") -> bytes | None:
    """The payload of the sealed file ``path``; None when it is absent, or (removed, with
    one line saying so) when it is damaged or not this user's."""
    try:
        with open(path, "rb") as f:
            why = _untrusted(os.fstat(f.fileno()))
            blob = f.read() if why is None else b""
    except OSError:
        return None
    if why is not None:
        _say(f"the compile cache {what} {path} is not loaded: {why}")
        return None
    data = unseal(blob)
    if data is None:
        _remove(path)
        _say(f"the compile cache {what} {path} failed its checksum; removed, "
             "compiling again")
    return data


def discard(path: str, what: str, why: str) -> None:
    """Remove the cache file ``path``, which is whole but wrong, with one line saying so."""
    _remove(path)
    _say(f"the compile cache {what} {path} {why}; removed, compiling again")


def write_sealed(path: str, data: bytes) -> bool:
    """Write ``data`` sealed to ``path`` atomically; False (and the cache refused, with
    one warning) when the directory cannot be written."""
    try:
        _atomic_write(path, seal(data))
        return True
    except OSError as exc:
        refuse(os.path.dirname(path), exc.strerror or str(exc))
        return False


def _atomic_write(path: str, data: bytes) -> None:
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".tmp-")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        _remove(tmp)
        raise


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.remove(path)


# -- shared libraries ----------------------------------------------------------------------
def _file_digest(path: str) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def publish_library(built: str, path: str) -> None:
    """Move the library ``built`` (whole) to ``path`` in the cache, its checksum first:
    a process that finds the library finds its checksum."""
    _atomic_write(path + _SUM, _file_digest(built).encode())
    os.replace(built, path)
    with contextlib.suppress(OSError):
        st = os.stat(path)
        _verified[path] = (st.st_ino, st.st_size, st.st_mtime_ns)


def library_ok(path: str) -> bool:
    """Whether the library ``path`` is there and whole (its bytes have the checksum
    recorded when it was written).  A library that fails is removed, with one line
    saying so; False then tells the caller to build it again."""
    try:
        st = os.stat(path)
    except OSError:
        return path in _transient
    stamp = (st.st_ino, st.st_size, st.st_mtime_ns)
    if _verified.get(path) == stamp:
        return True
    why = _untrusted(st)
    if why is not None:
        _say(f"the C library {path} in the compile cache is not loaded: {why}")
        return False
    try:
        with open(path + _SUM, "rb") as f:
            recorded = f.read().strip().decode("ascii", "replace")
            owner = _untrusted(os.fstat(f.fileno()))
        actual = _file_digest(path)
    except OSError:
        recorded, owner, actual = None, None, ""
    if recorded == actual and owner is None:
        _verified[path] = stamp
        return True
    _remove(path)
    _remove(path + _SUM)
    if recorded is not None:      # without one: written before checksums were kept
        _say(f"the C library {path} in the compile cache failed its checksum; removed, "
             "building it again")
    return False


def load_library(path: str):
    """``ctypes.CDLL(path)`` once the library is verified (:func:`library_ok`); raises
    OSError when it is not (the caller builds it again)."""
    handle = _transient.get(path)
    if handle is not None:
        return handle
    if not library_ok(path):
        raise OSError(f"{path} is not there, or not whole")
    return ctypes.CDLL(path)


@contextlib.contextmanager
def transient_build_dir():
    """A private temporary directory for a build when there is no cache to build into;
    removed when the block ends."""
    path = tempfile.mkdtemp(prefix="acausal-build-")
    try:
        yield path
    finally:
        shutil.rmtree(path, ignore_errors=True)


def load_transient(name: str, built: str):
    """Load the library ``built`` in a :func:`transient_build_dir` now (before the
    directory goes: the mapping stays valid), known as ``name`` for the rest of the
    process (:func:`load_library`)."""
    handle = _transient.get(name)
    if handle is None:
        handle = _transient[name] = ctypes.CDLL(built)
    return handle


# -- pruning --------------------------------------------------------------------------------
_SIZE = re.compile(r"^\s*(\d+)\s*([kmgt]?)(i?b)?\s*$", re.IGNORECASE)


def size_limit() -> int:
    """``$ACAUSAL_CACHE_SIZE`` in bytes (default 512 MiB): a whole number, optionally
    followed by K, M, G or T (binary multiples: 2**10 ...; ``KiB``, ``MB`` and the like
    also read so); raises :class:`~acausal.errors.CacheError` on anything else."""
    text = os.environ.get("ACAUSAL_CACHE_SIZE")
    if text is None or not text.strip():
        return DEFAULT_SIZE
    m = _SIZE.match(text)
    if m is None:
        raise CacheError(f"ACAUSAL_CACHE_SIZE={text!r} is not a size: give a number of "
                         "bytes, optionally with a suffix K, M, G or T (e.g. 512M)")
    return int(m.group(1)) * 1024 ** " kmgt".index((m.group(2) or " ").lower())


def prune(top: str) -> None:
    """Remove least recently used entries and libraries until the cache fits its size
    (an entry's side file and a library's checksum go with it, and count with it), and
    leftovers of killed builds and writes older than :data:`LEFTOVER_AGE`."""
    limit = size_limit()
    now = time.time()
    items = []
    for d in (top, os.path.join(top, "models")):
        try:
            entries = list(os.scandir(d))
        except OSError:
            continue
        for entry in entries:
            name = entry.name
            try:
                st = entry.stat(follow_symlinks=False)
            except OSError:
                continue
            if name.startswith(_LEFTOVERS):
                if now - st.st_mtime > LEFTOVER_AGE:
                    if entry.is_dir(follow_symlinks=False):
                        shutil.rmtree(entry.path, ignore_errors=True)
                    else:
                        _remove(entry.path)
                continue
            if name.endswith((".programs.pkl", _SUM)):
                continue
            if name.endswith((".so", ".pkl")) or name.startswith("tree-"):
                size, paths = st.st_size, [entry.path]
                side = entry.path[:-len(".pkl")] + ".programs.pkl" \
                    if name.endswith(".pkl") else entry.path + _SUM
                if not name.startswith("tree-"):
                    paths.append(side)
                    with contextlib.suppress(OSError):
                        size += os.stat(side).st_size
                items.append((st.st_mtime, paths, size))
    total = sum(s for _, _, s in items)
    for _, paths, size in sorted(items):
        if total <= limit:
            break
        for p in paths:     # a library still named by an entry is rebuilt on load
            _remove(p)
        total -= size
