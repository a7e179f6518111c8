"""A flow of one's own: the Euclidean Neumann flow with the potential ½tr(XᵀA²X).

From the shell:

    stiefelsym discover examples/my_flow.py:flow_A2 --max-a 2 --degree 2

or from Python (``python examples/my_flow.py``):

    from stiefelsym.claims import Size
    from stiefelsym.analyses.discover import conserved
    for line in conserved(flow_A2, Size(4, 2), degree=2, max_a=2).lines():
        print(line)
"""


def flow_A2(s):
    """Ẋ = P, Ṗ = −A²X − XPᵀP + XXᵀA²X: the Neumann flow of (NE_XP) with A² in place of A."""
    X, P, A2 = s.X, s.P, s.A @ s.A
    return {"X": P, "P": -(A2 @ X) - X @ P.T @ P + X @ X.T @ A2 @ X}


if __name__ == "__main__":
    from stiefelsym.claims import Size
    from stiefelsym.analyses.discover import conserved
    for line in conserved(flow_A2, Size(4, 2), degree=2, max_a=2).lines():
        print(line)
