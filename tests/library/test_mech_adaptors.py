"""Signal adaptors of the flanges (MSL Rotational TorqueToAngleAdaptor,
AngleToTorqueAdaptor; Translational GeneralForceToPositionAdaptor,
GeneralPositionToForceAdaptor) and the blocks of the GenerationOfFMUs examples built
with them: two inertias coupled through a spring block, against scipy's DOP853 on the
same two-mass equations; a direct inertia against its integral."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import rotational as rot
from acausal.library import translational as tr
from acausal.library.blocks import Constant, Sine
from acausal.library.rotational.adaptors import AngleToTorqueAdaptor, TorqueToAngleAdaptor
from acausal.library.rotational.examples.msl import utilities as rot_util
from acausal.library.translational.adaptors import (GeneralForceToPositionAdaptor,
                                                     GeneralPositionToForceAdaptor)
from acausal.library.translational.examples.msl import utilities as tr_util

J_A, J_B, C, AMP, F = 1.1, 2.2, 1e4, 10.0, 2.0


def two_masses(t):
    """J_A phi_a'' = AMP sin(2 pi F t) - C (phi_a - phi_b),  J_B phi_b'' = C (phi_a - phi_b)."""
    def rhs(t, y):
        spring = C * (y[0] - y[1])
        return [y[2], y[3], (AMP * np.sin(2 * np.pi * F * t) - spring) / J_A, spring / J_B]
    return solve_ivp(rhs, (t[0], t[-1]), [0, 0, 0, 0], t_eval=t, method="DOP853",
                     rtol=1e-12, atol=1e-14).y


class RotationalThree(ac.Component):
    """The third system of Rotational.Examples.GenerationOfFMUs."""

    sine1 = Sine(f=F, amplitude=AMP)
    inertia3a = rot.Inertia(J=J_A, phi={"fixed": True, "start": 0.0},
                            w={"fixed": True, "start": 0.0})
    force3 = rot.Torque()
    torqueToAngle3a = TorqueToAngleAdaptor(use_w=False, use_a=False)
    spring = rot_util.Spring(c=C)
    inertia3b = rot.Inertia(J=J_B, phi={"fixed": True, "start": 0.0},
                            w={"fixed": True, "start": 0.0})
    torqueToAngle3b = TorqueToAngleAdaptor(use_w=False, use_a=False)

    def equations(self):
        return [ac.connect(self.sine1.y, self.force3.tau),
                ac.connect(self.inertia3a.flange_b, self.torqueToAngle3a.flange),
                ac.connect(self.force3.flange, self.inertia3a.flange_a),
                ac.connect(self.torqueToAngle3b.flange, self.inertia3b.flange_a),
                ac.connect(self.torqueToAngle3a.phi, self.spring.phi1),
                ac.connect(self.torqueToAngle3a.tau, self.spring.tau1),
                ac.connect(self.spring.phi2, self.torqueToAngle3b.phi),
                ac.connect(self.spring.tau2, self.torqueToAngle3b.tau)]


class TranslationalThree(ac.Component):
    """The third system of Translational.Examples.GenerationOfFMUs."""

    sine1 = Sine(f=F, amplitude=AMP)
    mass3a = tr.Mass(m=J_A, s={"fixed": True, "start": 0.0}, v={"fixed": True, "start": 0.0})
    force3 = tr.Force()
    forceToPosition3a = GeneralForceToPositionAdaptor(use_pder=False, use_pder2=False)
    spring = tr_util.Spring(c=C)
    mass3b = tr.Mass(m=J_B, s={"fixed": True, "start": 0.0}, v={"fixed": True, "start": 0.0})
    forceToPosition3b = GeneralForceToPositionAdaptor(use_pder=False, use_pder2=False)

    def equations(self):
        return [ac.connect(self.sine1.y, self.force3.f),
                ac.connect(self.force3.flange, self.mass3a.flange_a),
                ac.connect(self.mass3a.flange_b, self.forceToPosition3a.flange),
                ac.connect(self.forceToPosition3b.flange, self.mass3b.flange_a),
                ac.connect(self.forceToPosition3a.f, self.spring.f1),
                ac.connect(self.spring.f2, self.forceToPosition3b.f),
                ac.connect(self.forceToPosition3a.p, self.spring.s1),
                ac.connect(self.spring.s2, self.forceToPosition3b.p)]


@pytest.mark.parametrize("model, a, b", [(RotationalThree, "inertia3a", "inertia3b"),
                                         (TranslationalThree, "mass3a", "mass3b")])
def test_two_masses_coupled_through_a_spring_block_move_as_the_two_mass_equations(model, a, b):
    t = np.linspace(0, 1, 101)
    res = ac.simulate(model(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    ref = two_masses(t)
    x = "phi" if model is RotationalThree else "s"
    v = "w" if model is RotationalThree else "v"
    scale = np.max(np.abs(ref[0]))
    assert np.max(np.abs(res[f"{a}.{x}"] - ref[0])) < 1e-7 * scale
    assert np.max(np.abs(res[f"{b}.{x}"] - ref[1])) < 1e-7 * scale
    assert np.max(np.abs(res[f"{b}.{v}"] - ref[3])) < 1e-6 * np.max(np.abs(ref[2]))


@pytest.mark.parametrize("block, drive, outputs", [
    (rot_util.DirectInertia, "tauDrive", ("phi", "w", "a")),
    (tr_util.DirectMass, "fDrive", ("s", "v", "a"))])
def test_a_direct_inertia_block_integrates_its_drive(block, drive, outputs):
    class Driven(ac.Component):
        direct = block(**({"J": J_A} if block is rot_util.DirectInertia else {"m": J_A}))
        sine = Sine(f=F, amplitude=AMP)
        nothing = Constant(k=0.0)

        def equations(self):
            other = "tau" if block is rot_util.DirectInertia else "f"
            return [ac.connect(self.sine.y, getattr(self.direct, drive)),
                    ac.connect(self.nothing.y, getattr(self.direct, other))]

    t = np.linspace(0, 1, 41)
    res = ac.simulate(Driven(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    om = 2 * np.pi * F
    acc = AMP / J_A * np.sin(om * t)
    vel = AMP / (J_A * om) * (1 - np.cos(om * t))
    pos = AMP / (J_A * om) * (t - np.sin(om * t) / om)
    for name, exact in zip(outputs, (pos, vel, acc)):
        assert np.max(np.abs(res[f"direct.{name}"] - exact)) < 1e-7 * np.max(np.abs(exact))


def test_the_adaptors_that_need_a_derivative_annotation_are_refused():
    with pytest.raises(ac.ModelError, match="derivative annotation"):
        AngleToTorqueAdaptor()
    with pytest.raises(ac.ModelError, match="derivative annotation"):
        GeneralPositionToForceAdaptor(use_pder2=False)
    assert set(TorqueToAngleAdaptor(use_a=False).children()) == {"flange", "phi", "tau", "w"}
