"""A true claim, written with @claim (collected by the plugin)."""
from stiefelsym import admissible, claim


@claim("s62-pl-true", kind="id", sizes=admissible(n_max=3))
def true_one(s):
    """XᵀX = I on T*V."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}
