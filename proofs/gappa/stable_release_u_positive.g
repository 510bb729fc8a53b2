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
# two, lies in [2^-2200, 2^2200]. phi covers all doubles >= 0.
#@ -Eprecision=200
#@ -Echange-threshold=0
@rnd = float<53, ne>;
u = rnd(u_);
dy = rnd(dy_);
phi = rnd(phi_);

# computed, operation by operation as in the code
st = rnd(rnd(phi * dy) * dy);
root = rnd(sqrt(rnd(fma(u, u, rnd(4 * st)))));
s = rnd(rnd(2 * st) / rnd(u + root));
# exact: the same expression in real arithmetic, which is (A.32)
# (smt/stable/release_rationalised.smt2)
St = (phi * dy) * dy;
Root = sqrt(fma(u, u, 4 * St));
S = 2 * St / (u + Root);

{ phi in [0, 1b1100] /\ dy in [1, 2] /\ u in [1b-2200, 1b2200]
  -> s -/ S in ? }
