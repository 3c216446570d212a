"""Hunting of a railway wheelset (the DAE notes, chapter 5, section 5.9).

``UnsuspendedWheelset``: the BA004 wheelset with conical wheels (delta = 0.05) at
V = 20 m/s without lateral suspension, started 1 mm off centre.  The centred running
is unstable: the hunting oscillation (about 1.2 Hz) grows until the flanges, a stiff
spring outside the clearance y_f = 9.1 mm, hold it on a limit cycle just past y_f, as
the notes' Figure 5.3 describes.  ``SuspendedWheelset`` (V = 100 m/s, k_s = 1.823 MN/m,
Figure 5.4) runs back to the centre; with delta = 0.08 (Figure 5.5) it would hunt.
``UnsuspendedWheelsetDAE`` is the first case in the notes' own index-3 formulation
(``WheelsetDAE``: contact constraints, multipliers, the nonlinear creep law), the spin
perturbation started at its centred value V s_0 tan(delta) / (r_0 (r_0 - s_0 tan(delta))).

``python -m acausal.library.multibody3d.examples.wheelset`` simulates both and prints
the eigenvalues at the three operating points of section 5.9.
"""
import numpy as np

import acausal as ac
from acausal.library.multibody3d.wheelset import Wheelset
from acausal.library.multibody3d.wheelset_dae import WheelsetDAE

__all__ = ["UnsuspendedWheelset", "SuspendedWheelset", "UnsuspendedWheelsetDAE"]


class UnsuspendedWheelset(ac.Component):
    """V = 20 m/s, no lateral suspension, delta = 0.05, y(0) = 1 mm."""

    stop_time = 20.0
    wheelset = Wheelset(V=20.0, k_s=0.0, delta=0.05, y=0.001)


class SuspendedWheelset(ac.Component):
    """V = 100 m/s, k_s = 1.823 MN/m, delta = 0.05, y(0) = 5 mm."""

    stop_time = 2.0
    wheelset = Wheelset(V=100.0, k_s=1.823e6, delta=0.05, y=0.005)


class UnsuspendedWheelsetDAE(ac.Component):
    """V = 20 m/s, no lateral suspension, delta = 0.05, y(0) = 1 mm, in the notes'
    index-3 form."""

    stop_time = 12.0
    wheelset = WheelsetDAE(V=20.0, k_s=0.0, delta=0.05, beta=0.14)


if __name__ == "__main__":
    for model, y in ((UnsuspendedWheelset, "wheelset.y"), (SuspendedWheelset, "wheelset.y"),
                     (UnsuspendedWheelsetDAE, "wheelset.q[0]")):
        res = ac.simulate(model(), model.stop_time, rtol=1e-8)
        late = res.t > 0.75 * model.stop_time
        print(f"{model.__name__}: max |y| over the last quarter "
              f"{np.abs(res[y][late]).max() * 1e3:.3f} mm")
    compiled = ac.compile(SuspendedWheelset())
    for delta, V, k_s in ((0.05, 100.0, 1.823e6), (0.08, 100.0, 1.823e6), (0.05, 20.0, 1.0)):
        poles = ac.linearize(compiled, at={"wheelset.delta": delta, "wheelset.V": V,
                                           "wheelset.k_s": k_s}).poles()
        print(f"delta = {delta}, V = {V} m/s, k_s = {k_s:g} N/m: hunting "
              f"{poles[np.argmax(poles.real)]:.4f} 1/s")
