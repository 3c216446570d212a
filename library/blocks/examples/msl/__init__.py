"""Modelica.Blocks.Examples (MSL v4.0.0) written with acausal's blocks, each compared with
the MSL's reference result by ``tests/msl``."""
