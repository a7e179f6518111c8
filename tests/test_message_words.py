"""The engine's own words in a record (certificates, messages, check details) state what the report prints: a bound
as m·10⁻ᵏ, never in E notation, and no "rank >= 0" offered as evidence of a lower bound."""
import re

from stiefelsym.ir.notation import power_of_ten
from stiefelsym.methods import fixed_size

E_NOTATION = re.compile(r"\d(?:\.\d+)?e-\d+")


def test_a_bound_is_written_as_a_power_of_ten():
    assert power_of_ten(1e-30) == "10⁻³⁰"
    assert power_of_ten(1.2e-36) == "1.2·10⁻³⁶" and power_of_ten(9.4e-31) == "9.4·10⁻³¹"
    assert power_of_ten(0) == "0" and power_of_ten(0.5) == "0.5"


def test_the_joint_bound_and_the_cap_of_random_points_read_as_powers_of_ten():
    text = fixed_size._joint_text([[1.1e-18, 1.1e-18]], 1.1e-18, 2, 1.21e-36)
    assert text == "(1.1·10⁻¹⁸)^2 = 1.2·10⁻³⁶"
    mixed = fixed_size._joint_text([[1e-18, 2e-18]], 2e-18, 2, 2e-36)
    cap = fixed_size._cap_text(1e-2, 1e-30)
    for words in (text, mixed, cap):
        assert not E_NOTATION.search(words), words
    assert "10⁻³⁰" in cap


def test_a_rank_0_at_a_point_is_no_lower_bound_in_the_record():
    """A two-sided rank whose rank at a point is 0 states that no lower bound is needed, not "rank >= 0"."""
    assert fixed_size._lower_words(0) == fixed_size.NO_LOWER_BOUND
    assert ">= 0" not in fixed_size._lower_words(0)
    assert fixed_size._lower_words(3) == "rank 3 at an exact rational point (rank >= 3 over the function field)"
