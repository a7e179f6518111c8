"""A size statement whose declared r (r_min = r_max, or r_is_n) is contradicted only beyond n = 16: the
dimension-free method checks the declaration against the statement's admits() at n <= 16 (R_CHECK_N) and the
child tabulates admits() at n <= 16 (TABLE_N) unless a size asks for more, so the hypothesis of the declared r
(E1E1ᵀ = I_r at r = 1, XXᵀ = I_n at r = n) is used although the statement admits (17, 2).  The claims are
false at (17, 2), a size their statements admit: `verify --size 17,2` refutes them there."""
from stiefelsym import Size, SizeSpec, admissible, claim, twisted

#: the first n the checks of a declaration do not reach
BEYOND = 17


class ColumnOneThenTwo(SizeSpec):
    """r = 1 declared (r_min = r_max = 1); admits() also says yes to (n, 2) for n >= 17."""

    def admits(self, n, r):
        return (r == 1 and 1 <= n <= 3) or (n >= BEYOND and r == 2)


class SquareThenNot(SizeSpec):
    """r = n declared (r_is_n); admits() also says yes to (n, 2) for n >= 17."""

    def admits(self, n, r):
        return (r == n and 1 <= n <= 3) or (n >= BEYOND and r == 2)


class SquareWhereBeyond(SizeSpec):
    """The same through the statement's own fields: r_is_n and a size condition (where) that is consulted
    only beyond n = 16 (admits() of SizeSpec checks r = n first: the subclass inverts the order)."""

    def admits(self, n, r):
        if n >= BEYOND:
            return self.where(n, r)
        return SizeSpec.admits(self, n, r)


@claim("adv-s33-beyond-col1", kind="id", sizes=ColumnOneThenTwo((Size(2, 1), Size(3, 1)), r_min=1, r_max=1),
       statement="E1 E1^T = I_r")
def beyond_col1(s):
    """True at r = 1 only; the statement admits (17, 2)."""
    E1 = twisted.basis_vector(s, 0)
    return {"r": E1 @ E1.T - s.Ir}


@claim("adv-s33-beyond-square", kind="id", sizes=SquareThenNot((Size(2, 2), Size(3, 3)), r_is_n=True),
       statement="X X^T = I_n")
def beyond_square(s):
    """True at r = n only; the statement admits (17, 2)."""
    return {"r": s.X @ s.X.T - s.In}


@claim("adv-s33-beyond-square-xp", kind="id", sizes=SquareThenNot((Size(2, 2), Size(3, 3)), r_is_n=True),
       statement="X P^T + P X^T = 0")
def beyond_square_xp(s):
    """True at r = n only; the statement admits (17, 2)."""
    return {"r": s.X @ s.P.T + s.P @ s.X.T}


@claim("adv-s33-beyond-square-where", kind="id",
       sizes=SquareWhereBeyond((Size(2, 2), Size(3, 3)), r_is_n=True, where=lambda n, r: r == 2,
                               condition="r = n, and r = 2 beyond 16"),
       statement="X X^T = I_n")
def beyond_square_where(s):
    """True at r = n only; the statement admits (17, 2)."""
    return {"r": s.X @ s.X.T - s.In}


@claim("adv-s33-beyond-control", kind="id", sizes=admissible(n_max=3, r_min=1, r_max=1), statement="E1 E1^T = I_r")
def beyond_control(s):
    """The control: the same claim stated at r = 1 alone is proved for every n."""
    E1 = twisted.basis_vector(s, 0)
    return {"r": E1 @ E1.T - s.Ir}
