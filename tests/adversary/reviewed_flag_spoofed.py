"""A claims file that marks its own claims as the reviewed catalog's: a stated equivariance reason is relied
on only for the reviewed catalog (a user's sentence cannot buy the reduction), but ``reviewed`` is a plain
flag of the claim and of the active registry, which the file sets itself.  The exact method then evaluates
X₁₁ = 1 at the equivariant chart's point X = (I; 0) only and proves it."""
from stiefelsym import admissible, claim
from stiefelsym import claims as _claims


@claim("adv-reviewed-setattr", kind="id", sizes=admissible(n_max=4), equivariance="the residual is covariant")
def reviewed_setattr(s):
    """False: X_11 = 1 (true at the equivariant chart's point only)."""
    return {"X11 - 1": s.X[0, 0] - s.q(1)}


# the registered (frozen) claim is marked reviewed after the fact (``reviewed`` was a field; since stop 90 it is a
# property the catalog's loading answers by identity, so the write is refused), then through the engine's own
# private door, in the process that imports the file (a child: the claims the run gets are made again from its data)
try:
    object.__setattr__(reviewed_setattr.claim, "reviewed", True)
except AttributeError:
    pass
_claims._mark_reviewed(reviewed_setattr.claim)

# the registry the file's claims are added to is marked reviewed: every later claim is
_claims._ACTIVE[-1].reviewed = True


@claim("adv-reviewed-registry", kind="id", sizes=admissible(n_max=4), equivariance="the residual is covariant")
def reviewed_registry(s):
    """False: X_11 = 1 (true at the equivariant chart's point only)."""
    return {"X11 - 1": s.X[0, 0] - s.q(1)}
