"""Dimension-free backend: identities on T*V_{n,r} proved for every n and r at once.

Matrices become letters of a free algebra with involution (:mod:`.algebra`),
the constraints become a confluent rewriting system (:mod:`.rewriting`), trace
forms are cyclic words (:mod:`.traces`), and :class:`FreeScene` runs claim code
written for the coordinate scene (:mod:`.scene`).  Every reduction to 0 is
certified as a combination of the hypotheses (:meth:`RewritingSystem.certify`),
written as data by :mod:`.certificates` and re-checked by
:mod:`stiefelsym.certificate_check`.
"""
from stiefelsym.free.algebra import Letter, NCPoly, letter_pair, skew_letter, substitute, symmetric_letter, trace
from stiefelsym.free.rewriting import (Certificate, CertificateError, CertTerm, Cofactor, CompletionResult, CriticalPair, Hypothesis,
                        Order, Reduction, RewritingError, RewritingSystem, Rule, complete, critical_pairs,
                        is_confluent)
from stiefelsym.free.scene import FreeField, FreeScene, FreeSolveError, NeedsCoordinates, standard_system
from stiefelsym.free.traces import gradient

__all__ = [
    "Letter", "NCPoly", "letter_pair", "skew_letter", "symmetric_letter", "substitute", "trace",
    "CompletionResult", "CriticalPair", "Order", "Reduction", "RewritingError", "RewritingSystem", "Rule",
    "complete", "critical_pairs", "is_confluent",
    "Certificate", "CertificateError", "CertTerm", "Cofactor", "Hypothesis",
    "FreeField", "FreeScene", "FreeSolveError", "NeedsCoordinates", "standard_system", "gradient",
]
