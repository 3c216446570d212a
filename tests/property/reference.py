"""An independent reference solution for random lumped networks.

The network is assembled from the netlist by hand, not through acausal, as a linear
constant-coefficient DAE

    E x' = A x + B u(t),        u_j(t) = sum_k a_jk sin(w_jk t),

in exact rational arithmetic (the parameter values are decimal strings, so E and A are
exact).  Electrical networks use modified nodal analysis (node potentials and every
branch current as unknowns; Ho, Ruehli & Brennan, "The modified nodal approach to network
analysis", IEEE Trans. Circuits Syst. 22, 1975).  Mechanical networks use the analogue
with node positions s, node velocities v = s' and every flange force (or torque) as
unknowns: the force balance at a node, Newton's law for a mass, the spring, damper and
ideal-gear laws, and s = 0 at the housing (node 0).

Decomposition (exact).  The Wong sequences

    V_0 = Q^n,   V_{i+1} = A^{-1}(E V_i)        W_0 = {0},   W_{i+1} = E^{-1}(A W_i)

converge to V* and W*; the pencil (E, A) is regular iff V* (+) W* = Q^n and
[E V*, A W*] is invertible, and then with T = [V, W], S = [E V, A W]^{-1}

    S E T = diag(I, N),   S A T = diag(J, I),   N nilpotent

(the quasi-Weierstrass form: Berger, Ilchmann & Trenn, "The quasi-Weierstrass form for
regular matrix pencils", Linear Algebra Appl. 436, 2012).  With
x = V z_s + W z_f the system splits into the ODE z_s' = J z_s + B_s u and the algebraic
part N z_f' = z_f + B_f u, whose only solution is z_f = -sum_{k<nu} N^k B_f u^(k): the
derivatives of the inputs that index reduction differentiates.  A singular pencil (no
unique solution for any input) is the definition of an ill-posed network here.

Solution (floating point).  Each sine term adds the oscillator (sin, cos)' =
w (cos, -sin) started from (0, 1), so [z_s; w]' = M [z_s; w] is one linear ODE and
[z_s; w](t) = expm(M t) [z_s; w](0) (mpmath's expm at 30 digits, see _propagate).
Every output (an element voltage, current, position, force) is a fixed row C times
[z_s; w].

Initial values.  u(0) = 0 for every source, and z_s(0) = 0.  acausal selects its
states among the variables that appear differentiated (capacitor voltages, inductor
currents, positions, velocities, and the potentials of the pins they connect): linear
combinations of the *candidates* (node potentials and inductor currents; node
positions and velocities).  Starting those states at 0 gives the same solution whatever
the selection, provided the candidates have no forced part at t = 0: P_c W z_f(0) = 0.
Then z_s(0) = 0, and x(0) = W z_f(0) (an algebraic variable such as the current of a
capacitor across a source, C u'(0), need not be 0).  ``forced_orders`` reports which
source derivatives reach a candidate, so that the case generator can give such a
source a zero slope at t = 0 (a pair of sines with a1 w1 + a2 w2 = 0).
"""
from __future__ import annotations

from fractions import Fraction
from typing import Dict, List, NamedTuple, Optional, Sequence

import numpy as np

from . import exact as ex

__all__ = ["Reference", "QuasiWeierstrass", "quasi_weierstrass", "assemble",
           "overdetermined_elements"]

SOURCES = ("V", "I", "force")


class _Builder:
    """Rows of E, A and B with named unknowns, filled one equation at a time."""

    def __init__(self):
        self.names: List[str] = []
        self.index: Dict[str, int] = {}
        self.rows: List[tuple] = []          # ({var: e}, {var: a}, {source: b})
        self.owners: List[object] = []       # element name, or ("node", n)
        self.owner: object = None

    def unknown(self, name: str) -> str:
        self.index[name] = len(self.names)
        self.names.append(name)
        return name

    def equation(self, e=None, a=None, b=None):
        self.rows.append((dict(e or {}), dict(a or {}), dict(b or {})))
        self.owners.append(self.owner)

    def matrices(self, sources: Sequence[str]):
        n, m = len(self.names), len(sources)
        assert len(self.rows) == n, (len(self.rows), n)
        col = {s: j for j, s in enumerate(sources)}
        E, A, B = ex.zeros(n, n), ex.zeros(n, n), ex.zeros(n, m)
        for i, (e, a, b) in enumerate(self.rows):
            for mat, entries, where in ((E, e, self.index), (A, a, self.index), (B, b, col)):
                for key, val in entries.items():
                    if key is not None:
                        mat[i][where[key]] += Fraction(val)
        return E, A, B


def _add(d: dict, key, val):
    if key is not None:
        d[key] = d.get(key, 0) + val


def _electrical(net, bld: _Builder):
    """Modified nodal analysis: KCL at every node but ground, one law per branch."""
    pot = {n: bld.unknown(f"e{n}") for n in net.nodes() if n != 0}
    pot[0] = None
    cur = {el.name: bld.unknown(f"{el.name}.i") for el in net.elements}
    for n in sorted(k for k in pot if k != 0):
        bld.owner = ("node", n)
        a = {}
        for el in net.elements:
            if el.a == n:
                _add(a, cur[el.name], 1)      # i enters the element at p ...
            if el.b == n:
                _add(a, cur[el.name], -1)     # ... and leaves it at n
        bld.equation(a=a)
    for el in net.elements:
        bld.owner = el.name
        p, q, i = pot[el.a], pot[el.b], cur[el.name]
        drop = {}
        _add(drop, p, 1)
        _add(drop, q, -1)
        x = el.exact() if el.kind not in SOURCES else None
        if el.kind == "R":           # 0 = (e_p - e_n) - R i
            bld.equation(a={**drop, i: -x})
        elif el.kind == "C":         # C (e_p - e_n)' = i
            bld.equation(e={k: x * v for k, v in drop.items()}, a={i: 1})
        elif el.kind == "L":         # L i' = e_p - e_n
            bld.equation(e={i: x}, a=drop)
        elif el.kind == "V":         # 0 = (e_p - e_n) - u
            bld.equation(a=drop, b={el.name: -1})
        elif el.kind == "I":         # 0 = i - u
            bld.equation(a={i: 1}, b={el.name: -1})
    return [pot[n] for n in pot if pot[n] is not None] + \
        [cur[el.name] for el in net.elements if el.kind == "L"]


def _mechanical(net, bld: _Builder):
    """Positions, velocities and flange forces; balance of forces at every free node."""
    pos = {n: bld.unknown(f"s{n}") for n in net.nodes() if n != 0}
    vel = {n: bld.unknown(f"v{n}") for n in net.nodes() if n != 0}
    pos[0] = vel[0] = None
    flange = {}                       # (element, 'a'|'b') -> (unknown, sign)
    for el in net.elements:
        if el.kind in ("spring", "damper"):
            f = bld.unknown(f"{el.name}.f")          # the force on flange_b
            flange[el.name, "a"], flange[el.name, "b"] = (f, -1), (f, 1)
        elif el.kind in ("mass", "gear"):
            flange[el.name, "a"] = (bld.unknown(f"{el.name}.fa"), 1)
            if el.b is not None:
                flange[el.name, "b"] = (bld.unknown(f"{el.name}.fb"), 1)
        elif el.kind == "force":
            flange[el.name, "a"] = (bld.unknown(f"{el.name}.fa"), 1)
    for n in sorted(k for k in pos if k != 0):
        bld.owner = ("node", n)
        bld.equation(e={pos[n]: 1}, a={vel[n]: 1})                  # s' = v
        bal = {}
        for el in net.elements:
            for side, node in (("a", el.a), ("b", el.b)):
                if node == n and (el.name, side) in flange:
                    f, sign = flange[el.name, side]
                    _add(bal, f, sign)
        bld.equation(a=bal)                                          # sum of forces = 0
    for el in net.elements:
        bld.owner = el.name
        x = el.exact() if el.kind not in SOURCES else None
        fa = flange.get((el.name, "a"), (None, 0))[0]
        fb = flange.get((el.name, "b"), (None, 0))[0]
        if el.kind in ("spring", "damper"):      # 0 = k (q_b - q_a) - f
            q = pos if el.kind == "spring" else vel
            a = {fa: -1}
            _add(a, q[el.b], x)
            _add(a, q[el.a], -x)
            bld.equation(a=a)
        elif el.kind == "mass":                  # m v_a' = f_a + f_b,  s_a = s_b
            bld.equation(e={vel[el.a]: x} if vel[el.a] else None, a={fa: 1, fb: 1})
            if el.b is not None:
                a = {}
                _add(a, pos[el.a], 1)
                _add(a, pos[el.b], -1)
                bld.equation(a=a)
        elif el.kind == "force":                 # flange force = -u
            bld.equation(a={fa: 1}, b={el.name: 1})
        elif el.kind == "gear":                  # s_a = n s_b,  0 = n f_a + f_b
            a = {}
            _add(a, pos[el.a], 1)
            _add(a, pos[el.b], -x)
            bld.equation(a=a)
            bld.equation(a={fa: x, fb: 1})
    return [pos[n] for n in pos if pos[n]] + [vel[n] for n in vel if vel[n]]


def _build(net) -> tuple:
    bld = _Builder()
    cand = (_electrical if net.domain == "electrical" else _mechanical)(net, bld)
    return bld, cand


def assemble(net):
    """(E, A, B, unknown names, source names, candidate-state names) of a netlist."""
    bld, cand = _build(net)
    sources = [el.name for el in net.elements if el.kind in SOURCES]
    E, A, B = bld.matrices(sources)
    return E, A, B, bld.names, sources, cand


# the unknown of the reference that an extra equation ``element.variable = 0`` fixes
_EXTRA_UNKNOWN = {"i": "{e}.i", "f": "{e}.f", "tau": "{e}.f", "flange_a.tau": "{e}.fa",
                  "v": "v{a}", "w": "v{a}", "flange.s": "s{a}", "flange.phi": "s{a}"}


def overdetermined_elements(net) -> List[str]:
    """The elements whose equations lie in the over-determined part of the network
    with its extra equation (Dulmage & Mendelsohn: every equation reachable by an
    alternating path from an equation left unmatched by a maximum matching), a node's
    balance counting for every element at the node.  Structure only: x and x' are
    one unknown, as in Pryce's structural analysis."""
    import networkx as nx
    bld, _ = _build(net)
    rows = [set(e) | set(a) for e, a, _ in bld.rows]
    owners = list(bld.owners)
    name, var = net.extra
    el = next(x for x in net.elements if x.name == name)
    rows.append({_EXTRA_UNKNOWN[var].format(e=name, a=el.a)} - {"v0", "s0"})
    owners.append(name)
    g = nx.Graph()
    g.add_nodes_from(("r", i) for i in range(len(rows)))
    g.add_nodes_from(("x", v) for v in bld.names)
    g.add_edges_from((("r", i), ("x", v)) for i, vs in enumerate(rows) for v in vs if v)
    match = nx.bipartite.hopcroft_karp_matching(g, top_nodes=[("r", i) for i in range(len(rows))])
    todo = [("r", i) for i in range(len(rows)) if ("r", i) not in match]
    seen = set(todo)
    while todo:
        r = todo.pop()
        for x in g[r]:
            m = match.get(x)
            if m is not None and m not in seen:
                seen.add(m)
                todo.append(m)
    out = set()
    for _, i in seen:
        own = owners[i]
        if isinstance(own, tuple):
            out |= {e.name for e in net.elements if own[1] in (e.a, e.b)}
        elif own is not None:
            out.add(own)
    return sorted(out)


def _outputs(net) -> Dict[str, dict]:
    """The compared signals, in acausal's names, as {unknown: coefficient} rows."""
    out: Dict[str, dict] = {}
    if net.domain == "electrical":
        def e(n):
            return {} if n == 0 else {f"e{n}": 1}
        for el in net.elements:
            drop = dict(e(el.a))
            for k, v in e(el.b).items():
                drop[k] = drop.get(k, 0) - v
            out[f"{el.name}.v"] = drop
            out[f"{el.name}.i"] = {f"{el.name}.i": 1}
        return out
    rot = net.domain == "rotational"
    q, w, f, rel = ("phi", "w", "tau", "phi_rel") if rot else ("s", "v", "f", "s_rel")

    def node(kind, n):
        return {} if n == 0 else {f"{kind}{n}": 1}
    for el in net.elements:
        if el.kind == "mass":
            out[f"{el.name}.{q}"] = node("s", el.a)
            out[f"{el.name}.{w}"] = node("v", el.a)
            out[f"{el.name}.flange_a.{f}"] = {f"{el.name}.fa": 1}
            if el.b is not None:
                out[f"{el.name}.flange_b.{f}"] = {f"{el.name}.fb": 1}
        elif el.kind in ("spring", "damper"):
            r = dict(node("s", el.b))
            for k, v in node("s", el.a).items():
                r[k] = r.get(k, 0) - v
            out[f"{el.name}.{rel}"] = r
            out[f"{el.name}.{f}"] = {f"{el.name}.f": 1}
        elif el.kind == "gear":
            out[f"{el.name}.flange_a.{f}"] = {f"{el.name}.fa": 1}
            out[f"{el.name}.flange_b.{f}"] = {f"{el.name}.fb": 1}
            out[f"{el.name}.flange_b.{q}"] = node("s", el.b)
        elif el.kind == "force":
            out[f"{el.name}.flange.{q}"] = node("s", el.a)
    return out


def _input_rows(terms, k: int) -> np.ndarray:
    """Row mapping the oscillator states (sin, cos per term) to the k-th derivative of
    u = sum a sin(w t):  d^k sin = w^k (sin, cos, -sin, -cos)[k mod 4]."""
    row = np.zeros(2 * len(terms))
    for t, (amp, freq) in enumerate(terms):
        w = 2 * np.pi * freq
        phase = k % 4
        sign = 1.0 if phase < 2 else -1.0
        row[2 * t + (phase % 2)] = sign * amp * w**k
    return row


class QuasiWeierstrass(NamedTuple):
    """S E T = diag(I, N), S A T = diag(J, I), T = [V, W]; B_s, B_f the rows of S B."""
    V: ex.Matrix
    W: ex.Matrix
    J: ex.Matrix
    N: ex.Matrix
    Bs: ex.Matrix
    Bf: ex.Matrix


def quasi_weierstrass(E: ex.Matrix, A: ex.Matrix, B: ex.Matrix) -> Optional[QuasiWeierstrass]:
    """The quasi-Weierstrass form of a square pencil (E, A), exactly; None if the
    pencil is singular (see the module docstring for the Wong sequences)."""
    n = len(E)

    def image(M, cols):
        return ex.columns(ex.matmul(M, ex.from_columns(cols, n)), n)
    unit = [[Fraction(int(i == j)) for i in range(n)] for j in range(n)]
    V = _limit(lambda cols: ex.preimage(A, image(E, cols), n, n), unit)
    W = _limit(lambda cols: ex.preimage(E, image(A, cols), n, n), [])
    ns = len(V)
    if ns + len(W) != n:
        return None
    try:
        S = ex.inverse(ex.from_columns(image(E, V) + image(A, W), n))
    except ZeroDivisionError:
        return None
    T = ex.from_columns(V + W, n)
    SET, SAT, SB = ex.matmul(ex.matmul(S, E), T), ex.matmul(ex.matmul(S, A), T), ex.matmul(S, B)
    # the form itself, checked exactly: S E V = [I; 0] and S A W = [0; I]
    assert all(SET[i][j] == (i == j) for i in range(n) for j in range(ns)), "S E V != [I; 0]"
    assert all(SAT[i][j] == (i == j) for i in range(n) for j in range(ns, n)), "S A W != [0; I]"
    return QuasiWeierstrass(ex.from_columns(V, n), ex.from_columns(W, n),
                            [row[:ns] for row in SAT[:ns]], [row[ns:] for row in SET[ns:]],
                            SB[:ns], SB[ns:])


class Reference:
    """The exact decomposition of a netlist and its solution for given sources.

    ``regular`` is False for a singular pencil (ill-posed); then nothing else is set.
    ``index`` is the nilpotency index of N (the differentiation index; 0 for an ODE),
    ``ns`` the number of degrees of freedom, ``eigenvalues`` those of J.
    """

    def __init__(self, net):
        self.net = net
        E, A, B, self.names, self.sources, cand = assemble(net)
        self.n, m = len(self.names), len(self.sources)
        self.index_of = {name: i for i, name in enumerate(self.names)}
        qwf = quasi_weierstrass(E, A, B)
        self.regular = qwf is not None
        if not self.regular:
            return
        self.ns, self.nf = len(qwf.J), len(qwf.N)
        self.index = _nilpotency(qwf.N) if self.nf else 0
        NkBf, P = [], qwf.Bf                  # N^k B_f, k = 0 .. index-1
        for _ in range(self.index):
            NkBf.append(P)
            P = ex.matmul(qwf.N, P)
        self.E, self.A, self.B = ex.to_float(E, self.n), ex.to_float(A, self.n), ex.to_float(B, m)
        self.Vf = ex.to_float(qwf.V, self.ns)                       # x_s = V z_s
        # x_f = -sum_k W N^k B_f u^(k)
        self.WNkBf = [ex.to_float(ex.matmul(qwf.W, P), m) for P in NkBf]
        self.Jf, self.Bsf = ex.to_float(qwf.J, self.ns), ex.to_float(qwf.Bs, m)
        self.eigenvalues = np.linalg.eigvals(self.Jf) if self.ns else np.zeros(0)
        rows = _outputs(net)
        self.outputs = sorted(rows)
        self.Y = np.zeros((len(self.outputs), self.n))
        for r, name in enumerate(self.outputs):
            for var, c in rows[name].items():
                self.Y[r, self.index_of[var]] += c
        self.candidates = list(cand)
        Pc = ex.zeros(len(cand), self.n)
        for r, var in enumerate(cand):
            Pc[r][self.index_of[var]] = Fraction(1)
        PcW = ex.matmul(Pc, qwf.W)
        self._candidate_hits = []             # per k: which sources reach a candidate
        for P in NkBf:
            hit = ex.matmul(PcW, P)
            self._candidate_hits.append([any(row[j] for row in hit) for j in range(m)])

    def forced_orders(self, source: str) -> List[int]:
        """The derivative orders k >= 1 of ``source`` that reach a candidate state at
        t = 0 (through z_f = -sum N^k B_f u^(k)); odd ones matter for a sine input."""
        j = self.sources.index(source)
        return [k for k, hits in enumerate(self._candidate_hits) if k >= 1 and hits[j]]

    def system(self, terms: Dict[str, Sequence[tuple]]):
        """(M, Cx, xi0, G): the augmented ODE xi' = M xi, xi(0) = xi0, with
        x = Cx xi and u = G xi, for sources {name: [(a, f), ...]}."""
        ns, m = self.ns, len(self.sources)
        offsets, total = {}, 0
        for s in self.sources:
            offsets[s] = total
            total += 2 * len(terms[s])
        dim = ns + total
        M = np.zeros((dim, dim))
        M[:ns, :ns] = self.Jf
        Cx = np.zeros((self.n, dim))
        Cx[:, :ns] = self.Vf
        G = np.zeros((m, dim))
        xi0 = np.zeros(dim)
        for j, s in enumerate(self.sources):
            o = ns + offsets[s]
            k2 = 2 * len(terms[s])
            G[j, o:o + k2] = _input_rows(terms[s], 0)
            M[:ns, o:o + k2] = np.outer(self.Bsf[:, j], G[j, o:o + k2])
            for t, (_, freq) in enumerate(terms[s]):
                w = 2 * np.pi * freq
                M[o + 2 * t, o + 2 * t + 1] = w           # sin' = w cos
                M[o + 2 * t + 1, o + 2 * t] = -w          # cos' = -w sin
                xi0[o + 2 * t + 1] = 1.0                  # cos(0) = 1
            for k, WP in enumerate(self.WNkBf):           # x_f = -sum W N^k B_f u^(k)
                Cx[:, o:o + k2] -= np.outer(WP[:, j], _input_rows(terms[s], k))
        return M, Cx, xi0, G

    def trajectories(self, times: Sequence[float], terms):
        """(x, x', u) at ``times``, one row per time (x in the order of ``names``)."""
        M, Cx, xi0, G = self.system(terms)
        xi = _propagate(M, xi0, np.asarray(times, dtype=float))
        return xi @ Cx.T, xi @ (Cx @ M).T, xi @ G.T

    def solve(self, times: Sequence[float], terms) -> Dict[str, np.ndarray]:
        """Every output at ``times``, by acausal's names, for sources
        u_j = sum a sin(2 pi f t), given as {source: [(a, f), ...]}."""
        return self.evaluate(times, terms)[0]

    def evaluate(self, times: Sequence[float], terms):
        """(outputs, sizes): ``solve`` and ``sizes`` from one pass over the times."""
        x, xp, u = self.trajectories(times, terms)
        Y = x @ self.Y.T
        outputs = {name: Y[:, r] for r, name in enumerate(self.outputs)}
        return outputs, self._sizes(x, xp, u)

    def sizes(self, times: Sequence[float], terms) -> Dict[str, float]:
        """How large each output's error may be, in units of the tolerance: the size of
        the terms it is computed from.

        An unknown x_i that an algebraic term A_ri x_i of equation r ties to other
        terms can be no more accurate than they are; every equation holds for the
        computed solution, so the best-conditioned one bounds the error:
        size_i = max(max|x_i|, min over r of T_ri / |A_ri|), T_ri = sum_k!=i |A_rk| X_k
        + sum_k |E_rk| X'_k + |B_r| U, with X, X', U the maxima of |x|, |x'|, |u|.
        Equations whose other terms are all zero (T_ri = 0: a Kirchhoff law in a part of
        the network that carries nothing) bound nothing, as the computed values of those
        terms are round-off, not zero; they are skipped.  An output y = Y x then has
        size max(max|y|, sum_i |Y_ji| size_i): an element voltage that is the small
        difference of two large potentials has the size of the potentials.
        """
        return self.evaluate(times, terms)[1]

    def _sizes(self, x, xp, u) -> Dict[str, float]:
        X, Xp = np.max(np.abs(x), axis=0), np.max(np.abs(xp), axis=0)
        U = np.max(np.abs(u), axis=0) if u.size else np.zeros(0)
        size = X.copy()
        absA, absE, absB = np.abs(self.A), np.abs(self.E), np.abs(self.B)
        rows = absA @ X + absE @ Xp + (absB @ U if U.size else 0.0)
        tiny = 1e-12 * (rows.max() if rows.size else 0.0)
        for i in range(self.n):
            bounds = [(rows[r] - absA[r, i] * X[i]) / absA[r, i]
                      for r in np.nonzero(absA[:, i])[0]
                      if rows[r] - absA[r, i] * X[i] > tiny]
            if bounds:
                size[i] = max(size[i], min(bounds))
        out = np.maximum(np.max(np.abs(x @ self.Y.T), axis=0), np.abs(self.Y) @ size)
        return {name: float(out[r]) for r, name in enumerate(self.outputs)}


def _propagate(M: np.ndarray, xi0: np.ndarray, times: np.ndarray) -> np.ndarray:
    """xi(t) = expm(M t) xi0 at ``times`` (rows), in 30-digit arithmetic.

    M is far from normal in the basis the decomposition gives (its norm can exceed its
    spectral radius a hundredfold), and double-precision expm then loses 1e-6 relative
    on a lightly damped oscillation over tens of periods; mpmath's expm at 30 digits
    leaves the double rounding of M itself as the only error.  On an even grid from
    0, one exponential is applied step by step.
    """
    import mpmath
    if M.size == 0:
        return np.zeros((len(times), 0))
    with mpmath.workdps(30):
        Mm = mpmath.matrix(M.tolist())
        x0 = mpmath.matrix(xi0.tolist())
        steps = np.diff(times)
        if len(times) > 1 and times[0] == 0 and np.allclose(steps, steps[0], rtol=1e-12, atol=0):
            step = mpmath.expm(Mm * mpmath.mpf(float(steps[0])))
            out = [x0]
            for _ in steps:
                out.append(step * out[-1])
        else:
            out = [mpmath.expm(Mm * mpmath.mpf(float(t))) * x0 for t in times]
        return np.array([[float(v) for v in x] for x in out]).reshape(len(times), len(xi0))


def _nilpotency(N) -> int:
    """The smallest k with N^k = 0 (N is nilpotent by construction)."""
    k, P = 1, N
    while not ex.is_zero(P):
        k, P = k + 1, ex.matmul(N, P)
        assert k <= len(N) + 1, "N is not nilpotent"
    return k


def _limit(step, start):
    """Iterate a Wong sequence to its limit (dimensions are monotone, so equal
    dimensions mean equal subspaces)."""
    cur = start
    while True:
        nxt = step(cur)
        if len(nxt) == len(cur):
            return nxt
        cur = nxt
