# A compensated form of stable_form::release, u > 0 (case (A.32)), that a later change
# of the code is to adopt. The code does not use it yet, so claimed_bounds.txt has no
# line for it and proofs.gappa (gappa_bounds) leaves it out; proofs.gappa.compensated
# (gappa_bounds --candidate) proves it on its own, checks that Gappa refuses half the
# bound, and that this line states what Gappa proves (rounded up):
#! proven: 3.0000000000000097e+0 ulp
#   p = phi dy, p_low = fma(phi, dy, -p);  st = p dy, st_err = fma(p, dy, -st);
#   st_low = fma(p_low, dy, st_err)                 (phi dy^2 = st + st_low, to 2^-104)
#   root = sqrt(fma(u, u, 4 (st + st_low)));  (den, den_low) = two_sum(u, root);
#   inverse = 1 / den;  q = 2 st inverse;  residual = fma(-q, den, 2 st);
#   correction = fma(-q, den_low, residual + 2 st_low);  s = fma(correction, inverse, q)
# Gappa: 3.0000000000000097 ulps (relative error 3.3307e-16, 3 2^-53 and a second-order
# term), in the frame phi dy^2 in [1, 4] (homogeneity in (u, dy) by powers of four), with
# 200-bit interval ends: at Gappa's default 60 bits the root's 2-unit error is rounded
# outward to 2 + 2^-7 units, which gave 3.0156. The root's error weighs fully when
# u << sqrt(phi) dy: a discriminant rounded twice (4 (st + st_low), then the fma) gives it
# 2 units, the last rounding 1. A double-double discriminant would give 2.5, but its
# low-order sums may cancel to 0, where Gappa cannot bound a relative rounding error, and
# the frame that bounds them absolutely (u bounded) is not the quotient's (phi dy^2
# bounded): two regime files. Window: st_low's exact value is a multiple of
# 2^(Pe + 2b - 156), below 2^-1074 unless Pe + 2b >= -918, 26 binades above the bands'
# present lowest for P <= 0.
#@ -Eprecision=200
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
residual = rnd(fma(-q, den, two_st));
m = rnd(residual + 2 * st_low);
correction = rnd(fma(-q, den_low, m));
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
  -> s -/ S in ? /\ disc -/ Disc in ? /\ Er in ? /\ y -/ Qc in ? /\ Stc - St in ? }

# phi dy^2 as the pair st + st_low, absolutely in the frame St in [1, 4]
p * dy -> St * (1 + (p - phi * dy) / (phi * dy));
p_low * dy -> (p_low - (phi * dy - p)) * dy - ((p - phi * dy) / (phi * dy)) * St;
st_err -> (st_err - (p * dy - st)) - ((st - p * dy) / (p * dy)) * (p * dy);
fma(p_low, dy, st_err) -> p_low * dy + st_err;
Stc - St -> (st_low - fma(p_low, dy, st_err)) + (p_low - (phi * dy - p)) * dy + (st_err - (p * dy - st));
st + st_low -> St + (Stc - St);

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
residual -> (residual - fma(-q, den, two_st)) + (two_st - q * den);
m -> (m - (residual + 2 * st_low)) + residual + 2 * st_low;
Cw -> 2 * st_low + (two_st - q * den) - q * den_low + q * (den_low - (u + root - den));
correction - Cw -> (correction - fma(-q, den_low, m)) + (m - (residual + 2 * st_low)) + (residual - fma(-q, den, two_st)) - q * (den_low - (u + root - den));
(y - Qc) / Qc -> (correction * (inverse * Dn - 1) + (correction - Cw)) / (2 * Stc);
