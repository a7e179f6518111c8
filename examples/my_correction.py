"""A correction search of one's own: which multiplier term keeps the Euclidean Neumann flow on T*V?

The flow Ẋ = P, Ṗ = −AX + X·M must keep XᵀX = I_r and XᵀP + PᵀX = 0.  With M an unknown
combination of five r×r words, that is a linear question; its answer is an affine space:

    python examples/my_correction.py

(from Python only: the discover command runs no code of a file in the process that gives its verdicts)

print  X·M = XXᵀAX − XPᵀP  (the multiplier term of (NE_XP)), plus any multiple of XXᵀP and of
XXᵀAP − XPᵀAX (XᵀP and XᵀAP − PᵀAX are skew on T*V: they rotate the frame and keep the constraints
too), verified by the usual methods and by the dimension-free one for every n, r.
"""
from stiefelsym.claims import Size
from stiefelsym.analyses.discover import CorrectionAnsatz, Term, correction_space

WORDS = {
    "XXᵀAX": (r"XX^TAX", lambda s, w: w["X"] @ w["X"].T @ s.A @ w["X"]),
    "XPᵀP": (r"XP^TP", lambda s, w: w["X"] @ w["P"].T @ w["P"]),
    "XXᵀP": (r"XX^TP", lambda s, w: w["X"] @ w["X"].T @ w["P"]),
    "XXᵀAP": (r"XX^TAP", lambda s, w: w["X"] @ w["X"].T @ s.A @ w["P"]),
    "XPᵀAX": (r"XP^TAX", lambda s, w: w["X"] @ w["P"].T @ s.A @ w["X"]),
}


def keeps_the_constraints(s, slot):
    """d/dt of the constraints of T*V along Ẋ = P, Ṗ = −AX + slot."""
    tangent = {"X": s.P, "P": -(s.A @ s.X) + slot(s, {"X": s.X, "P": s.P})}
    return {"d(XᵀX)/dt": s.d(lambda t: t.X.T @ t.X, tangent),
            "d(XᵀP + PᵀX)/dt": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, tangent)}


ANSATZ = CorrectionAnsatz(
    claim="my-multiplier-term", label="(my flow)", slot="X·M", slot_latex="XM",
    terms=[Term(text, latex, f) for text, (latex, f) in WORDS.items()],
    residual=keeps_the_constraints, point=lambda s: {"X": s.X, "P": s.P},
    description="Σ c·W, W ∈ {" + ", ".join(WORDS) + "}", description_latex="five words",
    size=Size(4, 2), free=True)


if __name__ == "__main__":
    for line in correction_space(ANSATZ, verify=("auto", "free")).lines():
        print(line)
