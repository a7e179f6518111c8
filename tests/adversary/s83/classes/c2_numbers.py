"""Class 2 (floats in disguise / constants that are not int or Fraction): number types that pass isinstance(int)
or numbers.Rational but whose arithmetic or fields lie, and exact number types of other libraries.

Truths at (3,2): XᵀX = I_r, so c·(XᵀX − I_r) = 0 for every constant c (TRUE), and c·XᵀX − 2·I_r = 0 is TRUE iff
c = 2 (as the claim's reader means c).  Each false claim is "k·XᵀX − k'·I_r" with k ≠ k' as the constant's *int
value* (int(c), c + 0, c == ...), while some other reading of the object (its numerator/denominator properties,
its __index__, __mul__, __hash__) says k'.  A verdict must be error (refused) or the one the int value gives.

n-numer:    class N(int) whose .numerator property says 2 while int(N(3)) = 3: N(3)·XᵀX − 2·I_r   FALSE (3 ≠ 2)
n-numer-t:  the same with N(2)                                                                   TRUE
n-mul:      class M(int) whose __mul__/__rmul__ return 2·other: M(3)·XᵀX − 3·I_r (FALSE: as an int, 3·XᵀX...
            no: the claim's code computes M(3)*(XᵀX) whose __mul__ says 2·XᵀX; the graph is what was traced; the
            int 3 read by the engine elsewhere would be the lie) -- we state q = s.q(M(3)) and q·XᵀX − 3 I_r: TRUE
            if the engine takes the int value 3, FALSE if __mul__ is used anywhere (2·XᵀX − 3·I_r)
n-bool:     True·XᵀX − I_r (bool is an int: 1) TRUE; n-bool-f: True·XᵀX − 2I_r FALSE
n-fmpq:     flint.fmpq(2, 1)·XᵀX − 2 I_r: TRUE if accepted; n-fmpq-f: fmpq(3, 1)·XᵀX − 2·I_r FALSE
n-fmpz:     flint.fmpz(2)·XᵀX − 2 I_r TRUE; n-fmpz-f with 3 FALSE
n-sympy:    sympy.Rational(1, 3)·(3XᵀX) − I_r TRUE; n-sympy-f: sympy.Rational(1, 3)·(3XᵀX) − 2I_r FALSE
n-decimal:  Decimal("0.1")·10·XᵀX − I_r: TRUE with exact decimals, must be refused (not int/Fraction)
n-frac-sub: a Fraction subclass whose __add__ lies (x + y returns x): F(1,2)·XᵀX + F(1,2)·XᵀX − I_r TRUE as
            exact rationals; n-frac-sub-f: F(1,3)... − I_r FALSE
n-index:    class I(int) with __index__ = 5 while int value 2: s.q(I(2), 1)·XᵀX − 2 I_r TRUE by int value
n-hash:     Fraction(2**61 - 1 + 2, 1) vs 1: hash(2**61+1) == hash(2)? (hash of ints mod 2**61−1): a constant cache
            keyed by hash/== would merge 2 and 2**61 + 1.  (2**61+1)·XᵀX − (2**61+1)·I_r + 2·XᵀX − 2·I_r TRUE;
            n-hash-f: (2**61+1)·XᵀX − 2·I_r FALSE (a merged constant would make it 0)
"""
from decimal import Decimal
from fractions import Fraction

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)


class N(int):
    @property
    def numerator(self):
        return 2

    @property
    def denominator(self):
        return 1


class M(int):
    def __mul__(self, other):
        return 2 * other

    __rmul__ = __mul__


class I(int):  # noqa: E742 - the trick needs the name
    def __index__(self):
        return 5


class F(Fraction):
    def __add__(self, other):
        return self

    __radd__ = __add__


def _g(s):
    return s.X.T @ s.X


@claim("n-numer", kind="id", sizes=SZ)
def n_numer(s):
    return {"x": N(3) * _g(s) - 2 * s.Ir}


@claim("n-numer-t", kind="id", sizes=SZ)
def n_numer_t(s):
    return {"x": N(2) * _g(s) - 2 * s.Ir}


@claim("n-numer-q", kind="id", sizes=SZ)
def n_numer_q(s):
    """s.q(N(3)) read by its numerator property would be 2: FALSE (3 XᵀX − 2 I)."""
    return {"x": s.q(N(3), 1) * _g(s) - 2 * s.Ir}


@claim("n-mul", kind="id", sizes=SZ)
def n_mul(s):
    return {"x": s.q(M(3), 1) * _g(s) - 3 * s.Ir}


@claim("n-mul-f", kind="id", sizes=SZ)
def n_mul_f(s):
    return {"x": s.q(M(3), 1) * _g(s) - 2 * s.Ir}


@claim("n-bool", kind="id", sizes=SZ)
def n_bool(s):
    return {"x": True * _g(s) - s.Ir}


@claim("n-bool-f", kind="id", sizes=SZ)
def n_bool_f(s):
    return {"x": True * _g(s) - 2 * s.Ir}


@claim("n-fmpq", kind="id", sizes=SZ)
def n_fmpq(s):
    import flint
    return {"x": flint.fmpq(2, 1) * _g(s) - 2 * s.Ir}


@claim("n-fmpq-f", kind="id", sizes=SZ)
def n_fmpq_f(s):
    import flint
    return {"x": flint.fmpq(3, 1) * _g(s) - 2 * s.Ir}


@claim("n-fmpz", kind="id", sizes=SZ)
def n_fmpz(s):
    import flint
    return {"x": flint.fmpz(2) * _g(s) - 2 * s.Ir}


@claim("n-fmpz-f", kind="id", sizes=SZ)
def n_fmpz_f(s):
    import flint
    return {"x": flint.fmpz(3) * _g(s) - 2 * s.Ir}


@claim("n-sympy", kind="id", sizes=SZ)
def n_sympy(s):
    import sympy
    return {"x": sympy.Rational(1, 3) * (3 * _g(s)) - s.Ir}


@claim("n-sympy-f", kind="id", sizes=SZ)
def n_sympy_f(s):
    import sympy
    return {"x": sympy.Rational(1, 3) * (3 * _g(s)) - 2 * s.Ir}


@claim("n-decimal", kind="id", sizes=SZ)
def n_decimal(s):
    return {"x": Decimal("0.1") * (10 * _g(s)) - s.Ir}


@claim("n-frac-sub", kind="id", sizes=SZ)
def n_frac_sub(s):
    return {"x": F(1, 2) * _g(s) + F(1, 2) * _g(s) - s.Ir}


@claim("n-frac-sub-f", kind="id", sizes=SZ)
def n_frac_sub_f(s):
    return {"x": F(1, 3) * _g(s) + F(1, 3) * _g(s) - s.Ir}


@claim("n-frac-sub-c", kind="id", sizes=SZ)
def n_frac_sub_c(s):
    """F(1,2) + F(1,2) computed by the claim (its lying __add__ gives F(1,2)), then used: (1/2)·XᵀX − I_r FALSE
    whatever the engine does (the claim's own Python arithmetic is the claim's statement)."""
    return {"x": (F(1, 2) + F(1, 2)) * _g(s) - s.Ir}


@claim("n-index", kind="id", sizes=SZ)
def n_index(s):
    return {"x": s.q(I(2), 1) * _g(s) - 2 * s.Ir}


@claim("n-hash", kind="id", sizes=SZ)
def n_hash(s):
    big = 2**61 + 1
    return {"x": big * _g(s) - big * s.Ir + 2 * _g(s) - 2 * s.Ir}


@claim("n-hash-f", kind="id", sizes=SZ)
def n_hash_f(s):
    big = 2**61 + 1
    return {"x": big * _g(s) - 2 * s.Ir}


@claim("n-hash-f2", kind="id", sizes=SZ)
def n_hash_f2(s):
    """s.q(2**61+1) and s.q(2) in one graph, as two named-looking constants: (2**61+1)·XᵀX − 2·XᵀX ≠ 0, FALSE."""
    return {"x": s.q(2**61 + 1, 1) * _g(s) - s.q(2, 1) * _g(s)}
