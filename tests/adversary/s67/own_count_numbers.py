# ruff: noqa
"""Stop 67, the stop's own attempt: the numbers of a Count (the size errata of this stop are Counts).  Each claim is
false unless its docstring says TRUE; a Count must compare the two numbers as integers, whatever type the claim
hands over (an int subclass that says it equals everything, a bool, a float, a numpy integer, a Fraction, a
string)."""
from fractions import Fraction

import numpy as np

from stiefelsym import Count, admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))


class Liar(int):
    def __eq__(self, other):
        return True

    def __ne__(self, other):
        return False

    __hash__ = int.__hash__


@claim("oc-liar-int", kind="dim", sizes=S)
def liar_int(s):
    """FALSE: the rows of X (3) counted as 2 by an int that equals everything."""
    return {"rows": Count(Liar(s.X.shape[0]) if isinstance(s.X.shape[0], int) else s.X.shape[0], Liar(2))}


@claim("oc-liar-printed", kind="dim", sizes=S)
def liar_printed(s):
    """FALSE: 3 rows, printed as Liar(7)."""
    return {"rows": Count(3, Liar(7))}


@claim("oc-bool", kind="dim", sizes=S)
def bool_count(s):
    """FALSE: True (1) against 2."""
    return {"rows": Count(True, 2)}


@claim("oc-float", kind="dim", sizes=S)
def float_count(s):
    """FALSE: 3.0000001 against 3 (a float must not round to the printed number)."""
    return {"rows": Count(3.0000001, 3)}


@claim("oc-numpy", kind="dim", sizes=S)
def numpy_count(s):
    """FALSE: numpy.int64(4) against 3."""
    return {"rows": Count(np.int64(4), 3)}


@claim("oc-fraction", kind="dim", sizes=S)
def fraction_count(s):
    """FALSE: 7/2 against 3."""
    return {"rows": Count(Fraction(7, 2), 3)}


@claim("oc-string", kind="dim", sizes=S)
def string_count(s):
    """FALSE: "3" against 3 (a string is not a number)."""
    return {"rows": Count("3", 3)}


@claim("oc-true", kind="dim", sizes=S)
def true_count(s):
    """TRUE: the rows of X, n = 3."""
    return {"rows": Count(3, s.n)}
