"""The repository root is the package `acausal`: map it, and list its sub-packages."""
from setuptools import find_packages, setup

_SUB = find_packages(".", exclude=["tests*", "benchmarks*", "build*"])
# the C sources of the FMU engine are compiled into every exported FMU, the compiled BDF
# step loop (solvers/cbdf.c) once into the C backend's cache
setup(packages=["acausal"] + [f"acausal.{p}" for p in _SUB], package_dir={"acausal": "."},
      package_data={"acausal": ["py.typed"], "acausal.fmi": ["*.c", "*.h"],
                    "acausal.solvers": ["*.c"]})
