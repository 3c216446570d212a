"""FMI 2.0 export: a compiled model as a Model Exchange or Co-Simulation FMU.

``export_fmu(model, path, fmi_type="ModelExchange")`` writes a ``.fmu`` (zip) with a
``modelDescription.xml`` (:mod:`.description`, dependencies from :mod:`.structure`), a
binary for this platform built (:mod:`.ccode`) from the generated C of the model and
the C sources of this package (``modes.c``: Newton on the algebraic unknowns, the
event indicators and the relations' modes; ``engine.c``: derivatives, the event
iteration, the initial system; ``discrete.c``: discrete variables and sample() clocks; ``cosim.c``: the embedded
integrator of Co-Simulation; ``fmu.c``: the FMI functions),
and those sources in ``sources/`` so that the FMU can be rebuilt elsewhere.  The FMI
headers are those that fmpy ships.
"""
from .export import FMI_TYPES, export_fmu

__all__ = ["export_fmu", "FMI_TYPES"]
