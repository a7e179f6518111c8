"""Words with ASCII scripts in a user's erratum and correction (item 4 of the brief).

The erratum's words are false as printed (the claim fails) and are set by tex_words / unicode_words:
  * "f^(k)" is the k-th derivative (parentheses = order of differentiation), set as the power f^k;
  * "x^(1)^(2)" (first component, squared... as a user may write an iterated script) is set x¹² in Markdown;
  * "d^10X/dt^10" keeps a literal caret in the numerator (only one digit is taken), while dt^10 is set;
  * "u^(é)", an accented letter as a script, makes pdflatex stop with "Please use \\mathaccent".
"""
from stiefelsym import claim


@claim("s76r2-words", kind="id", sizes=[(3, 2)], fails_at=lambda n, r: True,
       erratum="The tenth derivative d^10X/dt^10 = 0 is stated, with f^(k) the k-th derivative of f "
               "(not its k-th power) and the component x^(1)^(2); the weight u^(é) is taken from the text.")
def words(s):
    """XᵀX = 2Iᵣ (false)."""
    return {"res": s.X.T @ s.X - s.Ir * 2}


@words.claim.correction("f^(k) and d^10X/dt^10 read as printed; XᵀX = Iᵣ")
def words_corrected(s):
    return {"res": s.X.T @ s.X - s.Ir}
