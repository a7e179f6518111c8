# ruff: noqa
"""Does the hook of replay_observed_rev.py see the replay's sizes (the frames of _typed_at, in the tracing thread)?
In-process, as the file's child does: compile the claim with symbolic sizes, then at (3,2) uncached."""
import importlib, sys
from stiefelsym.claims import load_claims_file
from stiefelsym.ir import _compile
from stiefelsym.scene import REALIZATIONS
reg = load_claims_file("replay_observed_rev.py")
mod = [m for k, m in sys.modules.items() if k.startswith("stiefelsym_user_replay_observed_rev")][0]
c = [x for x in reg][0]
cons = REALIZATIONS["standard"]
g0 = _compile(c.func, None, None, (cons.name, cons.build), cached=False)
g1 = _compile(c.func, 3, 2, (cons.name, cons.build), cached=False)
g2 = _compile(c.func, None, None, (cons.name, cons.build), cached=False)
print("seen:", mod.SEEN, "hook now:", sys.gettrace())
print("symbolic graph before / after a replay differ:", g0.digest() != g2.digest())
