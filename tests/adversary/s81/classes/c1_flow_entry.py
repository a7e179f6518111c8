"""Class 1 (chart choice), trick 2: an entry of X read only inside the function of a derivative along a flow.

On T*V: XᵀP + PᵀX = 0.  At the equivariant chart X = (I_r; 0) the top r×r block of P is skew, so P₀₀ = 0.
d/dt X₀₀ along Ẋ = P is P₀₀, which is NOT 0 at a generic point of T*V (r < n: P = X·skew + (I − XXᵀ)·free, and
(XΩ + X⊥K)₀₀ ≠ 0 generically).  c1-dflow-false states d/dt X₀₀ = 0; c1-dflow-true states d/dt X₀₀ − P₀₀ = 0.
Also through a block: the top-left entry as a 1×1 block of X, and through tr(E₀₀ X ·) in a gradient function.
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4, n_min=2)


@claim("c1-dflow-false", kind="id", sizes=SZ)
def c1_dflow_false(s):
    """FALSE: d/dt X₀₀ = 0 along Ẋ = P."""
    return {"r": s.d(lambda t: t.X[0, 0], {"X": s.P})}


@claim("c1-dflow-true", kind="id", sizes=SZ)
def c1_dflow_true(s):
    """TRUE: d/dt X₀₀ = P₀₀ along Ẋ = P (P₀₀ read outside the derivative too)."""
    return {"r": s.d(lambda t: t.X[0, 0], {"X": s.P}) - s.P[0, 0]}


@claim("c1-dblock-false", kind="id", sizes=SZ)
def c1_dblock_false(s):
    """FALSE: d/dt of the top-left 1×1 block of X, squared trace form, along Ẋ = P: 2X₀₀P₀₀ ... stated as
    d/dt tr(X[0:1,0:1]) = 0 (= P₀₀ ≠ 0)."""
    return {"r": s.d(lambda t: t.tr(t.X[0:1, 0:1]), {"X": s.P})}


@claim("c1-dsq-false", kind="id", sizes=SZ)
def c1_dsq_false(s):
    """FALSE: d/dt (X₀₀)² = 0 along Ẋ = P at a point of T*V (= 2X₀₀P₀₀; 0 on the chart where P₀₀ = 0)."""
    return {"r": s.d(lambda t: t.X[0, 0] * t.X[0, 0], {"X": s.P})}
