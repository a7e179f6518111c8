"""Round 16: a record at a size its claim is not stated for, spliced into a results file.

XXᵀ = I_n is stated at r = n only (true there; false at every r < n).  The same claim id stated at every r
(the file run with STIEFELSYM_TEST_WIDE=1, a baked copy) gives a genuine `fails` record at (3,1); spliced into
the results of the run at (3,3), it is the record of a run of the same graph, with the same digest, so a check
that re-runs it agrees with it: before this round `check` accepted it and `report` wrote a note for the
authors that the statement fails at r = 1, where it says nothing.  A second claim holds at every r (XᵀX = I_r)
and is stated at n >= 3 only: its record at (2,2) (a size it does not state) is a true `proved`, refused all
the same; its record at (4,2), a stated size the command did not ask for, is refused too (a results file is
the whole run of its command)."""
import os

from stiefelsym import admissible, claim

WIDE = os.environ.get("STIEFELSYM_TEST_WIDE") == "1"


@claim("adv-s42-square-only", paper="adv", kind="id",
       sizes=admissible(n_max=3) if WIDE else admissible(n_max=3, r_is_n=True))
def square_only(s):
    """XXᵀ = I_n (r = n: X is orthogonal)."""
    return {"XXt": s.X @ s.X.T - s.In}


@claim("adv-s42-from-three", paper="adv", kind="id",
       sizes=admissible(n_max=4) if WIDE else admissible(n_max=4, n_min=3))
def from_three(s):
    """XᵀX = I_r, stated for n >= 3."""
    return {"XtX": s.X.T @ s.X - s.Ir}
