# Branch: solve_rounded<T>, case (A.30), rounded_form::impact_step, the Newton step
# of the correctly rounded mode's fast path:
#   [s0, root] = stable_form::impact_with_square_root(u, -dy, phi): stable_form::impact's
#   s0 and the square root of its discriminant, root = sqrt(fma(u, u, 4 * (push * (u - gap))));
#   denominator = 1 + phi;  inverse = 1 / root;
#   w = two_sum(s0, u);  a = product(s0, w.high);  a_low = s0 * w.low + a.low;
#   g = two_sum(dy, -s0);  k = product(g.high, g.high);  k_low = 2 * g.high * g.low + k.low;
#   m = product(phi, k.high);  m_low = phi * k_low + m.low;
#   q = (a.high + m.high) + (a_low + m_low);  delta = q * inverse;
# Goal: err = (s0 + delta - S) lam / |S|, S < 0 the exact root, and delta lam / |S|: the
# error in units of |S| / lam = (1 + phi) S^2 / sqrt(disc), which the code's margin
# K (1 + phi) s0^2 / root follows (Newton's square term e0^2 |S| / lam grows as Q's two
# roots merge, lam -> 0), so that no condition is needed.
#
# Model: as in rounded_release.g. Q(s) = s (s + u) + phi (dy - s)^2 = (1 + phi) s^2 +
# (u - 2 phi dy) s + phi dy^2, the smaller root S wanted, Q'(S) = -sqrt(disc); the code's
# q omits phi g.low^2 (below 2^-2p of the terms), which the model keeps in Q.
# Lengths are in units of |S| (S = -1), Q in units of (1 + phi) S^2; theta = phi / (1 + phi),
# g = dy / S in [0, 1) (S < dy <= 0). From Q(S) = 0, u / (1 + phi) = (1 - theta) +
# theta (1 - g)^2; the roots' distance sqrt(disc) / ((1 + phi) |S|) = lam = 1 - theta g^2,
# in [0, 1], and
# Q(s0) = lam e0 + e0^2. tau = 4 phi gap (u - gap) / disc in [0, 1].
# s0 = S (1 + e0): |e0| <= 6.01 ulps x 2^-52 (claimed_bounds.txt, checked by gappa_rounded).
# The file is the binary64 instance. gappa_rounded also runs it for x87 extended and
# binary128: every 2^-53 (1b-53) becomes 2^-p (p = 64, 113) and the bound on |e0| is
# scaled by 2^(53 - p) (claimed_bounds.txt's ulps are proven at those widths too).
# Interval ends carry 400 bits, so that terms of order 2^-2p keep their size.
#@ -Eprecision=400
#! stable e0: impact
#! margin roundings: 40
#! unit: (1 + phi) s*^2 / sqrt(disc)
#
# The hints: see rounded_release.g; the assumed nonzero denominators are rr (within
# 2^-50 of 1). The margin's 40 roundings: its 5 (1 + phi, the two products by s0, the
# reciprocal of the root and the product by it), the root's 3 against the exact sqrt(disc),
# the rounding test's 2, and (1 + e0)^2 >= 1 - 24.04 2^-p (|e0| <= 12.02 2^-p).
lam = 1 - theta * g * g;
W = theta * (1 - g) * (1 - g) - (1 - theta) * e0;
s0 = -(1 + e0);
wh = W * (1 + d1);
wl = -W * d1;
sw = s0 * wh;
ah = sw * (1 + d2);
al = -sw * d2;
swl0 = s0 * wl;
swl = swl0 * (1 + d3);
alow = (swl + al) * (1 + d4);
G = (1 - g) + e0;
gh = G * (1 + d5);
gl = -G * d5;
kh = gh * gh * (1 + d6);
kl = -gh * gh * d6;
mh = theta * kh * (1 + d7);
ml = -theta * kh * d7;
K0 = kl + 2 * gh * gl;
klow = (2 * gh * gl * (1 + d8) + kl) * (1 + d9);
mlow = (theta * klow * (1 + d10) + ml) * (1 + d11);
A = ah + mh;
L = alow + mlow;
q = (A * (1 + d12) + L * (1 + d13)) * (1 + d14);
Q = s0 * W + theta * G * G;
disc = (1 - tau) + tau * (1 + da) * (1 + db) * (1 + dc);
rr = sqrt(disc * (1 + dd)) * (1 + ds);
X = (1 + de) / rr * (1 + dm);
delta = q * X;
err = -e0 * lam + delta;

{ theta in [0, 1] /\ g in [0, 1] /\ lam in [0, 1] /\ tau in [0, 1] /\ |e0| <= 1.3345e-15 /\
  |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\ |d6| <= 1b-53 /\
  |d7| <= 1b-53 /\ |d8| <= 1b-53 /\ |d9| <= 1b-53 /\ |d10| <= 1b-53 /\ |d11| <= 1b-53 /\ |d12| <= 1b-53 /\
  |d13| <= 1b-53 /\ |d14| <= 1b-53 /\ |da| <= 1b-53 /\ |db| <= 1b-53 /\ |dc| <= 1b-53 /\ |dd| <= 1b-53 /\
  |ds| <= 1b-53 /\ |de| <= 1b-53 /\ |dm| <= 1b-53
  -> err in ? /\ delta in ? }

disc -> 1 + tau * ((1 + da) * (1 + db) * (1 + dc) - 1);
Q -> lam * e0 + e0 * e0;
A -> Q - (al + swl0) - (ml + theta * (K0 + gl * gl));
q - Q -> A * (d12 + d14 + d12 * d14) + L * (d13 + d14 + d13 * d14) + (swl0 * d3 + (swl + al) * d4) + (theta * (2 * gh * gl * d8 + (2 * gh * gl * (1 + d8) + kl) * d9) + theta * klow * (d10 + d11 + d10 * d11) + ml * d11) - theta * gl * gl;
err -> e0 * (X - 1) * lam + e0 * e0 * X + (q - Q) * X;
