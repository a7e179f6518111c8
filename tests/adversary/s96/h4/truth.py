"""Truth of this folder's claims at each size (decided by hand, see each claim's docstring), compared with every
record of the JSON files given (``stiefelsym verify --format json``): prints each wrong verdict and a count."""
import json
import sys

ALWAYS_TRUE = {"h4a-flow-tangent-X", "h4a-flow-tangent-P", "h4a-flow-conserves-H", "h4p-copy-true",
               "h4f-underflow-true", "h4f-underflow-nonzero", "h4k-two-mu-true"}
TRUE_AT = {"h4a-flow-tangent-false": lambda n, r: r == 1, "h4a-flow-conserves-false": lambda n, r: r == n}
PASS = {"proved", "checked", "numeric"}


def truth(cid, n, r):
    if cid in ALWAYS_TRUE:
        return True
    if cid in TRUE_AT:
        return TRUE_AT[cid](n, r) if n is not None else False
    if cid.startswith("h4t-"):                 # c2: "h4t-...-true" / "h4t-...-false"
        return cid.endswith("-true")
    return False


def main(paths):
    wrong = total = 0
    for path in paths:
        for rec in json.load(open(path))["results"]:
            cid, n, r, v = rec["claim"], rec.get("n"), rec.get("r"), rec["verdict"]
            total += 1
            t = truth(cid, n, r)
            if (v in PASS and not t) or (v == "fails" and t):
                wrong += 1
                print("WRONG", path, cid, n, r, rec["method"], v)
    print(f"{total} records, {wrong} wrong")


if __name__ == "__main__":
    main(sys.argv[1:])
