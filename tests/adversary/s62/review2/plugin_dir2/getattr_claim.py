import stiefelsym


def f(s):
    """FALSE: Psi = 0."""
    return {"Psi": s.Psi}


getattr(stiefelsym, "claim")("pd2-getattr", kind="id", sizes=stiefelsym.admissible(n_max=3))(f)
