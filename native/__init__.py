"""Native code behind one door: the C compiler, building C into shared libraries (one
translation unit, or several side by side), and the cache where they live -- shared by
the C backend's generated models and the solvers' compiled step loop."""
from .build import Build, build_library, library_path, start
from .toolchain import cache_dir, find_compiler

__all__ = ["find_compiler", "cache_dir", "start", "Build", "build_library", "library_path"]
