# Branch: solve_stable, dy > 0 and not stays_in_contact, case (A.32),
# stable_form::release(u, dy, phi), sub-branch u > 0 (the rationalised root):
#   stiffness_term = (phi * dy) * dy;
#   root = sqrt(fused_multiply_add(u, u, Num(4) * stiffness_term));
#   if (u > Num(0)) return Num(2) * stiffness_term / (u + root);
#
# fused_multiply_add is std::fma for double: one rounding, fma() below.
# Arithmetic: float<53,ne>, binary64 significands with an unbounded exponent (see
# stable_contact.g and proofs/README.md). Rescaling: homogeneous in (u, dy), so a power
# of two brings dy (> 0 in this case) into [1, 2]; then u, a double times that power of
# two, lies in [2^-2200, 2^2200]. phi > 1 (u > 0, dy > 0 and u < dy (phi - 1)); above
# that phi covers all doubles. X = u / root lies in (0, 1], and phi dy^2's share of the
# discriminant is W = 1 - X^2 (smt/stable/release_root_share.smt2 proves these; Gappa
# cannot, knowing no identity of square roots).
#
# The hints: phi dy^2's two roundings (E) reach s twice, in the numerator and, through
# the discriminant, in u + root, with opposite signs. Gappa bounds each occurrence on
# its own and would add them (6.5 ulps); written as one expression in E they partly
# cancel, and with both shares, the root's of u + root (1 / (1 + X)) and phi dy^2's of
# the discriminant (W), functions of the one variable X, the bound is that of the
# worst X: about 3 + X + 1.5 / (1 + X) <= 4.75 ulps; the split of X and E into
# pieces (16 of X, 8 of E) proves 4.78. Each hint is an identity of rational functions, which Gappa
# checks; the denominators it assumes non-zero (phi dy^2, the root, u + root, the
# discriminant) are positive here.
#@ -Eprecision=200
#@ -Echange-threshold=0
@rnd = float<53, ne>;
u = rnd(u_);
dy = rnd(dy_);
phi = rnd(phi_);

# computed, operation by operation as in the code
st = rnd(rnd(phi * dy) * dy);
disc = rnd(fma(u, u, rnd(4 * st)));
root = rnd(sqrt(disc));
den = rnd(u + root);
s = rnd(rnd(2 * st) / den);
# exact: the same expression in real arithmetic, which is (A.32)
# (smt/stable/release_rationalised.smt2)
St = (phi * dy) * dy;
Disc = fma(u, u, 4 * St);
Root = sqrt(Disc);
S = 2 * St / (u + Root);
# for the hints: relative errors of phi dy^2 and of the root, the root's share of
# u + root, phi dy^2's share of the discriminant, and u / root, which fixes both
E = (st - St) / St;
Er = (root - Root) / Root;
Rho = Root / (u + Root);
W = 4 * St / Disc;
X = u / Root;

{ phi in [1, 1b1100] /\ dy in [1, 2] /\ u in [1b-2200, 1b2200] /\ X <= 1 /\ W - (1 - X * X) in [0, 0]
  -> s -/ S in ? }

(s - S) / S -> (1 + (s - 2 * st / den) / (2 * st / den)) * (1 + E)
               / ((1 + (den - (u + root)) / (u + root)) * (1 + Rho * Er)) - 1;
(disc - Disc) / Disc -> (1 + (disc - (u * u + 4 * st)) / (u * u + 4 * st)) * (1 + W * E) - 1;
Rho -> 1 / (1 + X);
W -> (W - (1 - X * X)) + (1 - X * X);
$ X in 16, E in 8;
