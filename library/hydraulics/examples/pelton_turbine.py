"""Hydropower plant: reservoir, penstock, nozzle and Pelton wheel (Egeland & Gravdahl
11.2.9, (11.101)-(11.114)).

Water falls h = 100 m through a penstock L = 300 m long, A_p = 1 m2, to a nozzle whose
outlet area A (the gate) sets the jet; the jet drives a Pelton wheel of radius
r_t = 1 m, held at constant speed by the grid.  At the nominal gate A_0 = 0.05 m2 the
steady flow is q_0 = A_0 sqrt(2 g h / alpha), alpha = 1 - A_0^2/A_p^2, and the wheel
turns at the speed of the most power, the bucket at half the jet speed:
r_t w_0 = q_0/(2 A_0), so beta = 1.5 (11.107).  Linearized, the torque answers the gate
with the right half-plane zero of (11.113):

    dT_t/dA = (2/gamma)(r_t rho q_0^2/A_0^2)(1 - gamma tau s)/(1 + tau s),
    tau = mu T_r/2 = L A_0^2 / (alpha q_0 A_p),   gamma = 1/(beta/alpha - 1)

(11.114 for alpha = 1, gamma = 2: a zero at 1/T_r, a pole at -2/T_r).  Opening the gate
first lowers the torque: the water column must be accelerated before more flow comes,
and the larger jet area slows the jet meanwhile.

``ElasticPeltonPlant`` swaps the rigid column for a compressible one, a ``LumpedLine``
with the speed of sound c = 1200 m/s (assumed: water in a steel pipe), fed by the
reservoir's head as a pressure rho g h at its inlet; the rest is unchanged.  Its
transfer function tends to (11.109) with H_pq = (rho c/A_p) tanh(L s/c) (11.119), the
pipe's quarter-wave resonance at pi c/(2 L) = 6.3 rad/s included.
"""
import acausal as ac
from acausal.library import rotational as rot
from acausal.library.blocks import Step

from ..lines import LumpedLine
from ..sources import FixedPressure
from ..turbines import PeltonTurbine, Penstock

__all__ = ["PeltonPlant", "ElasticPeltonPlant", "H", "L", "A_P", "A_0", "RHO", "G", "R_T",
           "ALPHA", "Q_0", "W_0", "C"]

H, L, A_P, A_0, RHO, G, R_T = 100.0, 300.0, 1.0, 0.05, 1000.0, 9.81, 1.0
C = 1200.0                                     # speed of sound in the penstock
ALPHA = 1 - A_0**2 / A_P**2
Q_0 = A_0 * (2 * G * H / ALPHA)**0.5          # steady flow: the head is all jet
W_0 = Q_0 / (2 * A_0 * R_T)                    # bucket speed half the jet speed


class PeltonPlant(ac.Component):
    """The gate opens by 10 % (a step at t = 1 s) from the steady state at A_0."""

    stop_time = 5.0
    reservoir = FixedPressure(p=0.0)
    penstock = Penstock(L=L, A_p=A_P, h=H, rho=RHO, g=G, q={"start": Q_0, "fixed": True})
    # the nozzle's flow is a state of the rigid column but solved from the pressure
    # behind a compressible one: start it at q_0
    turbine = PeltonTurbine(r_t=R_T, A_p=A_P, rho=RHO, q={"start": Q_0})
    tailwater = FixedPressure(p=0.0)
    grid = rot.ConstantSpeed(w_fixed=W_0)
    gate = Step(offset=A_0, height=0.1 * A_0, startTime=1.0)

    def equations(self):
        return [ac.connect(self.reservoir.port, self.penstock.port_a),
                ac.connect(self.penstock.port_b, self.turbine.port_a),
                ac.connect(self.turbine.port_b, self.tailwater.port),
                ac.connect(self.turbine.flange, self.grid.flange),
                ac.connect(self.gate.y, self.turbine.A)]



class ElasticPeltonPlant(PeltonPlant):
    """The same plant with a compressible penstock of 20 resonators (hybrid form: the
    reservoir's pressure at port_a, the nozzle at port_b), in steady flow at the start."""

    reservoir = FixedPressure(p=RHO * G * H)
    penstock = LumpedLine(n=20, form="hybrid", L=L, A=A_P, rho=RHO, beta=RHO * C**2,
                          p_start=RHO * G * H, q_start=Q_0)


if __name__ == "__main__":
    plant = ac.compile(PeltonPlant())
    # the wheel's angle turns on at w_0: hold it, the flow settles
    op = ac.steady_state(plant, hold=["turbine.flange.phi"])
    sys = ac.linearize(plant, inputs=["gate.offset"], outputs=["turbine.T_t"], at=op)
    sys = sys.minimal()                      # without the grid's angle, which T_t ignores
    print(f"zeros {sys.zeros()}, poles {sys.poles()}")
    res = ac.simulate(PeltonPlant(), t_end=PeltonPlant.stop_time, rtol=1e-8)
    T = res["turbine.T_t"]
    print(f"torque: {T[0]:.5g} N.m before the step, {T[res.t > 1.0].min():.5g} just after, "
          f"{T[-1]:.5g} at the end")
