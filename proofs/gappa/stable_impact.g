# Branch: solve_stable, dy <= 0 and u > -dy, case (A.30), stable_form::impact(u, gap, phi),
# gap = -dy (exact), compensated:
#   push = phi * gap;  push_error = fma(phi, gap, -push);          (exact: phi gap - push)
#   discriminant = fma(u, u, 4 * (push * (u - gap)));  root = sqrt(discriminant);
#   head = two_sum(u, 2 * push);  numerator = two_sum(head.high, root);
#   numerator_low = numerator.low + (head.low + 2 * push_error);
#   one_plus_phi = two_sum(1, phi);  denominator = 2 * one_plus_phi.high;
#   inverse = 1 / denominator;  quotient = numerator.high * inverse;
#   residual = fma(-quotient, denominator, numerator.high);
#   correction = fma(-quotient, 2 * one_plus_phi.low, residual + numerator_low);
#   return -fma(correction, inverse, quotient);
# two_sum is Knuth's (detail::two_sum), written out below operation by operation.
#
# Arithmetic: float<53,ne>, binary64 significands with an unbounded exponent (see
# stable_contact.g and proofs/README.md). Rescaling: every operation is homogeneous in
# (u, gap) (degree 1 or 2, phi fixed), and multiplying u and gap by a power of two
# multiplies every intermediate by it or its square exactly, so the relative error
# does not change; it brings N = u + 2 phi gap + root into [1, 2]. Its three terms are
# non-negative, so each is at most N: u, R <= 2 and phi gap <= 1; u > 0, and a double
# u is at least 2^-1074 while N is below 2^1026, so the move leaves u >= 2^-2200.
# 0 <= gap < u (smt/stable/impact_no_cancellation.smt2). The root is at most
# u + 2 push, so at most half the numerator (A / R >= 1 below,
# smt/stable/impact_root_below_sum.smt2).
#
# Exactness hypotheses, each "x - (exact value) in [0, 0]": fma(phi, gap, -push) is the
# exact error of the product (facts/two_prod_exact.g, proven), and two_sum's low part
# that of its sum, barring overflow (Knuth's theorem; checked on every pair of two
# miniature formats, proofs.exact_sum_exhaustive). That the operations below are the
# code's, in its order, model_agreement checks bit for bit.
#
# The second goal, that the correction moves the quotient by less than 2^-50 of it, is
# what window/impact_push_zero.g.in takes from here: s from 2^(emin + 1) up leaves the
# quotient normal.
#
# The hints: the numerator's error is the root's, weighted by its share (at most 1/2),
# as in the uncompensated form; the pair n + n_low is N to within 2^-104 of N. The
# quotient's correction is exact but for roundings of terms of order 2^-53 N, so its
# error is of order 2^-105: what is left is the root's share (1.5) and the last
# rounding (1), 2.5 units of 2^-53 in all. The tiny terms are bounded absolutely, in
# the frame N in [1, 2]; the quotient relative to W = n + n_low, in [1, 2] too. Each
# hint is an identity, which Gappa checks; the denominators it assumes non-zero
# (R, N, W, d, the reciprocal, n times it) are positive here.
# Two mutants of this model that model_agreement cannot tell apart by testing: an fma
# whose product is of order 2^-53 s split into two roundings changes s only where the
# exact sum lies within about 2^-106 s of a rounding boundary, about one input in 2^50.
#! indistinguishable: fma split in s: the product correction * inverse is of order 2^-53 s
#! indistinguishable: fma split in correction: the product q * 2 d_low is of order 2^-53 s
#@ -Eprecision=200
#@ -Echange-threshold=0
@rnd = float<53, ne>;
u = rnd(u_);
gap = rnd(gap_);
phi = rnd(phi_);

# computed, operation by operation as in the code
push = rnd(phi * gap);
push_error = rnd(fma(phi, gap, -push));
disc = rnd(fma(u, u, rnd(4 * rnd(push * rnd(u - gap)))));
root = rnd(sqrt(disc));
t = 2 * push;
a = rnd(u + t);
a_bv = rnd(a - u);
a_av = rnd(a - a_bv);
a_low = rnd(rnd(u - a_av) + rnd(t - a_bv));
n = rnd(a + root);
n_bv = rnd(n - a);
n_av = rnd(n - n_bv);
n_err = rnd(rnd(a - n_av) + rnd(root - n_bv));
n_low = rnd(n_err + rnd(a_low + 2 * push_error));
d = rnd(1 + phi);
d_bv = rnd(d - 1);
d_av = rnd(d - d_bv);
d_low = rnd(rnd(1 - d_av) + rnd(phi - d_bv));
D = 2 * d;
inverse = rnd(1 / D);
q = rnd(n * inverse);
residual = rnd(fma(-q, D, n));
m = rnd(residual + n_low);
correction = rnd(fma(-q, 2 * d_low, m));
s = -rnd(fma(correction, inverse, q));

# exact: the same expression in real arithmetic, which is (A.30)
# (smt/stable/impact_rewrite.smt2)
Push = phi * gap;
Disc = fma(u, u, 4 * (Push * (u - gap)));
A = u + 2 * Push;
R = sqrt(Disc);
N = A + R;
S = -(A + R) / (2 * (1 + phi));

# for the hints: N with the computed root, the root's error and share, the pair's
# value W, the quotient's exact target and residual
Nr = A + root;
Er = (root - R) / R;
Tr = R / N;
W = n + n_low;
L = a_low + 2 * push_error;
y = fma(correction, inverse, q);
Dt = 2 * (1 + phi);
Qw = W / Dt;
Cw = W - q * Dt;

{ phi in [0, 1b1100] /\ u in [1b-2200, 2] /\ gap in [0, 2] /\ u - gap in [0, 2] /\ A / R >= 1
  /\ N in [1, 2] /\ Push in [0, 1] /\ R in [0, 2]
  /\ push_error - (phi * gap - push) in [0, 0]
  /\ a_low - (u + t - a) in [0, 0]
  /\ n_err - (a + root - n) in [0, 0]
  /\ d_low - (1 + phi - d) in [0, 0]
  -> s -/ S in ? /\ (y - q) / q in ? }

Tr -> 1 / (1 + A / R);
(Nr - N) / N -> Tr * Er;
Nr -> N * (1 + (Nr - N) / N);
(W - N) / N -> ((W - Nr) + (Nr - N)) / N;
(s - S) / S -> (1 + (-s - y) / y) * (1 + (y - Qw) / Qw) * (1 + (W - N) / N) - 1;

push_error -> (push_error - (Push - push)) - (push - Push);
a_low -> (a_low - (u + t - a)) - (a - (u + t));
n_err -> (n_err - (a + root - n)) - (n - (a + root));
W - Nr -> (n_low - (n_err + rnd(a_low + 2 * push_error))) + (rnd(a_low + 2 * push_error) - L) + (n_err - (a + root - n)) + 2 * (push_error - (Push - push)) + (a_low - (u + t - a));
W -> Nr + (W - Nr);

d_low / d -> (d_low - (1 + phi - d)) / d + ((1 + phi) - d) / d;
((1 + phi) - d) / d -> -((d - (1 + phi)) / (1 + phi)) / (1 + (d - (1 + phi)) / (1 + phi));
inverse * Dt - 1 -> (inverse - 1 / D) / (1 / D) * (1 + ((1 + phi) - d) / d) + ((1 + phi) - d) / d;
q * D -> n * ((1 + (q - n * inverse) / (n * inverse)) * (1 + (inverse - 1 / D) / (1 / D)));
n - q * D -> n * (1 - (1 + (q - n * inverse) / (n * inverse)) * (1 + (inverse - 1 / D) / (1 / D)));
q * (2 * d_low) -> (q * D) * (d_low / d);
Cw -> n_low + (n - q * D) - q * (2 * d_low) + 2 * q * (d_low - (1 + phi - d));
fma(-q, 2 * d_low, m) -> m - q * (2 * d_low);
fma(-q, D, n) -> n - q * D;
m -> (m - (residual + n_low)) + residual + n_low;
residual -> (residual - fma(-q, D, n)) + (n - q * D);
correction - Cw -> (correction - fma(-q, 2 * d_low, m)) + (m - (residual + n_low)) + (residual - fma(-q, D, n)) - 2 * q * (d_low - (1 + phi - d));
(y - Qw) / Qw -> (correction * (inverse * Dt - 1) + (correction - Cw)) / W;
(y - q) / q -> (correction / W) * (W / n) / (1 + (q - n * inverse) / (n * inverse));
correction / W -> (correction - Cw) / W + Cw / W;
Cw / W -> 1 - (1 + (q - n * inverse) / (n * inverse)) * (n / W) * (inverse * Dt);
