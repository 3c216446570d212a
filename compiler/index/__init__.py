"""Numeric checks of the structural decisions: the balance of equations and unknowns,
Pryce's success test checked exactly and the LC conversion of singular constant
blocks, index reduction and state selection joined to the symbolic system, exact and
modular ranks, and the numeric values of incidence coefficients."""
from .balance import check_balance
from .conversion import ConversionResult, convert_model
from .modp import full_row_rank_mod_p
from .numeric import CoefficientValues, is_number
from .reduction import IndexReduction, as_written, differentiate, reduce_index, select

__all__ = ["check_balance", "convert_model", "ConversionResult", "differentiate", "select",
           "reduce_index", "IndexReduction", "as_written", "full_row_rank_mod_p",
           "CoefficientValues", "is_number"]
