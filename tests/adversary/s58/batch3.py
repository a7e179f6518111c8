"""s58 batch 3: entries of engine values of unknown shape (kind 'value': the trace knows no axis length,
so the new range check does not apply; each backend indexes)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


@claim("s58-op-entry-oob", kind="id", sizes=SZ)
def op_entry_oob(s):
    """𝔸(ξ)[5, 5] at n = 3 (an engine value: no range known at trace time)."""
    AA = s.sym_operator("AA")
    return {"x": AA(s.xi)[5, 5]}


@claim("s58-op-entry-neg-true", kind="id", sizes=SZ)
def op_entry_neg_true(s):
    """𝔸(ξ)[-1, 0] + 𝔸(ξ)[0, -1] = 0 (TRUE: 𝔸 maps so(n) to so(n))."""
    AA = s.sym_operator("AA")
    V = AA(s.xi - s.xi.T)
    return {"x": V[-1, 0] + V[0, -1]}


@claim("s58-op-entry-neg-oob", kind="id", sizes=SZ)
def op_entry_neg_oob(s):
    """𝔸(ξ)[-4, 0] at n = 3 (negative, out of range)."""
    AA = s.sym_operator("AA")
    return {"x": AA(s.xi - s.xi.T)[-4, 0]}


@claim("s58-op-slice-oob-false", kind="id", sizes=SZ)
def op_slice_oob_false(s):
    """𝔸(ξ−ξᵀ)[5:, :] is an empty block; claim: tr(Bᵀ B) − 1 = 0 (FALSE)."""
    AA = s.sym_operator("AA")
    B = AA(s.xi - s.xi.T)[5:, :]
    return {"x": s.tr(B.T @ B) - 1}


@claim("s58-op-slice-step-true", kind="id", sizes=SZ)
def op_slice_step_true(s):
    """V = 𝔸(ξ−ξᵀ) skew: tr(V[::-1, ::-1]) = tr V = 0 (TRUE)."""
    AA = s.sym_operator("AA")
    V = AA(s.xi - s.xi.T)
    return {"x": s.tr(V[::-1, ::-1])}


@claim("s58-op-entry-int-idx", kind="id", sizes=SZ)
def op_entry_int_idx(s):
    """𝔸(ξ)[0] (one int index on an engine value: an item)."""
    AA = s.sym_operator("AA")
    return {"x": AA(s.xi - s.xi.T)[0]}


@claim("s58-op-entry-int-idx-oob", kind="id", sizes=SZ)
def op_entry_int_idx_oob(s):
    """𝔸(ξ)[7] (one int index, out of range)."""
    AA = s.sym_operator("AA")
    return {"x": AA(s.xi - s.xi.T)[7]}


@claim("s58-conj-any-oob", kind="id", sizes=SZ)
def conj_any_oob(s):
    """conj of an engine value, entry out of range."""
    AA = s.sym_operator("AA")
    return {"x": s.conj(AA(s.xi - s.xi.T))[9, 0]}


@claim("s58-mixed-matmul-oob", kind="id", sizes=SZ)
def mixed_matmul_oob(s):
    """X^T 𝔸(ξ) X is r x r, entry [2, 0] (value kind: unchecked)."""
    AA = s.sym_operator("AA")
    M = s.X.T @ AA(s.xi - s.xi.T) @ s.X
    return {"x": M[2, 0]}


@claim("s58-mixed-matmul-neg-true", kind="id", sizes=SZ)
def mixed_matmul_neg_true(s):
    """Xᵀ𝔸(ξ−ξᵀ)X is skew: M[-1,-1] = 0 (TRUE)."""
    AA = s.sym_operator("AA")
    M = s.X.T @ AA(s.xi - s.xi.T) @ s.X
    return {"x": M[-1, -1]}
