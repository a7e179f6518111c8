# ruff: noqa
"""Writes one claims file per TeX probe (q64): the docstring and the statement are literals."""
PROBES = {
    "groups": ("XᵀX = 2I $" + "{" * 300 + "x" + "}" * 300 + "$.", "X^T X = 2 I_r"),
    "stmt_groups": ("XᵀX = 2I.", "X^T X = 2 I_r " + "{" * 300 + "}" * 300),
    "blankline": ("XᵀX = 2I.", "X^T X\n\n= 2 I_r"),
    "blank_doc": ("XᵀX = 2I $a\n\nb$ end.", "X^T X = 2 I_r"),
    "uncounted_env": ("XᵀX = 2I $\\begin {matrix} a$ and more.", "X^T X = 2 I_r"),
    "leftright": ("XᵀX = 2I $\\left( a$ end.", "X^T X = 2 I_r \\left("),
    "fracs": ("XᵀX = 2I $" + "\\frac{a}{" * 200 + "b" + "}" * 200 + "$.", "X^T X = 2 I_r"),
    "double_sup": ("XᵀX = 2I $a^b^c$.", "X^T X = 2 I_r"),
    "frac_dollar": ("XᵀX = 2I $\\frac$ end.", "X^T X = 2 I_r"),
}
for name, (doc, st) in PROBES.items():
    with open(f"{name}.py", "w") as f:
        f.write(f'from stiefelsym import claim\n\n\n@claim("q64-{name.replace("_", "-")}", kind="id", sizes=[(3, 2)], '
                f'statement={st!r})\ndef f(s):\n    {doc!r}\n    return {{"XtX": s.X.T @ s.X - 2 * s.Ir}}\n')
