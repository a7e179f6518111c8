"""The report shows one size's graph ("the smallest size with 1 < r < n"); the other sizes' graphs may be other
statements.

s9-so3-cubic: text at (3,2): ξ³ − ½tr(ξ²)ξ = 0 for ξ in so(n).  TRUE at n = 3 (Cayley-Hamilton in so(3)), FALSE at
  n = 4 (truth_numpy.py: |ξ³ − ½tr(ξ²)ξ| = 4.1 in so(4)).  The graph at n ≠ 3 is ξ + ξᵀ (TRUE, 0).  Every size
  proved; the report prints only (3,2)'s text, and says "the claim has a graph at each size, 3 in all" -- as it
  says for every honest claim that reads entries or numbers.
s10-xxt: the same with XXᵀ − Iₙ (TRUE only at r = n) shown at ... the shown size must have 1 < r < n, so the false
  graph cannot be the shown one (it would fail there); this claim shows XᵀX − Iᵣ at (3,2) and at r = n returns
  XXᵀ − Iₙ: honest; included as a control (expected: proved everywhere).
"""
from stiefelsym import admissible, claim


@claim("s9-so3-cubic", kind="id", sizes=admissible(n_max=4, where=lambda n, r: 1 < r < n))
def s9(s):
    """ξ³ = ½ tr(ξ²) ξ for ξ in so(n), n ≤ 4 (FALSE at n = 4)."""
    xi = s.xi
    if int(s.n) == 3:
        return {"cubic": xi @ xi @ xi - s.tr(xi @ xi) * xi / 2}
    return {"cubic": xi + xi.T}
