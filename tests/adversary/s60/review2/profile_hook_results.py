"""s60 review2 (in-process reproduction of tests/adversary/profile_hook_evaluation.py, closed for the CLI by stage
separation only): a profile hook installed at import runs inside the engine's frames while a method evaluates:
on the return of stiefelsym.methods.fixed_size.call_claim it multiplies the residuals of this claim by 0 in the
dict the method goes on to decide.  No engine attribute is written; the seal's fingerprint is unchanged."""
import sys
import threading

from stiefelsym import admissible, claim

CHECK = "X (hooked)"


def _hook(frame, event, arg):
    if event == "return" and frame.f_code.co_name == "call_claim" and isinstance(arg, dict) and CHECK in arg:
        for k in list(arg):
            arg[k] = arg[k] * 0


sys.setprofile(_hook)
threading.setprofile(_hook)


@claim("s60r2-profile-x-zero", paper="adv", kind="id", sizes=admissible(n_max=3))
def x_zero(s):
    """False: X = 0."""
    return {CHECK: s.X}
