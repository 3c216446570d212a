"""Rich display in Jupyter: HTML, SVG and PNG for components, compiled models, index
reports, results and linear models.

``component_html`` (schematic and parameters), ``model_html``, ``report_html``,
``result_html`` and ``statespace_html`` return HTML; ``component_svg`` the schematic
alone (``diagram`` the same as data, ``component_dot`` as Graphviz text), ``blt_svg``
the incidence in BLT order, ``result_png`` and ``bode_png`` PNG bytes.  ``show(obj)``
wraps any of these objects for a notebook cell; the classes' ``_repr_html_`` methods
call the same functions.
"""
from .html import (component_html, model_html, report_html, result_html, show,
                   statespace_html, units_of)
from .plots import blt_svg, bode_png, result_png
from .schematic import Schematic, component_dot, component_svg, diagram

__all__ = ["component_html", "model_html", "report_html", "result_html", "statespace_html",
           "show", "units_of", "blt_svg", "bode_png", "result_png", "Schematic", "diagram",
           "component_dot", "component_svg"]
