"""A helper of the same module name as tests/adversary/s62/hidden/common.py, with another H_neumE."""


def H_neumE(t):
    """The free kinetic energy 1/2 tr(P^T P) (NOT the hidden folder's Neumann Hamiltonian)."""
    return t.tr(t.P.T @ t.P) / 2
