# Branch: solve_rounded<T>, case (A.31), rounded_form::contact_step, the Newton step
# of the correctly rounded mode's fast path:
#   s0 = stable_form::contact(u, dy, phi) = fma(phi, 2 * dy, -u) / (1 + phi);
#   inverse = 1 / (1 + phi);
#   push = product(phi, 2 * dy);  gap = two_sum(push.high, -u);
#   numerator = two_sum(gap.high, push.low);  denominator = two_sum(1, phi);
#   slope = product(s0, denominator.high);
#   r = (numerator.high - slope.high)
#       + (((numerator.low + gap.low) - slope.low) - denominator.low * s0);
#   delta = r * inverse;
# Goal: err = (s0 + delta - S) / S, S the exact root, and delta / S.
#
# Model: as in rounded_release.g, every rounding x (1 + d), |d| <= 2^-53, two_sum and
# product exact. Q(s) = (1 + phi) s - N, N = 2 phi dy - u, is linear, its root S = N / D
# with D = 1 + phi, so Newton's step has no error of its own; what remains is the
# rounding of r = N - D s0, with N and D s0 each an exact sum of T values. Lengths are in
# units of S, r in units of D S = N (S != 0: s0 outside the window is not stepped).
# N = numerator.high + numerator.low + gap.low, and gap.low is small against N however
# 2 phi dy and u cancel: where u lies within a factor 2 of push.high, gap.low = 0
# (Sterbenz); elsewhere |push.high - u| >= |push.high| / 2 >= 2^(p-1) |push.low|, so
# |gap.low| <= 2^-p |gap.high| <= 2^-p (1 + 2^(3-p)) |N| (nl below, |kn| <= 1.001).
# denominator.high = D (1 + dd) is the rounding of 1 + phi that inverse divides by too.
# The residual's leading difference numerator.high - slope.high is of order 2^-p N, so
# its rounding, and every later one, is of order 2^-2p N: the bound is relative to S
# with no term for the cancellation, however deep (the margin is K |s0| alone).
# s0 = S (1 + e0): |e0| <= 3.01 ulps x 2^-52 (claimed_bounds.txt, checked by gappa_rounded).
# The file is the binary64 instance. gappa_rounded also runs it for x87 extended and
# binary128: every 2^-53 (1b-53) becomes 2^-p (p = 64, 113) and the bound on |e0| is
# scaled by 2^(53 - p) (claimed_bounds.txt's ulps are proven at those widths too).
# Interval ends carry 400 bits, so that terms of order 2^-2p keep their size.
#@ -Eprecision=400
#! stable e0: contact
#
# The hints: see rounded_release.g; the assumed nonzero denominator is 1 + dd.
nl = kn * dn;
A = 1 - nl;
nh = A * (1 + da);
nlow = -A * da;
sh = (1 + e0) * (1 + dd) * (1 + dq);
sl = -(1 + e0) * (1 + dd) * dq;
dlx = -dd * (1 + e0);
dls0 = dlx * (1 + d9);
T0 = nh - sh;
t = T0 * (1 + d5);
I0 = nlow + nl;
inner = (I0 * (1 + d6) - sl) * (1 + d7);
inner2 = (inner - dls0) * (1 + d10);
r = (t + inner2) * (1 + d8);
R = T0 + (I0 - sl) - dlx;
X = (1 + de) / (1 + dd) * (1 + dm);
delta = r * X;
err = e0 + delta;

{ kn in [-1.001, 1.001] /\ |e0| <= 6.6836e-16 /\
  |dn| <= 1b-53 /\ |da| <= 1b-53 /\ |dq| <= 1b-53 /\ |d5| <= 1b-53 /\ |d6| <= 1b-53 /\
  |d7| <= 1b-53 /\ |d8| <= 1b-53 /\ |d9| <= 1b-53 /\ |d10| <= 1b-53 /\
  |dd| <= 1b-53 /\ |de| <= 1b-53 /\ |dm| <= 1b-53
  -> err in ? /\ delta in ? }

R -> -e0;
T0 -> (da - nl - nl * da) - (e0 + dd + dq + e0 * dd + e0 * dq + dd * dq + e0 * dd * dq);
r - R -> T0 * d5 + I0 * d6 + (I0 * (1 + d6) - sl) * d7 - dlx * d9 + (inner - dls0) * d10 + (t + inner2) * d8;
err -> e0 * (1 - X) + (r - R) * X;
