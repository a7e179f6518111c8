# ruff: noqa: F841, E702, F401
"""What a user gets wrong: each claim here is ill-formed on purpose (expect error / clear refusal)."""
import random
import time

from stiefelsym import admissible, claim

from common import hamiltonian

SZ = [(3, 2)]


@claim("u2-bad-raises", kind="id", sizes=SZ)
def raises(s):
    """A claim that raises."""
    raise ValueError("my own bug in the claim")


@claim("u2-bad-random", kind="id", sizes=SZ)
def nondeterministic(s):
    """Non-deterministic: a random integer multiple of a true residual plus a random 0/1 times a false one."""
    k = random.randint(0, 1)
    return {"r": k * s.d(lambda t: t.Phi, s.dirac_flow(hamiltonian(s.scalar("c"))))}


@claim("u2-bad-clock", kind="id", sizes=SZ)
def clock(s):
    """Non-deterministic through the clock: Phi conserved (false) only on odd microseconds."""
    k = int(time.time() * 1e6) % 2
    return {"r": k * s.d(lambda t: t.Phi, s.dirac_flow(hamiltonian(s.scalar("c"))))}


@claim("u2-bad-float", kind="id", sizes=SZ)
def float_const(s):
    """A float constant 0.5 in the Hamiltonian."""
    H = lambda t: 0.5 * t.tr(t.P.T @ t.P)
    return {"r": s.d(H, s.dirac_flow(H))}


@claim("u2-bad-list", kind="id", sizes=SZ)
def list_return(s):
    """Returns a list instead of a dict."""
    return [s.Psi - s.Psi]


@claim("u2-bad-I", kind="id", sizes=SZ)
def identity_name(s):
    """Uses s.I."""
    return {"r": s.X.T @ s.X - s.I}


@claim("u2-bad-shape", kind="id", sizes=SZ)
def shape(s):
    """Phi - Psi: different spaces."""
    return {"r": s.Phi - s.Psi}


@claim("u2-bad-key", kind="id", sizes=SZ)
def bad_key(s):
    """A tangent vector with key 'Q'... and lowercase 'x'."""
    return {"r": s.d(lambda t: t.Psi, {"x": s.P})}


@claim("u2-bad-empty", kind="id", sizes=SZ)
def empty(s):
    """No checks at all."""
    return {}
