"""Round 5: twisted.kernel_frame's W was s.generic("W", "n", "r") at fixed sizes, the claim's own name: a claim's
generic matrix named W was the frame that twisted.kernel_annihilator annihilates (the dimension-free backend has
two letters)."""
from stiefelsym import admissible, claim
from stiefelsym.twisted import kernel_annihilator

SIZES = admissible(n_max=4)


@claim("adv-s35-kernel-frame-named-w", kind="id", sizes=SIZES)
def generic_named_w(s):
    """False: K G = 0 for a generic n×r matrix G of the claim's own, named W (K annihilates ker-frame W only)."""
    G = s.generic("W", "n", "r")
    return {"r": kernel_annihilator(s) @ G}


@claim("adv-s35-kernel-frame-named-v", kind="id", sizes=SIZES)
def generic_named_v(s):
    """False (control): K G = 0 for G named V."""
    return {"r": kernel_annihilator(s) @ s.generic("V", "n", "r")}
