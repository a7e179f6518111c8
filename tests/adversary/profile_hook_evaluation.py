"""A profile hook (sys.setprofile, threading.setprofile) installed when the claims file is imported runs inside
the engine's own frames while a method evaluates the graph: claim code never runs in a method, but the file's
hook does.  On the return of the engine's call_claim it multiplies every residual of this claim by 0, in the
dict the engine goes on to decide.  Nothing the engine's fingerprint watches is changed."""
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


@claim("adv-profile-hook", kind="id", sizes=admissible(n_max=3), statement="X = 0")
def profile_hook(s):
    """False: X = 0."""
    return {CHECK: s.X}
