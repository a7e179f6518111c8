# ruff: noqa
"""Hand-edit a results.json: the small (hand) witness of every failing record that has one.
python forge_small.py MODE IN OUT
  value   -- the hand witness's value changed (-1 -> -7)
  letters -- the hand witness's matrices changed (X = [[2]]: off T*V)
  move    -- a small witness added to a later failing record that had none, taken from the first, at its size
"""
import json, sys, copy
mode, src, dst = sys.argv[1:4]
d = json.load(open(src))
first = None
for r in d["results"]:
    w = r.get("witness")
    if r["verdict"] != "fails" or not isinstance(w, dict):
        continue
    if isinstance(w.get("small"), dict):
        if mode == "value":
            w["small"]["value"] = "-7"
        elif mode == "letters":
            w["small"]["letters"]["X"] = [["2"] * len(row) for row in w["small"]["letters"]["X"]]
        elif mode == "move":
            if first is None:
                first = copy.deepcopy(w["small"]); del w["small"]
json.dump(d, open(dst, "w"), indent=1)
