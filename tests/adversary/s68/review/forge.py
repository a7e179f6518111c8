# ruff: noqa
"""Hand-edit a results.json written by `stiefelsym verify` (the forgeries of FINDINGS.md #F1, #F2).

python3 forge.py place   IN OUT   -- every record's `place` set to a phrase its claim never declared
python3 forge.py expected IN OUT -- every error / inconclusive record marked expected=True, with a forged erratum
                                    and place
"""
import json
import sys

mode, src, dst = sys.argv[1:4]
d = json.load(open(src))
for r in d["results"]:
    if mode == "place":
        r["place"] = "the abstract of an unrelated paper"
    elif mode == "expected" and r["verdict"] in ("error", "inconclusive"):
        r["expected"] = True
        r["erratum"] = "forged words: the paper is wrong here"
        r["place"] = "the abstract of an unrelated paper"
json.dump(d, open(dst, "w"), indent=1)
