# ruff: noqa
"""Which errata does shared_misprints merge, with what labels and corrections (a results.json)."""
import sys
from stiefelsym.results import load_results
from stiefelsym.reports import report as R
meta, rs = load_results(sys.argv[1] if len(sys.argv) > 1 else "reports/results.json")
claims = R.group_by_claim(rs)
text, errata = R.headline(claims)
print(text)
for g in R.shared_misprints(errata):
    print([(c.id, c.paper, R._erratum_facts(c)["verified"]) for c in g])
