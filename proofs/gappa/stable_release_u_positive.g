# Branch: solve_stable, dy > 0 and not stays_in_contact, case (A.32),
# stable_form::release(u, dy, phi), sub-branch u > 0 (the rationalised root, compensated;
# release_with_square_root, stiffness_of, release_term, release_denominator,
# rationalised_quotient):
#   phi_dy = phi * dy;  phi_dy_error = fused_multiply_add(phi, dy, -phi_dy);
#   high = phi_dy * dy;  low = fma(phi_dy_error, dy, fma(phi_dy, dy, -high));
#   root = sqrt(fma(u, u, Num(4) * (high + low)));  u_plus_root = two_sum(u, root);
#   inverse = Num(1) / u_plus_root.high;  twice = Num(2) * high;
#   quotient = twice * inverse;
#   residual = fma(-quotient, u_plus_root.high, twice);
#   correction = fma(-quotient, u_plus_root.low, residual + Num(2) * low);
#   return fma(correction, inverse, quotient);
# Below: p = phi_dy, p_low = phi_dy_error, st = high, st_err, st_low = low, (den, den_low)
# = u_plus_root, q = quotient, two_st = twice, m = residual + 2 st_low. fma is
# fused_multiply_add, std::fma for double: one rounding. two_sum is Knuth's
# (detail::two_sum), written out operation by operation. With a subnormal phi the code
# forms phi dy from normal factors of the same exact product (factors_of): same values.
#
# Arithmetic: float<53,ne>, binary64 significands with an unbounded exponent (see
# stable_contact.g and proofs/README.md), but for the residual's and the correction's
# roundings (underflow, below). Rescaling: multiplying u and dy by 2^k multiplies each
# intermediate by 2^(k d), d its degree in (u, dy) (2 for st, st_low, the residual and the
# correction, -1 for inverse), exactly, and leaves the relative error as it is; a k brings
# St = phi dy^2 into [1, 4]. phi > 1 (u > 0, dy > 0 and u < dy (phi - 1)); above that phi
# covers all doubles, so dy^2 <= St <= 4 and dy^2 >= 1 / phi >= 2^-1100; with 2^k
# between 2^-1537 and 2^1075, u, a positive double times 2^k, lies in [2^-3000, 2^3000].
# u / R lies in (0, 1] (smt/stable/release_root_share.smt2; Gappa knows no identity of
# square roots).
#
# Exactness hypotheses, each "x - (exact value) in [0, 0]": fma(phi, dy, -p) and
# fma(p, dy, -st) are the exact errors of their products (facts/two_prod_exact.g), and
# two_sum's low part that of its sum (Knuth's theorem; proofs.exact_sum_exhaustive). That
# the operations below are the code's, in its order, model_agreement checks bit for bit.
#
# Underflow: in double a rounding whose exact value lies below 2^-1022 rounds on the
# subnormal grid, of spacing 2^-1074. Where the moved stage runs, window.hpp's bands keep
# phi dy^2 >= 2^-918 (2^-720 in the plain window), so 4^k <= 2^920, and a value of
# degree 2 sees in the frame a grid of spacing 2^t, t <= -154. The window proofs
# (gappa/window/) keep phi dy, st, the discriminant, the root and den normal, and p_low,
# st_err and st_low exact or normal; inverse is normal, as the boxes with phi > 1 keep
# u + root below 2^513; the solver checks at run time that q and s are normal. A sum of
# doubles whose value lies below 2^-1022 is a multiple of 2^-1074, so exact (m's and
# two_sum's), as are the scalings by 2 and 4. That leaves the residual and the
# correction, each written as the unbounded rounding plus an underflow term in
# [-2^-154, 2^-154]: for any x, the grid's rounding equals the 53-bit unbounded one where
# |x| >= 2^(t + 52), and otherwise both lie within 2^(t - 1) of x, so they differ by at
# most 2^t.
#
# The hints: phi dy^2 is the pair st + st_low, to 2^-104 of it, bounded absolutely in the
# frame St in [1, 4]; its rounded sum and the fma round the discriminant twice, which
# gives the root an error of 2 units of 2^-53 where u << sqrt(phi) dy, and there the
# root's share of u + root is 1. The quotient by den is corrected by the residual
# 2 (st + st_low) - q (den + den_low), exact but for roundings of terms of order 2^-53 St
# and the underflow terms, so that the corrected quotient y is within 2^-99 of
# 2 (st + st_low) / (u + root), relatively: what is left is the root's error (2) and the
# last rounding (1), 3 units of 2^-53 and a second-order term, 3.0000000000000088 ulps.
# 200-bit interval ends: at Gappa's default 60 bits the root's 2-unit error is rounded
# outward to 2 + 2^-7 units, which gives 3.0156. Change threshold 0: by default Gappa
# keeps a new enclosure only if it improves on the old by a set fraction (0.01), so which
# of two nearly equal ones stands follows the order of its search, and the bound's last
# digits may change from run to run; with 0 every narrower one replaces the old. Each
# hint is an identity, which Gappa checks; the denominators it assumes non-zero (phi dy,
# p dy, St, the discriminants, R, u + R, den, u + root, st + st_low, 2 st inverse, y) are
# positive here.
# Five mutants of this model that model_agreement cannot tell apart by testing: an fma
# whose product is of order 2^-53 s or 2^-53 St split into two roundings changes s only
# where an exact sum lies within about 2^-106 s of a rounding boundary, about one input
# in 2^50; and the underflow terms are 0 on its inputs, where every value is normal.
#! indistinguishable: fma split in s: the product correction * inverse is of order 2^-53 s
#! indistinguishable: fma split in correction: the product q * den_low is of order 2^-53 St
#! indistinguishable: fma split in st_low: the product p_low * dy is of order 2^-53 St
#! indistinguishable: + -> - in residual: its underflow term is 0 on normal values
#! indistinguishable: + -> - in correction: its underflow term is 0 on normal values
#@ -Eprecision=200
#@ -Echange-threshold=0
@rnd = float<53, ne>;
u = rnd(u_);
dy = rnd(dy_);
phi = rnd(phi_);

p = rnd(phi * dy);
p_low = rnd(fma(phi, dy, -p));
st = rnd(p * dy);
st_err = rnd(fma(p, dy, -st));
st_low = rnd(fma(p_low, dy, st_err));
disc = rnd(fma(u, u, 4 * rnd(st + st_low)));
root = rnd(sqrt(disc));
den = rnd(u + root);
den_bv = rnd(den - u);
den_av = rnd(den - den_bv);
den_low = rnd(rnd(u - den_av) + rnd(root - den_bv));
inverse = rnd(1 / den);
two_st = 2 * st;
q = rnd(two_st * inverse);
residual = rnd(fma(-q, den, two_st)) + residual_underflow;
m = rnd(residual + 2 * st_low);
correction = rnd(fma(-q, den_low, m)) + correction_underflow;
s = rnd(fma(correction, inverse, q));

St = phi * dy * dy;
Disc = u * u + 4 * St;
R = sqrt(Disc);
S = 2 * St / (u + R);

Stc = st + st_low;
Dn = u + root;
Er = (root - R) / R;
y = fma(correction, inverse, q);
Qc = 2 * Stc / Dn;
Cw = 2 * Stc - q * Dn;

{ u in [1b-3000, 1b3000] /\ dy in [1b-600, 2] /\ phi in [1, 1b1100] /\ St in [1, 4] /\ u / R in [0, 1]
  /\ p_low - (phi * dy - p) in [0, 0]
  /\ st_err - (p * dy - st) in [0, 0]
  /\ den_low - (u + root - den) in [0, 0]
  /\ residual_underflow in [-1b-154, 1b-154] /\ correction_underflow in [-1b-154, 1b-154]
  -> s -/ S in ? /\ disc -/ Disc in ? /\ Er in ? /\ y -/ Qc in ? /\ Stc - St in ? }

# phi dy^2 as the pair st + st_low, absolutely in the frame St in [1, 4]
p * dy -> St * (1 + (p - phi * dy) / (phi * dy));
p_low * dy -> (p_low - (phi * dy - p)) * dy - ((p - phi * dy) / (phi * dy)) * St;
st_err -> (st_err - (p * dy - st)) - ((st - p * dy) / (p * dy)) * (p * dy);
fma(p_low, dy, st_err) -> p_low * dy + st_err;
Stc - St -> (st_low - fma(p_low, dy, st_err)) + (p_low - (phi * dy - p)) * dy + (st_err - (p * dy - st));

# the discriminant and its root
(rnd(st + st_low) - St) / St -> ((rnd(st + st_low) - (st + st_low)) / (st + st_low)) * ((st + st_low) / St) + (Stc - St) / St;
St / Disc -> 1 / (4 + (u * u) / St);
fma(u, u, 4 * rnd(st + st_low)) / Disc -> 1 + 4 * ((rnd(st + st_low) - St) / St) * (St / Disc);
(disc - Disc) / Disc -> ((disc - fma(u, u, 4 * rnd(st + st_low))) / fma(u, u, 4 * rnd(st + st_low))) * (fma(u, u, 4 * rnd(st + st_low)) / Disc) + 4 * ((rnd(st + st_low) - St) / St) * (St / Disc);

# the result: the quotient, the numerator's pair, the denominator's root share
(Dn - (u + R)) / (u + R) -> Er * (R / (u + R));
R / (u + R) -> 1 / (1 + u / R);
(s - S) / S -> (1 + (s - y) / y) * (1 + (y - Qc) / Qc) * (1 + (Stc - St) / St) / (1 + (Dn - (u + R)) / (u + R)) - 1;

# the corrected quotient, absolutely in the same frame
inverse * den -> 1 + (inverse - 1 / den) / (1 / den);
den_low / den -> (den_low - (u + root - den)) / den - ((den - (u + root)) / (u + root)) * (1 / (1 + (den - (u + root)) / (u + root)));
inverse * Dn - 1 -> (inverse * den) * (1 + den_low / den - (den_low - (u + root - den)) / den) - 1;
q * den -> two_st * ((1 + (q - two_st * inverse) / (two_st * inverse)) * (inverse * den));
q * den_low -> (q * den) * (den_low / den);
fma(-q, den, two_st) -> two_st - q * den;
two_st - q * den -> two_st * (1 - (1 + (q - two_st * inverse) / (two_st * inverse)) * (inverse * den));
fma(-q, den_low, m) -> m - q * den_low;
residual -> (rnd(fma(-q, den, two_st)) - fma(-q, den, two_st)) + residual_underflow + (two_st - q * den);
m -> (m - (residual + 2 * st_low)) + residual + 2 * st_low;
Cw -> 2 * st_low + (two_st - q * den) - q * den_low + q * (den_low - (u + root - den));
correction - Cw -> (rnd(fma(-q, den_low, m)) - fma(-q, den_low, m)) + correction_underflow + (m - (residual + 2 * st_low))
                   + (rnd(fma(-q, den, two_st)) - fma(-q, den, two_st)) + residual_underflow - q * (den_low - (u + root - den));
(y - Qc) / Qc -> (correction * (inverse * Dn - 1) + (correction - Cw)) / (2 * Stc);
