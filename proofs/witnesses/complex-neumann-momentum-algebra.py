"""After Theorem 10.3 the momentum psi_0 = Z^T conj(Z') - Z'^T conj(Z) of the complex Neumann system is said to be a
u(n) momentum map.  Z is n x r, so psi_0 is r x r: the momentum of the right U(r)-action, with values in u(r).
At (n, r) = (2, 1), psi_0 is 1 x 1 and a matrix of u(2) is 2 x 2."""
import sympy as sp

KIND = "count"
CHECK = "size of ψ₀ = n"
SIZE = (2, 1)


def counts():
    n, r = SIZE
    Z = sp.Matrix([[1], [0]])                  # a point of W(2, 1): conj(Z)^T Z = I_1
    Zd = sp.Matrix([[sp.I], [0]])              # conj(Z)^T Z' + conj(Z')^T Z = i - i = 0
    psi0 = Z.T * Zd.conjugate() - Zd.T * Z.conjugate()
    assert psi0.shape == (r, r) and psi0 == -psi0.H != sp.zeros(r, r)   # skew-Hermitian, nonzero: in u(r)
    return {"computed": psi0.shape[0], "printed": n, "corrected": r,
            "meaning": "the size of ψ₀ (r × r, r the number of columns of Z), against n, of u(n)"}
