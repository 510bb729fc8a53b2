# Branch: solve_rounded<T>, case (A.31), rounded_form::contact_step, the Newton step
# of the correctly rounded mode's fast path:
#   s0 = stable_form::contact(u, dy, phi) = fma(phi, 2 * dy, -u) / (1 + phi);
#   inverse = 1 / (1 + phi);
#   g = two_sum(2 * dy, -s0);  m = product(phi, g.high);  w = two_sum(u, s0);
#   r = (m.high - w.high) + ((m.low + phi * g.low) - w.low);  delta = r * inverse;
# This file covers phi dy <= (1 + phi) |S|; rounded_contact_cancellation.g the rest.
# Goal: err = (s0 + delta - S) / S, S the exact root, and delta / S.
#
# Model: as in rounded_release.g, every rounding x (1 + d), |d| <= 2^-53, two_sum and
# product exact. Q(s) = (1 + phi) s - (2 phi dy - u) is linear, its root S = N / D with
# D = 1 + phi, so Q(s0) = -(N - s0 D) and Newton's step has no error of its own; what
# remains is the rounding of r = N - s0 D = phi (2 dy - s0) - (u + s0).
# Lengths are in units of S (either sign), r in units of D S; theta = phi / D in [0, 1),
# y = dy / S, ty = theta y in [-1, 1]. Then u / (D S) = 2 ty - 1, theta (2 dy - s0) / S = 2 ty - theta (1 + e0),
# (u + s0) / (D S) = (2 ty - 1) + (1 - theta)(1 + e0), and r = -e0 exactly.
# s0 = S (1 + e0): |e0| <= 3.01 ulps x 2^-52 (claimed_bounds.txt, checked by gappa_rounded).
# The file is the binary64 instance. gappa_rounded also runs it for x87 extended and
# binary128: every 2^-53 (1b-53) becomes 2^-p (p = 64, 113) and the bound on |e0| is
# scaled by 2^(53 - p) (claimed_bounds.txt's ulps are proven at those widths too).
# Interval ends carry 400 bits, so that terms of order 2^-2p keep their size.
#@ -Eprecision=400
#! stable e0: contact
#
# The hints: see rounded_release.g; the assumed nonzero denominator is 1 + dd.
tG = 2 * ty - theta * (1 + e0);
tgh = tG * (1 + d1);
tgl0 = -tG * d1;
mh = tgh * (1 + d2);
ml = -tgh * d2;
W = (2 * ty - 1) + (1 - theta) * (1 + e0);
wh = W * (1 + d3);
wl = -W * d3;
tgl = tgl0 * (1 + d4);
A = mh - wh;
L = (ml + tgl) * (1 + d6) - wl;
r = (A * (1 + d5) + L * (1 + d7)) * (1 + d8);
R = tG - W;
X = (1 + de) / (1 + dd) * (1 + dm);
delta = r * X;
err = e0 + delta;

{ theta in [0, 1] /\ ty in [-1, 1] /\ |e0| <= 6.6836e-16 /\
  |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\ |d6| <= 1b-53 /\
  |d7| <= 1b-53 /\ |d8| <= 1b-53 /\ |dd| <= 1b-53 /\ |de| <= 1b-53 /\ |dm| <= 1b-53
  -> err in ? /\ delta in ? }

R -> -e0;
A -> R - (ml + tgl0 - wl);
r - R -> A * (d5 + d8 + d5 * d8) + L * (d7 + d8 + d7 * d8) + (tgl0 * d4 + (ml + tgl) * d6);
err -> e0 * (1 - X) + (r - R) * X;
