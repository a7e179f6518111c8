"""72 generated claims: true identities (constraint sandwiches) and false twins."""
from stiefelsym import admissible, claim

@claim("h2-m00", kind="id", sizes=admissible(n_max=6), statement="generated 0")
def m00(s):
    """generated 0 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m01", kind="id", sizes=admissible(n_max=6), statement="generated 1")
def m01(s):
    """generated 1 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m02", kind="id", sizes=admissible(n_max=6), statement="generated 2")
def m02(s):
    """generated 2 (true)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m03", kind="id", sizes=admissible(n_max=6), statement="generated 3")
def m03(s):
    """generated 3 (false at r >= 2)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m04", kind="id", sizes=admissible(n_max=6), statement="generated 4")
def m04(s):
    """generated 4 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m05", kind="id", sizes=admissible(n_max=6), statement="generated 5")
def m05(s):
    """generated 5 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m06", kind="id", sizes=admissible(n_max=6), statement="generated 6")
def m06(s):
    """generated 6 (true)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + s.X.T @ s.X - s.Ir}


@claim("h2-m07", kind="id", sizes=admissible(n_max=6), statement="generated 7")
def m07(s):
    """generated 7 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m08", kind="id", sizes=admissible(n_max=6), statement="generated 8")
def m08(s):
    """generated 8 (true)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m09", kind="id", sizes=admissible(n_max=6), statement="generated 9")
def m09(s):
    """generated 9 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m10", kind="id", sizes=admissible(n_max=6), statement="generated 10")
def m10(s):
    """generated 10 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P)}


@claim("h2-m11", kind="id", sizes=admissible(n_max=6), statement="generated 11")
def m11(s):
    """generated 11 (false at r >= 2)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m12", kind="id", sizes=admissible(n_max=6), statement="generated 12")
def m12(s):
    """generated 12 (true)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m13", kind="id", sizes=admissible(n_max=6), statement="generated 13")
def m13(s):
    """generated 13 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m14", kind="id", sizes=admissible(n_max=6), statement="generated 14")
def m14(s):
    """generated 14 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X)}


@claim("h2-m15", kind="id", sizes=admissible(n_max=6), statement="generated 15")
def m15(s):
    """generated 15 (false at r >= 2)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m16", kind="id", sizes=admissible(n_max=6), statement="generated 16")
def m16(s):
    """generated 16 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m17", kind="id", sizes=admissible(n_max=6), statement="generated 17")
def m17(s):
    """generated 17 (false at r >= 2)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m18", kind="id", sizes=admissible(n_max=6), statement="generated 18")
def m18(s):
    """generated 18 (true)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m19", kind="id", sizes=admissible(n_max=6), statement="generated 19")
def m19(s):
    """generated 19 (false at r >= 2)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.X)}


@claim("h2-m20", kind="id", sizes=admissible(n_max=6), statement="generated 20")
def m20(s):
    """generated 20 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m21", kind="id", sizes=admissible(n_max=6), statement="generated 21")
def m21(s):
    """generated 21 (false at r >= 2)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.A @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m22", kind="id", sizes=admissible(n_max=6), statement="generated 22")
def m22(s):
    """generated 22 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m23", kind="id", sizes=admissible(n_max=6), statement="generated 23")
def m23(s):
    """generated 23 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m24", kind="id", sizes=admissible(n_max=6), statement="generated 24")
def m24(s):
    """generated 24 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m25", kind="id", sizes=admissible(n_max=6), statement="generated 25")
def m25(s):
    """generated 25 (false at r >= 2)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m26", kind="id", sizes=admissible(n_max=6), statement="generated 26")
def m26(s):
    """generated 26 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X)}


@claim("h2-m27", kind="id", sizes=admissible(n_max=6), statement="generated 27")
def m27(s):
    """generated 27 (false at r >= 2)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m28", kind="id", sizes=admissible(n_max=6), statement="generated 28")
def m28(s):
    """generated 28 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P)}


@claim("h2-m29", kind="id", sizes=admissible(n_max=6), statement="generated 29")
def m29(s):
    """generated 29 (false at r >= 2)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m30", kind="id", sizes=admissible(n_max=6), statement="generated 30")
def m30(s):
    """generated 30 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m31", kind="id", sizes=admissible(n_max=6), statement="generated 31")
def m31(s):
    """generated 31 (false at r >= 2)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.X)}


@claim("h2-m32", kind="id", sizes=admissible(n_max=6), statement="generated 32")
def m32(s):
    """generated 32 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X)}


@claim("h2-m33", kind="id", sizes=admissible(n_max=6), statement="generated 33")
def m33(s):
    """generated 33 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m34", kind="id", sizes=admissible(n_max=6), statement="generated 34")
def m34(s):
    """generated 34 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P)}


@claim("h2-m35", kind="id", sizes=admissible(n_max=6), statement="generated 35")
def m35(s):
    """generated 35 (false at r >= 2)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.P)}


@claim("h2-m36", kind="id", sizes=admissible(n_max=6), statement="generated 36")
def m36(s):
    """generated 36 (true)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + s.X.T @ s.X - s.Ir}


@claim("h2-m37", kind="id", sizes=admissible(n_max=6), statement="generated 37")
def m37(s):
    """generated 37 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m38", kind="id", sizes=admissible(n_max=6), statement="generated 38")
def m38(s):
    """generated 38 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X)}


@claim("h2-m39", kind="id", sizes=admissible(n_max=6), statement="generated 39")
def m39(s):
    """generated 39 (false at r >= 2)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.A @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m40", kind="id", sizes=admissible(n_max=6), statement="generated 40")
def m40(s):
    """generated 40 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m41", kind="id", sizes=admissible(n_max=6), statement="generated 41")
def m41(s):
    """generated 41 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m42", kind="id", sizes=admissible(n_max=6), statement="generated 42")
def m42(s):
    """generated 42 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m43", kind="id", sizes=admissible(n_max=6), statement="generated 43")
def m43(s):
    """generated 43 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X)}


@claim("h2-m44", kind="id", sizes=admissible(n_max=6), statement="generated 44")
def m44(s):
    """generated 44 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X)}


@claim("h2-m45", kind="id", sizes=admissible(n_max=6), statement="generated 45")
def m45(s):
    """generated 45 (false at r >= 2)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m46", kind="id", sizes=admissible(n_max=6), statement="generated 46")
def m46(s):
    """generated 46 (true)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.X)}


@claim("h2-m47", kind="id", sizes=admissible(n_max=6), statement="generated 47")
def m47(s):
    """generated 47 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m48", kind="id", sizes=admissible(n_max=6), statement="generated 48")
def m48(s):
    """generated 48 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m49", kind="id", sizes=admissible(n_max=6), statement="generated 49")
def m49(s):
    """generated 49 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m50", kind="id", sizes=admissible(n_max=6), statement="generated 50")
def m50(s):
    """generated 50 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P)}


@claim("h2-m51", kind="id", sizes=admissible(n_max=6), statement="generated 51")
def m51(s):
    """generated 51 (false at r >= 2)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m52", kind="id", sizes=admissible(n_max=6), statement="generated 52")
def m52(s):
    """generated 52 (true)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir)}


@claim("h2-m53", kind="id", sizes=admissible(n_max=6), statement="generated 53")
def m53(s):
    """generated 53 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m54", kind="id", sizes=admissible(n_max=6), statement="generated 54")
def m54(s):
    """generated 54 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m55", kind="id", sizes=admissible(n_max=6), statement="generated 55")
def m55(s):
    """generated 55 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m56", kind="id", sizes=admissible(n_max=6), statement="generated 56")
def m56(s):
    """generated 56 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P)}


@claim("h2-m57", kind="id", sizes=admissible(n_max=6), statement="generated 57")
def m57(s):
    """generated 57 (false at r >= 2)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P) @ (s.P.T @ s.A @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m58", kind="id", sizes=admissible(n_max=6), statement="generated 58")
def m58(s):
    """generated 58 (true)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir)}


@claim("h2-m59", kind="id", sizes=admissible(n_max=6), statement="generated 59")
def m59(s):
    """generated 59 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m60", kind="id", sizes=admissible(n_max=6), statement="generated 60")
def m60(s):
    """generated 60 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m61", kind="id", sizes=admissible(n_max=6), statement="generated 61")
def m61(s):
    """generated 61 (false at r >= 2)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.P.T @ s.P)}


@claim("h2-m62", kind="id", sizes=admissible(n_max=6), statement="generated 62")
def m62(s):
    """generated 62 (true)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P)}


@claim("h2-m63", kind="id", sizes=admissible(n_max=6), statement="generated 63")
def m63(s):
    """generated 63 (false at r >= 2)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m64", kind="id", sizes=admissible(n_max=6), statement="generated 64")
def m64(s):
    """generated 64 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m65", kind="id", sizes=admissible(n_max=6), statement="generated 65")
def m65(s):
    """generated 65 (false at r >= 2)"""
    return {"r": (s.X.T @ s.X) @ (s.X.T @ s.P) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P) @ (s.X.T @ s.X)}


@claim("h2-m66", kind="id", sizes=admissible(n_max=6), statement="generated 66")
def m66(s):
    """generated 66 (true)"""
    return {"r": (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.P) + (s.P.T @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.A @ s.X) + s.X.T @ s.X - s.Ir}


@claim("h2-m67", kind="id", sizes=admissible(n_max=6), statement="generated 67")
def m67(s):
    """generated 67 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P) @ (s.Ir)}


@claim("h2-m68", kind="id", sizes=admissible(n_max=6), statement="generated 68")
def m68(s):
    """generated 68 (true)"""
    return {"r": (s.P.T @ s.A @ s.P) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir) + (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.P.T @ s.A @ s.P)}


@claim("h2-m69", kind="id", sizes=admissible(n_max=6), statement="generated 69")
def m69(s):
    """generated 69 (false at r >= 2)"""
    return {"r": (s.P.T @ s.P) @ (s.X.T @ s.P) @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ (s.X.T @ s.P) @ (s.P.T @ s.P) + s.X.T @ s.X - s.Ir}


@claim("h2-m70", kind="id", sizes=admissible(n_max=6), statement="generated 70")
def m70(s):
    """generated 70 (true)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P + s.P.T @ s.X) @ (s.Ir)}


@claim("h2-m71", kind="id", sizes=admissible(n_max=6), statement="generated 71")
def m71(s):
    """generated 71 (false at r >= 2)"""
    return {"r": (s.Ir) @ (s.X.T @ s.P) @ (s.X.T @ s.P - s.P.T @ s.X) + (s.X.T @ s.P - s.P.T @ s.X) @ (s.X.T @ s.P) @ (s.Ir)}

