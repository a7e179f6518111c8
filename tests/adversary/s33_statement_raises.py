"""A size statement whose admits() raises at one size the dimension-free method asks about (it checks a
declared r = 2 against admits() at n <= 16): the child records the exception in the admits table and the
verifying process raises it again where the engine asks.  In `verify` that is the run's error; `derive` runs
the dimension-free method in its own process, unguarded, and prints a Python traceback."""
from stiefelsym import Size, SizeSpec, claim, twisted


class RaisesAtFiveThree(SizeSpec):
    """r = 2 declared; admits() raises at (5, 3) and says yes to (2, 2), (3, 2) only."""

    def admits(self, n, r):
        if (n, r) == (5, 3):
            raise ValueError("this statement has no answer at (5,3)")
        return r == 2 and 2 <= n <= 3


class RaisesZeroDivision(SizeSpec):
    """The same with a ZeroDivisionError (an ArithmeticError, which the free method otherwise reads as a claim
    that does not run on the free algebra)."""

    def admits(self, n, r):
        return 1 // (n - 7) * 0 == 0 and r == 2 and 2 <= n <= 3


@claim("adv-s33-raises-value", kind="id", sizes=RaisesAtFiveThree((Size(2, 2), Size(3, 2)), r_min=2, r_max=2),
       statement="E1 E1^T + E2 E2^T = I_r")
def raises_value(s):
    """True at r = 2 (its statement's r)."""
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    return {"r": E1 @ E1.T + E2 @ E2.T - s.Ir}


@claim("adv-s33-raises-zerodiv", kind="id", sizes=RaisesZeroDivision((Size(2, 2), Size(3, 2)), r_min=2, r_max=2),
       statement="E1 E1^T + E2 E2^T = 2 I_r")
def raises_zerodiv(s):
    """False at r = 2."""
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    return {"r": E1 @ E1.T + E2 @ E2.T - 2 * s.Ir}


def _fails_nowhere_known(n, r):
    raise ValueError("this erratum has no answer at any size")


@claim("adv-s33-raises-erratum", kind="id", sizes=RaisesAtFiveThree((Size(2, 2), Size(3, 2)), r_min=2, r_max=2),
       statement="X^T X = I_r", fails_at=_fails_nowhere_known, erratum="(its erratum sizes raise)")
def raises_erratum(s):
    """True; its erratum sizes (fails_at) raise: `verify` says error, `show` prints a traceback."""
    return {"r": s.X.T @ s.X - s.Ir}
