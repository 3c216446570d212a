"""The repository root is the package `acausal`: map it, list its sub-packages, and build
the compiled BDF step loop (solvers/cbdf*.c) as an optional extension of the install.

The step loop is a plain shared library that acausal.solvers.cbdf_library loads with
ctypes (not a Python module).  Where no C compiler works the install goes on without it,
says so, and the Python step loop runs; the library carries the digest of the sources it
was built from, so a library older than its sources is never loaded.
"""
import hashlib
import os
import sys

from setuptools import Extension, find_packages, setup
from setuptools.command.build_ext import build_ext

_SUB = find_packages(".", exclude=["tests*", "benchmarks*", "build*"])
# the step loop's sources, whose digest names the library (cbdf_library.source_digest)
_LOOP = ("cbdf.h", "cbdf_lu.c", "cbdf_dyn.c", "cbdf_sparse.c", "cbdf.c", "cbdf_loop.c")


def _digest() -> str:
    h = hashlib.sha256()
    for name in _LOOP:
        with open(os.path.join("solvers", name), "rb") as f:
            h.update(name.encode() + b"\0" + f.read() + b"\0")
    return h.hexdigest()[:32]


class OptionalBuildExt(build_ext):
    """Build the step loop if a C compiler works; otherwise install without it."""

    def build_extension(self, ext):
        if self.compiler.compiler_type == "msvc":
            ext.extra_compile_args = ["/O2", "/fp:precise"]
        else:
            ext.extra_compile_args = ["-O2", "-std=c99", "-ffp-contract=off"]
        try:
            super().build_extension(ext)
        except Exception as exc:      # noqa: BLE001 - any failure: install without it
            sys.stderr.write(f"acausal: the compiled step loop was not built ({exc}); "
                             "simulations run the Python step loop (install a C compiler "
                             "and reinstall acausal to build it)\n")

    def get_export_symbols(self, ext):
        return []                     # a library for ctypes: no PyInit_ function

    def run(self):
        try:
            super().run()
        except Exception as exc:      # noqa: BLE001 - no compiler at all
            sys.stderr.write(f"acausal: the compiled step loop was not built ({exc}); "
                             "simulations run the Python step loop\n")


setup(packages=["acausal"] + [f"acausal.{p}" for p in _SUB], package_dir={"acausal": "."},
      package_data={"acausal": ["py.typed"], "acausal.fmi": ["*.c", "*.h"],
                    "acausal.solvers": ["*.c", "*.h"]},
      ext_modules=[Extension("acausal.solvers._cbdf", ["solvers/cbdf_loop.c"],
                             depends=[os.path.join("solvers", n) for n in _LOOP],
                             define_macros=[("CBDF_SOURCE_DIGEST", f'"{_digest()}"')],
                             optional=True)],
      cmdclass={"build_ext": OptionalBuildExt})
