"""Rotating stall and surge of an axial compression system, the Moore-Greitzer model
(Egeland & Gravdahl 14.1.2, (14.1)-(14.4), Figures 14.2-14.3).

The compressor delivers into a plenum that empties through a throttle; all in the
book's normalized variables: the plenum pressure Psi, the flow coefficient Phi and the
squared stall amplitude J, and normalized time.  The laboratory compressor of the book:
H = 0.18, W = 0.25, psi_c0 = 0.30, sigma = 0.38, gamma_T = 0.5, l_c = 2, started at
Psi = Phi = 0.6, J = 0.1.  Greitzer's B decides what the operating point falls into:

* B = 0.1 (a small plenum): rotating stall, an equilibrium with J > 0 (Psi = 0.4133,
  Phi = 0.3215, J = 3.673);
* B = 1: surge, a limit cycle of Phi and Psi with reverse flow (Phi down to -0.19), in
  which the stall amplitude dies out (J -> 0); its period is about 33.2.
"""
import acausal as ac

from ..compressors import Ambient, CompressorThrottle, MooreGreitzerCompressor, Plenum

__all__ = ["RotatingStall", "Surge", "H", "W", "PSI_C0", "SIGMA", "GAMMA_T", "L_C"]

H, W, PSI_C0, SIGMA, GAMMA_T, L_C = 0.18, 0.25, 0.30, 0.38, 0.5, 2.0


class _CompressionSystem(ac.Component):
    """inlet -> compressor -> plenum -> throttle -> outlet, started at the book's
    Psi = Phi = 0.6, J = 0.1; the plenum (its B) is declared by the subclass."""

    inlet = Ambient()
    compressor = MooreGreitzerCompressor(H=H, W=W, psi_c0=PSI_C0, sigma=SIGMA, l_c=L_C,
                                         phi={"start": 0.6, "fixed": True},
                                         J={"start": 0.1, "fixed": True})
    throttle = CompressorThrottle(gamma_T=GAMMA_T)
    outlet = Ambient()

    def equations(self):
        return [ac.connect(self.inlet.port, self.compressor.port_a),
                ac.connect(self.compressor.port_b, self.plenum.port, self.throttle.port_a),
                ac.connect(self.throttle.port_b, self.outlet.port)]


class RotatingStall(_CompressionSystem):
    """B = 0.1: the compressor falls into rotating stall (Figure 14.2)."""

    plenum = Plenum(B=0.1, l_c=L_C, psi={"start": 0.6, "fixed": True})
    stop_time = 300.0


class Surge(_CompressionSystem):
    """B = 1: the compressor surges (Figure 14.3)."""

    plenum = Plenum(B=1.0, l_c=L_C, psi={"start": 0.6, "fixed": True})
    stop_time = 300.0


if __name__ == "__main__":
    for model in (RotatingStall, Surge):
        res = ac.simulate(model(), t_end=model.stop_time, rtol=1e-8)
        late = res.t > model.stop_time / 2
        print(f"{model.__name__}: Psi in [{res['plenum.psi'][late].min():.4f}, "
              f"{res['plenum.psi'][late].max():.4f}], Phi in "
              f"[{res['compressor.phi'][late].min():.4f}, {res['compressor.phi'][late].max():.4f}],"
              f" J at the end {res['compressor.J'][-1]:.4g}")
