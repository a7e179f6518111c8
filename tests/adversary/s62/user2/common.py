"""Shared helpers (no claims): the Jensen-type Hamiltonian with a quartic potential.

H_c = 1/2 tr(P^T P) + c tr((X^T P)^2) + 1/4 tr((X^T A X)^2),   c a free scalar parameter.

Hand derivation (K = X^T P, skew on T*V; M = X^T A X):
  H_P = P + 2c X K^T,   H_X = A X M + 2c P K      (ambient gradients of H as written)
  Pi  = sym(X^T H_P) = (1 + 2c) sym K = 0          on T*V
  Lam = sym(X^T H_X - H_P^T P) = M^2 - P^T P
  Xdot = P - 2c X X^T P
  Pdot = -A X M + X M^2 - X P^T P - 2c P X^T P
Consequences: dPsi/dt = 0, dPhi/dt = [X M X^T, A], d(XX^T)/dt = [Phi, XX^T].
"""


def hamiltonian(c):
    def H(t):
        K = t.X.T @ t.P
        M = t.X.T @ t.A @ t.X
        return t.tr(t.P.T @ t.P) / 2 + c * t.tr(K @ K) + t.tr(M @ M) / 4
    return H


def hand_flow(s, c):
    X, P, A = s.X, s.P, s.A
    M = X.T @ A @ X
    return {"X": P - 2 * c * (X @ X.T @ P),
            "P": -(A @ X @ M) + X @ M @ M - X @ P.T @ P - 2 * c * (P @ X.T @ P)}
