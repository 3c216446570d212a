"""The RC circuit that the tests of a fresh process run as a script (a file: the compile
cache's tree key reads the model class's source): import lines, then the class."""

RC_CLASS = '''
import acausal as ac
from acausal.library.electrical import Capacitor, Ground, Resistor, StepVoltage


class RC(ac.Component):
    src = StepVoltage(V=1.0)
    R1 = Resistor(R=1.0e3)
    C1 = Capacitor(C=1.0e-6)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]
'''
