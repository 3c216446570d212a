"""The compiled step loop's shared layouts, as C and as Python see them.

``cbdf_state`` is declared once, in ``solvers/cbdf.h``, and Python builds its
ctypes.Structure from that text (``solvers/cbdf_layout.py``).  Here the C compiler
itself says where every field lies (``offsetof``, ``sizeof``, compiled from the same
header) and ctypes must agree field by field; the installed library's own ``sizeof``
too.  The dynamic state sets' arrays (``cbdf_dyn.c``'s header) are checked by their
effect: the quality the C test computes from the arrays ``cbdf_dyn.layout`` writes is
the quality computed here with numpy."""
import ctypes
import os
import subprocess

import numpy as np
import pytest

from acausal import native
from acausal.solvers import cbdf_dyn, cbdf_layout, cbdf_library
from acausal.solvers.cbdf_layout import FIELDS, CbdfState

HERE = os.path.dirname(os.path.abspath(cbdf_layout.__file__))


def test_every_field_is_read_from_the_header():
    names = [name for name, _, _ in FIELDS]
    assert len(names) == len(set(names)) > 90
    assert {"tn", "phi", "orders", "residual_fn", "dyn_longs"} <= set(names)
    # nothing of the platform's `long`: 8-byte integers and pointers everywhere
    assert all(t in ("double", "int64_t") or t.endswith("*") for _, t, _ in FIELDS)
    assert all(ctypes.sizeof(kind) % 8 == 0 for _, _, kind in FIELDS)


@pytest.mark.skipif(native.find_compiler() is None, reason="no C compiler")
def test_the_compiler_and_ctypes_place_every_field_alike(tmp_path):
    lines = ['#include <stddef.h>', '#include <stdio.h>', '#include "cbdf.h"',
             "int main(void) {", '  printf("size %zu\\n", sizeof(cbdf_state));']
    lines += [f'  printf("{name} %zu %zu\\n", offsetof(cbdf_state, {name}), '
              f"sizeof(((cbdf_state *)0)->{name}));" for name, _, _ in FIELDS]
    lines += ["  return 0;", "}"]
    src, exe = tmp_path / "layout.c", tmp_path / "layout"
    src.write_text("\n".join(lines) + "\n")
    subprocess.run([native.find_compiler(), "-std=c99", "-I", HERE, "-o", str(exe), str(src)],
                   check=True, capture_output=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    c_view = {}
    for line in out.splitlines():
        name, *numbers = line.split()
        c_view[name] = tuple(int(x) for x in numbers)
    assert c_view.pop("size") == (ctypes.sizeof(CbdfState),)
    py_view = {name: (getattr(CbdfState, name).offset, getattr(CbdfState, name).size)
               for name, _, _ in FIELDS}
    assert c_view == py_view


def test_the_installed_library_has_this_layout():
    lib = cbdf_library.library()
    if lib is None:
        pytest.skip("the compiled step loop is not installed")
    assert lib.cbdf_state_size() == ctypes.sizeof(CbdfState)
    assert lib.cbdf_source_digest().decode() == cbdf_library.source_digest()


def _quality(block, scale, keep):
    """The quality of a choice of columns, as acausal.runtime.dynamic defines it: each
    scaled row normalized to a largest entry of one, |det| of the chosen columns over
    the product of the rows' norms."""
    rows = block * scale
    rows = rows / np.abs(rows).max(axis=1, keepdims=True)
    return abs(np.linalg.det(rows[:, keep])) / np.prod(np.linalg.norm(rows, axis=1))


def test_the_dynamic_state_test_reads_the_arrays_python_writes():
    lib = cbdf_library.library()
    if lib is None:
        pytest.skip("the compiled step loop is not installed")
    lib.dyn_keeps.restype = ctypes.c_int
    lib.dyn_keeps.argtypes = [ctypes.c_void_p, ctypes.c_int64, ctypes.c_void_p,
                              ctypes.c_void_p]
    rng = np.random.default_rng(3)
    block = rng.standard_normal((2, 3))
    scale, keep = np.array([1.0, 10.0, 0.5]), [2, 0]
    vals = np.concatenate([block.ravel(), [7.0]])          # one unrelated value after
    entries = [[0, 1, 2], [3, 4, 5]]
    q = _quality(block, scale, keep)
    for threshold, kept in ((0.99 * q, 1), (1.01 * q, 0)):
        dl, dd = cbdf_dyn.layout([(entries, scale.tolist(), keep, threshold)])
        got = lib.dyn_keeps(vals.ctypes.data, len(vals), dl.ctypes.data, dd.ctypes.data)
        assert got == kept
