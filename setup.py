"""The repository root is the package `acausal`: map it, and list its sub-packages."""
from setuptools import find_packages, setup

_SUB = find_packages(".", exclude=["tests*", "benchmarks*", "build*"])
setup(packages=["acausal"] + [f"acausal.{p}" for p in _SUB], package_dir={"acausal": "."})
