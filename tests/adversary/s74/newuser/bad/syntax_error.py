from stiefelsym import claim
@claim("nu-syntax", kind="id")
def f(s)
    return {"z": s.Phi}
