"""The compile-time values of incidence coefficients (``compiler.index.numeric``): a
coefficient that is not a number at the start values is no value, not an error."""
import numpy as np

import acausal as ac


class NaNAtTheStart(ac.Component):
    """A torn loop whose coefficients hold a relation of a/b (evaluated without events, as
    the MSL's exlin of v/(N vt_t) in a diode), 0/0 at the start values 0:

        a + b^3 = 1 + t,   a^3 (2 if a/b > 0 else 3) + b = 2
    """

    a = ac.Variable(start=0.0)
    b = ac.Variable(start=0.0)

    def equations(self):
        law = ac.no_event(ac.if_else(self.a / self.b > 0, 2, 3))
        return [ac.Eq(self.a + self.b**3, 1 + ac.time),
                ac.Eq(self.a**3 * law + self.b, 2)]


def test_a_relation_that_is_nan_at_the_start_values_is_no_compile_error():
    # start values 0: a/b is 0/0 where the coefficients are sampled
    res = ac.simulate(NaNAtTheStart(a={"start": 0.0}, b={"start": 0.0}), t_end=0.1,
                      rtol=1e-10, t_eval=[0.0, 0.05, 0.1], raise_on_failure=True)
    a, b = res["a"], res["b"]
    assert np.allclose(a + b**3, 1 + res.t, atol=1e-9)
    assert np.allclose(a**3 * np.where(a / b > 0, 2, 3) + b, 2, atol=1e-9)
