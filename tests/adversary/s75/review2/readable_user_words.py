"""A user's own claims (no paper labels) whose words use names that happen to be label keys of the paper:
"(A2)" for a hypothesis of the user's, "(BB)" for a product, "(No)" as a word.  readable() rewrites them into
the paper's equation numbers.  The statement also carries a key in math mode (outside \\text)."""
from stiefelsym import claim


@claim("r2-user-hypothesis", kind="id", sizes=[(3, 2)],
       statement=r"X^TX=I_r\ \text{under (A2)},\quad \det(BB)\,(dot\_XP3*)=\det(BB)\,(dot\_XP3*)")
def user_hypothesis(s):
    """Under the user's hypothesis (A2), the Gram matrix (BB) is the identity; Theorem ET is not used."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}
