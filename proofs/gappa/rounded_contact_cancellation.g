# Branch: solve_rounded<T>, case (A.31), rounded_form::contact_step, as rounded_contact.g,
# where 2 phi dy and u cancel: phi dy >= (1 + phi) |S| (|ty| >= 1 there). The step's
# roundings then scale with the cancelling terms, not with S, so this model bounds the
# error in units of T = phi dy / (1 + phi) instead, which the code's margin adds
# (K' T beside K |s0|; rounded_contact.g covers |ty| <= 1, this file |ty| >= 1, so the
# sum of both margins covers every contact input, with no condition).
# Goal: err = (s0 + delta - S) / T, S the exact root, and delta / T.
#
# Model: as rounded_contact.g, with lengths in units of T (T > 0: dy > 0 in this case, and
# phi = 0 gives ty = 0, rounded_contact.g's), r in units of D T; sig = S / T = 1 / ty in
# [-1, 1]. Then u / (D T) = 2 - sig, theta (2 dy - s0) / T = 2 - theta sig (1 + e0),
# (u + s0) / (D T) = (2 - sig) + (1 - theta) sig (1 + e0), and r = -sig e0 exactly.
# s0 = S (1 + e0): |e0| <= 3.01 ulps x 2^-52 (claimed_bounds.txt, checked by gappa_rounded).
# The file is the binary64 instance. gappa_rounded also runs it for x87 extended and
# binary128: every 2^-53 (1b-53) becomes 2^-p (p = 64, 113) and the bound on |e0| is
# scaled by 2^(53 - p) (claimed_bounds.txt's ulps are proven at those widths too).
# Interval ends carry 400 bits, so that terms of order 2^-2p keep their size.
# The margin K' T is computed as K' ((phi * dy) * (1 / (1 + phi))) and added to K |s0|:
# seven roundings between T and the rounding test (gappa_rounded's margin check).
#@ -Eprecision=400
#! stable e0: contact
#! margin roundings: 7
#! unit: phi dy / (1 + phi)
#
# The hints: see rounded_release.g; the assumed nonzero denominator is 1 + dd.
tG = 2 - theta * sig * (1 + e0);
tgh = tG * (1 + d1);
tgl0 = -tG * d1;
mh = tgh * (1 + d2);
ml = -tgh * d2;
W = (2 - sig) + (1 - theta) * sig * (1 + e0);
wh = W * (1 + d3);
wl = -W * d3;
tgl = tgl0 * (1 + d4);
A = mh - wh;
L = (ml + tgl) * (1 + d6) - wl;
r = (A * (1 + d5) + L * (1 + d7)) * (1 + d8);
R = tG - W;
X = (1 + de) / (1 + dd) * (1 + dm);
delta = r * X;
err = sig * e0 + delta;

{ theta in [0, 1] /\ sig in [-1, 1] /\ |e0| <= 6.6836e-16 /\
  |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\ |d6| <= 1b-53 /\
  |d7| <= 1b-53 /\ |d8| <= 1b-53 /\ |dd| <= 1b-53 /\ |de| <= 1b-53 /\ |dm| <= 1b-53
  -> err in ? /\ delta in ? }

R -> -sig * e0;
A -> R - (ml + tgl0 - wl);
r - R -> A * (d5 + d8 + d5 * d8) + L * (d7 + d8 + d7 * d8) + (tgl0 * d4 + (ml + tgl) * d6);
err -> sig * e0 * (1 - X) + (r - R) * X;
