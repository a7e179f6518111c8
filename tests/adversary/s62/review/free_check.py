"""free 'proved' claims must be true at every size numpy checks."""
import json
import subprocess
import sys
seed = sys.argv[1]
res = json.load(open(f"out/f{seed}_free.json"))["results"]
truths = {sz: json.loads(subprocess.run([sys.executable, "numpy_truth.py", seed, *sz.split()], capture_output=True,
                                        text=True, check=True).stdout) for sz in ("3 2", "3 3", "4 2", "4 4", "5 3")}
bad = [(r["claim"], r["verdict"]) for r in res if r["verdict"] == "proved" and not all(t[r["claim"]] for t in truths.values())]
missed = [r["claim"] for r in res if r["verdict"] != "proved" and all(t[r["claim"]] for t in truths.values())]
print("free proved:", sum(r["verdict"] == "proved" for r in res), "WRONG:", bad, "true but not proved:", len(missed))
