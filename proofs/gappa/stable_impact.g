# Branch: solve_stable, dy <= 0 and u > -dy, case (A.30), stable_form::impact(u, gap, phi),
# gap = -dy (exact):
#   push = phi * gap;
#   discriminant = fused_multiply_add(u, u, Num(4) * (push * (u - gap)));
#   return -((u + Num(2) * push) + sqrt(discriminant)) / (Num(2) * (Num(1) + phi));
#
# fused_multiply_add is std::fma for double: one rounding, fma() below.
# Arithmetic: float<53,ne>, binary64 significands with an unbounded exponent (see
# stable_contact.g and proofs/README.md). Rescaling: every operation is homogeneous in
# (u, gap) (degree 1 or 2, phi fixed), and multiplying u and gap by a power of two 2^k
# multiplies every intermediate by 2^k or 2^2k exactly, so the relative error does not
# change; u > 0 in this case, so 2^k can bring u into [1, 2]. Then 0 <= gap < u
# (smt/stable/impact_no_cancellation.smt2 proves these hypotheses from the case).
# The root is at most u + 2 push, so at most half the numerator (A / R >= 1 below,
# smt/stable/impact_root_below_sum.smt2).
#
# The hints: the numerator's error is the two terms' errors weighted by their shares.
# Without the root's share Gappa takes the larger error, the root's, whose discriminant
# can be almost all rounded product (6 ulps); with its share, at most 1/2, the root's
# error counts half (5.5 ulps). Each hint is an identity of rational functions, which
# Gappa checks; the denominators it assumes non-zero (u + 2 push, the root, their sum)
# are positive here.
#@ -Eprecision=200
#@ -Echange-threshold=0
@rnd = float<53, ne>;
u = rnd(u_);
gap = rnd(gap_);
phi = rnd(phi_);

# computed, operation by operation as in the code
push = rnd(phi * gap);
disc = rnd(fma(u, u, rnd(4 * rnd(push * rnd(u - gap)))));
a = rnd(u + rnd(2 * push));
r = rnd(sqrt(disc));
n = rnd(a + r);
s = rnd(-(n) / rnd(2 * rnd(1 + phi)));
# exact: the same expression in real arithmetic, which is (A.30)
# (smt/stable/impact_rewrite.smt2)
Push = phi * gap;
Disc = fma(u, u, 4 * (Push * (u - gap)));
A = u + 2 * Push;
R = sqrt(Disc);
N = A + R;
S = -(A + R) / (2 * (1 + phi));
# for the hints: the relative errors of the numerator's two terms, the root's share
Ea = (a - A) / A;
Er = (r - R) / R;
Tr = R / N;

{ phi in [0, 1b1100] /\ u in [1, 2] /\ gap in [0, 2] /\ u - gap in [0, 2] /\ A / R >= 1
  -> s -/ S in ? }

(n - N) / N -> (1 + (n - (a + r)) / (a + r)) * (1 + (1 - Tr) * Ea + Tr * Er) - 1;
Tr -> 1 / (1 + A / R);
