"""Engine state held in containers that the engine's fingerprint does not look into (it watches code, types,
modules, public scalar constants and the listed registries): the division probe's memo
(``stiefelsym.methods.fixed_size._PROBES``, keyed by the claim's own function) seeded with "no division" for the claim's
sizes, and the set of coordinate-basis engine steps (``stiefelsym.ir.passes.COORDINATE_STEPS``, a frozenset)
replaced by an empty one."""
from stiefelsym import admissible, claim, twisted
from stiefelsym.methods import fixed_size as methods
from stiefelsym.ir import passes
from stiefelsym.systems import real_coordinates


def _first_eigenvalue(s):
    """tr(Dn A (I − S))/2 = a_1 at every fixed size (Dn = diag(I_2, 0), S = S_1, A = diag(a))."""
    D, S = twisted.eigenspace_projector(s), twisted.reflection(s)
    return (s.tr(D @ s.A) - s.tr(D @ s.A @ S)) / 2


@claim("adv-state-probe-memo", kind="id", sizes=admissible(n_max=3), statement="A R(mu) = R(mu) A, mu = a_1")
def probe_memo(s):
    """R(mu) exists at no point of any stated size (mu = a_1 there)."""
    R = s.resolvent(_first_eigenvalue(s))
    return {"r": s.A @ R - R @ s.A}


# the probe's answer for every stated size, written before the method asks: "" (no division by zero)
methods._PROBES[probe_memo] = {("adv-state-probe-memo", "standard", n, r, 0, True): ""
                               for n in range(1, 4) for r in range(1, n + 1)}


@claim("adv-state-probe-control", kind="id", sizes=admissible(n_max=3), statement="A R(mu) = R(mu) A, mu = a_1")
def probe_control(s):
    """The same claim without the seeded memo (error: the probe finds R(a_1) singular)."""
    R = s.resolvent(_first_eigenvalue(s))
    return {"r": s.A @ R - R @ s.A}


passes.COORDINATE_STEPS = frozenset()


@claim("adv-state-coordinate-steps", kind="id", sizes=admissible(n_max=4), statement="X_11 = 1")
def coordinate_steps(s):
    """False: X_11 = 1, read as tr(E11^T X) with E11 from real_coordinates (route H) once the set of
    coordinate-basis steps is empty."""
    E11 = real_coordinates(s, ["X"])[0][1]
    return {"X11 - 1": s.tr(E11.T @ s.X) - s.q(1)}
