# ruff: noqa
"""Hand edits of the results of `verify --claims headline.py --method modular --report-dir /tmp/s65_rep1`
(small witness, witness value and residual, a `not` claim's certificate); each is rejected by `stiefelsym check`."""
import copy
import json
import sys

src = sys.argv[1] if len(sys.argv) > 1 else "/tmp/s65_rep1/results.json"
out = sys.argv[2] if len(sys.argv) > 2 else "/tmp/s65_ed"
d = json.load(open(src))


def save(name, f):
    e = copy.deepcopy(d)
    f(e)
    json.dump(e, open(f"{out}/{name}.json", "w"))


def small(e):
    s = e["results"][0]["witness"]["small"]
    s["value"] = "-7"
    s["letters"]["X"] = [["1"], ["0"]]
    s["letters"]["P"] = [["0"], ["5"]]


def value(e):
    e["results"][0]["witness"]["value"] = "-9 (mod 6094691473483085353)"
    e["results"][0]["residual"] = "r[1,1] = -9 (mod 6094691473483085353)"


def cert(e):
    for r in e["results"]:
        if r["claim"] == "hl-not-vanishes" and (r["n"], r["r"]) == (2, 1):
            r["certificate"] = "exactly zero: the residual reduces to 0 by the constraints (exact symbolic computation)"


save("small_edit", small)
save("value_edit", value)
save("cert_edit", cert)
