"""Native code behind one door: the C compiler, building C into shared libraries (one
translation unit, or several side by side), the cache where they live, and loading
them -- shared by the C backend's generated models and the solvers' compiled step loop,
which is built when acausal is installed (:func:`installed_library`)."""
from .build import Build, build_library, library_path, start
from .load import installed_library
from .toolchain import cache_dir, find_compiler

__all__ = ["find_compiler", "cache_dir", "start", "Build", "build_library", "library_path",
           "installed_library"]
