"""The structural passes, on integers only (never sympy): the incidence graph
(:class:`Structure`), maximum matching and the Dulmage-Mendelsohn decomposition,
Pantelides' index reduction, Pryce's Sigma-method, dummy-derivative state selection,
BLT ordering, tearing and causalization.  Each is testable on a hand-drawn graph.  The
passes named as their modules are reached through them (``structure.pantelides
.pantelides``, ``structure.blt.blt``, ``structure.causalize.causalize``)."""
from .blt import Block, strongly_connected_components
from .causalize import Causalization, full_form
from .graph import UNASSIGNED, Names, Structure
from .matching import (DMParts, StructuralDiagnosis, bipartite_matching, check_structure,
                       diagnose, dulmage_mendelsohn, make_structure, maximum_matching)
from .pantelides import PantelidesResult
from .sigma import SigmaResult, sigma_method, signature_matrix
from .states import StateSelection, StateSet, select_states
from .tearing import Tearing, tear

__all__ = ["Structure", "Names", "UNASSIGNED", "make_structure", "bipartite_matching",
           "maximum_matching", "dulmage_mendelsohn", "DMParts", "diagnose",
           "check_structure", "StructuralDiagnosis", "PantelidesResult", "signature_matrix",
           "sigma_method", "SigmaResult", "select_states", "StateSelection", "StateSet",
           "Block", "strongly_connected_components", "tear", "Tearing", "full_form",
           "Causalization"]
