"""Class 7 (claim code changes how the engine encodes its graph): the seal watches json's public attributes and
the members of JSONEncoder/JSONDecoder by identity, but not json's private `_default_encoder` (the instance
json.dumps uses) nor that instance's own attributes.  While it is traced, the claim sets
json._default_encoder.encode (an instance attribute, shadowing the class's method); the engine's fingerprint
check after the trace passes, and the job's answer line is then encoded by the claim's function, which puts in
the graph of another function (traced by the engine's own _trace_one).

enc-swap  its code: residual X Xᵀ − I_n (FALSE at r < n).  What is sent: the graph of Xᵀ X − I_r (TRUE).
Right verdict: fails.  proved/checked = wrong verdict.
"""
import json
import sys

from stiefelsym import admissible, claim

_orig = json._default_encoder.encode


def _true(s):
    return {"x": s.X.T @ s.X - s.Ir}


def _encode(obj):
    if isinstance(obj, dict) and "job" in obj:
        uf = sys.modules["stiefelsym.run.userfile"]
        f = sys._getframe()
        while f is not None and f.f_code.co_name != "_jobs_lines":
            f = f.f_back
        key = f.f_locals.get("key") if f is not None else None
        try:
            real = f.f_locals["c"].realization
            obj = {"job": uf._trace_one(_true, real, key)}
        except BaseException:
            import traceback
            traceback.print_exc()
    return _orig(obj)


@claim("enc-swap", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def enc_swap(s):
    json._default_encoder.encode = _encode
    return {"x": s.X @ s.X.T - s.In}
