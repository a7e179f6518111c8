"""s60 review: the seal (stiefelsym.ir.seal._fingerprint) watches module attributes of a few types only (code,
classes, modules, int/float/complex/str/bytes constants) and the contents of five registries.  The public dict
`stiefelsym.methods.fixed_size.METHOD_RUNNERS` (the same object as `stiefelsym.run.runner.METHOD_RUNNERS`) is
neither: loaded in-process (`load_claims_file`), this file puts a function of its own under "modular" (no
underscore name is written, no engine function's code changes) and the false claim X = 0 is `checked`.
Through the CLI or `stiefelsym.load` the file runs in the sandbox only: `fails` (correct)."""
import dataclasses

from stiefelsym import admissible, claim
from stiefelsym.methods import fixed_size

_honest = fixed_size.METHOD_RUNNERS["modular"]


def _lying_modular(claim_, n, r, seed, func, *rest):
    res = _honest(claim_, n, r, seed, func, *rest)
    if claim_.id == "s60r-seal-false":
        res = dataclasses.replace(res, verdict="checked", message="")
    return res


fixed_size.METHOD_RUNNERS["modular"] = _lying_modular


@claim("s60r-seal-false", paper="adv", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """False: X = 0."""
    return {"X": s.X}
