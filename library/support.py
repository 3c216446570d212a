"""Conditional support flanges: the Modelica Standard Library's ``useSupport``.

In the MSL a source or a gear acts between its flange(s) and a *support* (its housing):
``Support support if useSupport``.  With ``useSupport = true`` the support is a flange
that receives the reaction (so the housing may move and must be connected); with
``useSupport = false`` there is no port and the housing is fixed (``phi_support = 0``).

Adding or removing a port is structural, so here the switch is an argument of the
constructor, not a parameter (as the number of segments of a line is):
``Torque(useSupport=True)``.  The flag is kept on the instance; the component's
equations read the support's across variable through ``support_position`` and add the
reaction equation only when the port exists.
"""
import acausal as ac

__all__ = ["SupportMixin"]


class SupportMixin:
    """Creates the support flanges listed in ``_supports`` ({port: flag}) whose flag was
    given as True, and names the flag when a missing support is used."""

    _supports: dict = {}

    def _mount(self, port_types: dict, flags: dict) -> None:
        """``port_types`` {port: port class}; ``flags`` {flag: value} as given."""
        for port, flag in self._supports.items():
            use = flags[flag]
            if not isinstance(use, bool):
                raise ac.ModelError(f"{type(self).__name__}: {flag} must be True or False, "
                                    f"not {use!r}")
            object.__setattr__(self, flag, use)
            if use:
                setattr(self, port, port_types[port]())

    def support_position(self, port: str, across: str):
        """The support's position (its across variable), 0 when it is not used."""
        return getattr(getattr(self, port), across) if self.__dict__.get(
            self._supports[port]) else 0

    def supported(self, port: str) -> bool:
        return bool(self.__dict__.get(self._supports[port]))

    def __getattr__(self, name):
        # called only for attributes that do not exist: say how to get a support
        flag = type(self)._supports.get(name)
        if flag is None:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        raise AttributeError(f"{type(self).__name__}.{name}: this {type(self).__name__} "
                             f"has no support flange ({flag}=False: its housing is fixed); "
                             f"create it with {type(self).__name__}({flag}=True) to "
                             f"connect the support")
