# two_prod (float_tools.hpp), fused branch, for double:
#   product = a * b;  low = fma(a, b, -product);
# Claim: low is the exact error a * b - product (one rounding of an exact value that is
# representable), |low| <= 2^-52 and low is a multiple of 2^-104, for significands a, b in
# [1, 2] with binary64's 53 bits. Rounding with an unbounded exponent commutes with
# scaling a and b by powers of two, so for a = A 2^i, b = B 2^j the error is the one here
# times 2^(i+j). In the plain window (|a|, |b| in [2^-240, 2^240]) i + j >= -480, so a
# non-zero low is at least 2^-584 and at most 2^428: binary64 holds it as a normal number,
# and the bounded format rounds as the unbounded one. This is stays_in_contact's
# two_prod(phi, dy); the scaled path's two_prod of significands has i = j = -1.
#@ -Eprecision=200
#! refute: |low| <= 1b-52 => |low| <= 1b-54
#! refute: @FIX(low, -104) => @FIX(low, -103)
@rnd = float<53, ne>;
a = rnd(a_);
b = rnd(b_);
product = rnd(a * b);
low = rnd(a * b - product);   # fma(a, b, -product): one rounding of a * b - product

{ a in [1, 2] /\ b in [1, 2]
  -> low - (a * b - product) in [0, 0] /\ |low| <= 1b-52 /\ @FIX(low, -104) }
