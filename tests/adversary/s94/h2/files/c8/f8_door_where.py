from stiefelsym import admissible, claim


@claim("h2-door-where", kind="id", sizes=admissible(n_max=3, where=lambda n, r: n >= 2 * r, condition="n >= 2r"),
       statement="(n - n) X = 0")
def door_where(s):
    """true: reads n"""
    k = int(s.n)
    return {"r": (k - k) * s.X}
