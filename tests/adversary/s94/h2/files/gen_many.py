"""Write f6_many.py: 72 claims, words in X, P, A with true and false twins (more than the 64 results a process keeps)."""
import random
rng = random.Random(7)
lines = ['"""72 generated claims: true identities (constraint sandwiches) and false twins."""',
         "from stiefelsym import admissible, claim", ""]
truth = {}
words = ["s.X", "s.P", "s.A @ s.X", "s.A @ s.P", "s.X @ s.X.T @ s.P"]
for i in range(72):
    a = rng.choice(["s.X.T @ s.A @ s.X", "s.P.T @ s.P", "s.X.T @ s.X", "s.Ir", "s.P.T @ s.A @ s.P"])
    b = rng.choice(["s.X.T @ s.A @ s.X", "s.P.T @ s.P", "s.Ir", "s.X.T @ s.P - s.P.T @ s.X"])
    true = i % 2 == 0
    cons = "(s.X.T @ s.P + s.P.T @ s.X)" if true else "(s.X.T @ s.P)"
    expr = f"({a}) @ {cons} @ ({b}) + ({b}) @ {cons} @ ({a})"
    if i % 3 == 0:
        expr += " + s.X.T @ s.X - s.Ir"
    lines += [f'@claim("h2-m{i:02d}", kind="id", sizes=admissible(n_max=6), statement="generated {i}")',
              f"def m{i:02d}(s):", f'    """generated {i} ({"true" if true else "false at r >= 2"})"""',
              f'    return {{"r": {expr}}}', "", ""]
open("/tmp/s94h2/files/c6/f6_many.py", "w").write("\n".join(lines))
