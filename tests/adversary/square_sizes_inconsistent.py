"""r_is_n declared on a SizeSpec whose sizes have r < n: the free method takes the declaration (and uses
X X^T = I_n) while the claim's own default sizes, which every fixed-size method verifies, include r < n.
Both specs are built through the public API (SizeSpec, dataclasses.replace on admissible(...))."""
import dataclasses

from stiefelsym import Size, SizeSpec, admissible, claim

#: a hand-built spec: sizes (3,2), (3,3), (4,4), declared r = n
SQ_HANDBUILT = SizeSpec((Size(3, 2), Size(3, 3), Size(4, 4)), r_is_n=True)
#: every 2 <= n <= 4, r <= n (admissible's sizes), with r_is_n switched on afterwards
SQ_REPLACED = dataclasses.replace(admissible(n_max=4, n_min=2), r_is_n=True)


@claim("adv-square-handbuilt", kind="id", sizes=SQ_HANDBUILT, statement="X X^T = I_n")
def square_handbuilt(s):
    """False at (3,2), one of the claim's sizes."""
    return {"r": s.X @ s.X.T - s.In}


@claim("adv-square-replace", kind="id", sizes=SQ_REPLACED, statement="X X^T = I_n")
def square_replaced(s):
    """False at every size with r < n, among the claim's sizes."""
    return {"r": s.X @ s.X.T - s.In}


@claim("adv-square-xpt", kind="id", sizes=SQ_REPLACED, statement="X P^T + P X^T = 0")
def square_xpt(s):
    """False for r < n (X^T P skew gives X P^T skew only when X X^T = I_n)."""
    return {"r": s.X @ s.P.T + s.P @ s.X.T}


class AdmitsEverySize(SizeSpec):
    """A SizeSpec (public) whose admits() says yes to every (n, r): its r_min = r_max = 2 are what the free
    method reads, its admits() what an explicit --size is checked against."""

    def admits(self, n, r):
        return 1 <= r <= n


R2_ADMITS_ALL = AdmitsEverySize((Size(3, 2), Size(4, 2)), r_min=2, r_max=2)


@claim("adv-r2-admits-all", kind="id", sizes=R2_ADMITS_ALL, statement="E1 E1^T + E2 E2^T = I_r")
def r2_admits_all(s):
    """True at r = 2 only; --size 3,3 is admitted."""
    from stiefelsym import twisted
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    return {"r": E1 @ E1.T + E2 @ E2.T - s.Ir}


@claim("adv-square-set-while-traced", kind="id", sizes=admissible(n_max=4, n_min=2), statement="X X^T = I_n")
def square_set_while_traced(s):
    """Stated for every r <= n (a consistent spec); the claim's code declares r = n on its own registered claim
    (frozen, but object.__setattr__) while it is traced, which is before the free method reads r_is_n."""
    c = square_set_while_traced.claim
    object.__setattr__(c, "sizes", dataclasses.replace(c.sizes, r_is_n=True))
    return {"r": s.X @ s.X.T - s.In}
