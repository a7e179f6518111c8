"""s72 review: Rank with a kernel certificate (two-sided generic ranks), attempts R1-R7."""
from stiefelsym import Rank, admissible, claim

SIZES = admissible(n_max=4, where=lambda n, r: r < n)


@claim("s72-rk-true", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_true(s):
    """rank Xᵀ = r with kernel I − XXᵀ (true, two-sided)."""
    return {"rk": Rank(s.X.T, int(s.r), kernel=s.In - s.X @ s.X.T)}


@claim("s72-rk-off-v", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_off_v(s):
    """rank Xᵀ = r with kernel I − XXᵀ + tr(XᵀX − I_r)·G (equal to I − XXᵀ on V; true)."""
    G = s.generic("G", "n", "n")
    K = s.In - s.X @ s.X.T + s.tr(s.X.T @ s.X - s.Ir) * G
    return {"rk": Rank(s.X.T, int(s.r), kernel=K)}


@claim("s72-rk-off-v-false", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_off_v_false(s):
    """rank Xᵀ = r − 1 with the same kernel (false)."""
    G = s.generic("G", "n", "n")
    K = s.In - s.X @ s.X.T + s.tr(s.X.T @ s.X - s.Ir) * G
    return {"rk": Rank(s.X.T, int(s.r) - 1, kernel=K)}


@claim("s72-rk-tangent-kernel", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_tangent(s):
    """rank Xᵀ = r with kernel [I − XXᵀ, P − X XᵀP] (columns in the kernel on T*V: Xᵀ(P − XXᵀP) = 0; true)."""
    from stiefelsym import block
    K = block([[s.In - s.X @ s.X.T, s.P - s.X @ (s.X.T @ s.P)]])
    return {"rk": Rank(s.X.T, int(s.r), kernel=K)}


@claim("s72-rk-wrong-kernel-false", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_wrong_kernel(s):
    """rank Xᵀ = r − 1 with a wrong 'kernel' I (Xᵀ I ≠ 0): must not be used; false claim."""
    return {"rk": Rank(s.X.T, int(s.r) - 1, kernel=s.In)}


@claim("s72-rk-kernel-psi", paper="No", kind="dim", section="t", sizes=admissible(n_max=4, where=lambda n, r: 2 <= r < n))
def rk_kernel_psi(s):
    """rank [Xᵀ; Ψ Xᵀ]... rank of Xᵀ + Ψ Xᵀ = r with kernel I − XXᵀ (true: (I + Ψ) invertible)."""
    M = s.X.T + s.Psi @ s.X.T
    return {"rk": Rank(M, int(s.r), kernel=s.In - s.X @ s.X.T)}


@claim("s72-rk-kernel-r1", paper="No", kind="dim", section="t", sizes=admissible(n_max=4, where=lambda n, r: 2 <= r < n))
def rk_kernel_r1(s):
    """rank Ψ = 0 with kernel I_r (Ψ I_r = 0 holds at r = 1 only; false for r >= 2)."""
    return {"rk": Rank(s.Psi, 0, kernel=s.Ir)}


@claim("s72-rk-xxt", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_xxt(s):
    """rank XXᵀ = r with kernel I − XXᵀ + tr(XᵀX − I_r)·G (I − XXᵀ on V; true, two-sided)."""
    G = s.generic("G", "n", "n")
    K = s.In - s.X @ s.X.T + s.tr(s.X.T @ s.X - s.Ir) * G
    return {"rk": Rank(s.X @ s.X.T, int(s.r), kernel=K)}


@claim("s72-rk-xxt-high", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_xxt_high(s):
    """rank XXᵀ = r + 1 with the same kernel (false)."""
    G = s.generic("G", "n", "n")
    K = s.In - s.X @ s.X.T + s.tr(s.X.T @ s.X - s.Ir) * G
    return {"rk": Rank(s.X @ s.X.T, int(s.r) + 1, kernel=K)}


@claim("s72-rk-xxt-coords", paper="No", kind="dim", section="t", sizes=SIZES)
def rk_xxt_coords(s):
    """rank XXᵀ = r with kernel (I − XXᵀ)·E where E = diag(1, 0, ..., 0) + ... a matrix of given entries (true)."""
    n = int(s.n)
    E = s.mat([[1 if i == j else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    return {"rk": Rank(s.X @ s.X.T, int(s.r), kernel=(s.In - s.X @ s.X.T) @ E)}
