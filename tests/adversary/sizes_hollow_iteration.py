"""A SizeSpec (public) whose iteration is empty while its field ``sizes`` and its length say (3,2): the claim
passes the "no sizes" check (len), and every loop of the dimension-free method over the stated sizes (the
comparison of the symbolic graph with the graph at each size, the division probe at every size when a
resolvent moves with the point) runs over nothing."""
from stiefelsym import Size, SizeSpec, claim, twisted


class HollowSizes(SizeSpec):
    """Stated for (3,2) by its fields and its length; no size by iteration."""

    def __iter__(self):
        return iter(())


HOLLOW = HollowSizes((Size(3, 2),), n_max=3)


@claim("adv-hollow-moving-eigenvalue", kind="id", sizes=HOLLOW, statement="A R(mu) = R(mu) A, mu = tr(Dn A (I - S))/2")
def hollow_moving_eigenvalue(s):
    """mu = a_1 at every fixed size: R(mu) exists at no point of the stated size (3,2)."""
    D, S = twisted.eigenspace_projector(s), twisted.reflection(s)
    R = s.resolvent((s.tr(D @ s.A) - s.tr(D @ s.A @ S)) / 2)
    return {"r": s.A @ R - R @ s.A}
