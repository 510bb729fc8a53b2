# Branch: solve_rounded<T>, case (A.32), rounded_form::release_step, the Newton step
# of the correctly rounded mode's fast path:
#   [s0, root] = stable_form::release_with_square_root(u, dy, phi): s0 and
#   root = sqrt(fma(u, u, 4 * term)), term = phi dy^2 rounded as (phi * dy) * dy
#   (u <= 0), or as st + st_low (u > 0: the pair within 2^-105 of phi dy^2, then one
#   rounding), two roundings or fewer either way (da, db below);  inverse = 1 / root;
#   w = two_sum(s0, u);  a = product(s0, w.high);  a_low = s0 * w.low + a.low;
#   b = product(phi, dy);  c = product(b.high, dy);  c_low = b.low * dy + c.low;
#   q = (a.high - c.high) + (a_low - c_low);  delta = -q * inverse;
# Goal: err = (s0 + delta - S) / S, S the exact root, and delta / S.
#
# Model: every rounding x -> x (1 + d), |d| <= 2^-53 (binary64, round to nearest; in the
# plain window no operation here over- or underflows, docs/equations.md section 7), each d
# a free variable, so the proof covers every way the roundings can fall; two_sum and
# product are exact (high + low = the exact result). The exact root S > 0 solves
# Q(S) = S (S + u) - phi dy^2 = 0, and the slope there is Q'(S) = 2 S + u = sqrt(disc).
# Lengths are in units of S, Q in units of S sqrt(disc); rho = S / sqrt(disc) lies in
# (0, 1] since S + u = phi dy^2 / S >= 0. Then (s0 + u) / sqrt(disc) = (1 - rho) + rho e0,
# phi dy^2 / (S sqrt(disc)) = 1 - rho, and Q(s0) = e0 + rho e0^2 exactly.
# tau = 4 phi dy^2 / disc in [0, 1]: the discriminant is a sum of non-negative terms.
# s0 = S (1 + e0): |e0| <= 6.51 ulps x 2^-52, the stable path's bound for both release
# branches (claimed_bounds.txt, checked by gappa_rounded through the line below).
# The file is the binary64 instance. gappa_rounded also runs it for x87 extended and
# binary128: every 2^-53 (1b-53) becomes 2^-p (p = 64, 113) and the bound on |e0| is
# scaled by 2^(53 - p) (claimed_bounds.txt's ulps are proven at those widths too).
# Interval ends carry 400 bits, so that terms of order 2^-2p keep their size.
#@ -Eprecision=400
#! stable e0: release_u_positive release_u_nonpositive
#
# The hints split each difference into the rounding errors it is made of; Gappa checks
# that each hint's two sides are equal as polynomials (gappa_rounded fails if it warns
# that they are not), and the nonzero denominator it assumes, rr, is within 2^-50 of 1.
w = (1 - rho) + rho * e0;
wh = w * (1 + d1);
wl = -w * d1;
ah = (1 + e0) * wh * (1 + d2);
al = -(1 + e0) * wh * d2;
swl0 = (1 + e0) * wl;
swl = swl0 * (1 + d3);
C = 1 - rho;
ch = C * (1 + d4) * (1 + d5);
cl = -C * (1 + d4) * d5;
bldy0 = -C * d4;
bldy = bldy0 * (1 + d6);
alow = (swl + al) * (1 + d7);
clow = (bldy + cl) * (1 + d8);
A = ah - ch;
L = alow - clow;
q = (A * (1 + d9) + L * (1 + d10)) * (1 + d11);
Q = (1 + e0) * w - C;
disc = (1 - tau) + tau * (1 + da) * (1 + db);
rr = sqrt(disc * (1 + dd)) * (1 + ds);
X = (1 + de) / rr * (1 + dm);
delta = -q * X;
err = e0 + delta;

{ rho in [0, 1] /\ tau in [0, 1] /\ |e0| <= 1.4456e-15 /\
  |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\ |d6| <= 1b-53 /\
  |d7| <= 1b-53 /\ |d8| <= 1b-53 /\ |d9| <= 1b-53 /\ |d10| <= 1b-53 /\ |d11| <= 1b-53 /\
  |da| <= 1b-53 /\ |db| <= 1b-53 /\ |dd| <= 1b-53 /\ |ds| <= 1b-53 /\ |de| <= 1b-53 /\ |dm| <= 1b-53
  -> err in ? /\ delta in ? }

Q -> e0 + rho * e0 * e0;
disc -> 1 + tau * (da + db + da * db);
A -> Q - (al + swl0 - cl - bldy0);
q - Q -> A * (d9 + d11 + d9 * d11) + L * (d10 + d11 + d10 * d11) + (swl0 * d3 + (swl + al) * d7) - (bldy0 * d6 + (bldy + cl) * d8);
err -> e0 * (1 - X) - rho * e0 * e0 * X - (q - Q) * X;
