"""Modelica.Electrical.Analog.Examples.ShowSaturatingInductor (MSL v4.0.0): a
saturating inductor and a linear one of its nominal inductance in parallel on a
cosine-phased sine source of 1.25 V at 1/(2 pi) Hz."""
import math

import acausal as ac
from acausal.library.electrical import Ground, Inductor, SaturatingInductor, SineVoltage

__all__ = ["ShowSaturatingInductor"]

Lzer = 2.0                   # inductance near current = 0 (H)
Lnom = 1.0                   # nominal inductance at nominal current (H)
Inom = 1.0                   # nominal current (A)
Linf = 0.5                   # inductance at large currents (H)
U = 1.25                     # source voltage, peak (V)
f = 1 / (2 * math.pi)        # source frequency (Hz)
phase = math.pi / 2          # source voltage phase shift (rad)


class ShowSaturatingInductor(ac.Component):
    """Lzer = 2 H, Lnom = 1 H at Inom = 1 A, Linf = 0.5 H; U = 1.25 V."""

    msl_name = "Modelica.Electrical.Analog.Examples.ShowSaturatingInductor"
    stop_time = 6.2832
    tolerance = 1e-6

    SineVoltage1 = SineVoltage(V=U, phase=phase, f=f)
    Ground1 = Ground()
    SaturatingInductance1 = SaturatingInductor(Lzer=Lzer, Lnom=Lnom, Inom=Inom, Linf=Linf,
                                               i={"fixed": True})
    Inductance1 = Inductor(L=Lnom, i={"fixed": True})

    def equations(self):
        c = ac.connect
        return [c(self.SineVoltage1.n, self.Ground1.p),
                c(self.SineVoltage1.n, self.SaturatingInductance1.n),
                c(self.SaturatingInductance1.p, self.SineVoltage1.p),
                c(self.Inductance1.p, self.SineVoltage1.p),
                c(self.Inductance1.n, self.SineVoltage1.n)]


if __name__ == "__main__":
    res = ac.simulate(ShowSaturatingInductor(), t_end=6.2832, rtol=1e-6)
    print(f"SaturatingInductance1.i at {res.t[-1]:g} s: "
          f"{res['SaturatingInductance1.i'][-1]:.6g} A")
