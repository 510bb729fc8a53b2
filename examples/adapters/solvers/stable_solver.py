"""solve(u, dy, phi) -> (s, which): the closed form of (A.2) without
cancellation (docs/equations.md, section 3). An example of a right solver for
check_python.py."""
import math
from fractions import Fraction


def split(x):
    c = 134217729.0 * x  # 2^27 + 1: Veltkamp's split
    upper = c - (c - x)
    return upper, x - upper


def exact_product(a, b):
    """a * b = high + low exactly (Dekker's product)."""
    high = a * b
    a1, a2 = split(a)
    b1, b2 = split(b)
    return high, ((a1 * b1 - high) + a1 * b2 + a2 * b1) + a2 * b2


def release(u, dy, phi):
    t = math.sqrt(u * u + 4 * phi * dy * dy)
    return 2 * phi * dy * dy / (u + t) if u >= 0 else (-u + t) / 2


def solve(u, dy, phi):
    if not all(map(math.isfinite, (u, dy, phi))) or phi < 0:
        return math.nan, 0
    if dy <= 0:
        if u <= -dy:
            return -u, 1
        # impact, (A.11): every term has the sign of s
        return (2 * phi * dy - u - math.sqrt(u * u - 4 * phi * dy * (u + dy))) / (2 * (1 + phi)), 2
    # the case from the exact sign of u + dy - phi dy: rounded, it errs near the boundary
    if Fraction(u) + Fraction(dy) - Fraction(phi) * Fraction(dy) >= 0:
        # contact, (A.19), with 2 phi dy carried exactly where u nearly cancels it
        high, low = exact_product(2 * phi, dy)
        return ((high - u) + low) / (1 + phi), 3
    return release(u, dy, phi), 4
