# Branch: solve_stable, dy > 0 and not stays_in_contact, case (A.32),
# stable_form::release(u, dy, phi), sub-branch u <= 0:
#   stiffness_term = (phi * dy) * dy;
#   root = sqrt(fused_multiply_add(u, u, Num(4) * stiffness_term));
#   return (root - u) / Num(2);
#
# fused_multiply_add is std::fma for double: one rounding, fma() below.
# Arithmetic: float<53,ne>, binary64 significands with an unbounded exponent (see
# stable_contact.g and proofs/README.md). Rescaling: homogeneous in (u, dy), so a power
# of two brings dy into [1, 2]; u <= 0 lies in [-2^2200, 0]. The case criterion
# u < dy (phi - 1) keeps the discriminant away from 0 (phi < 1/2 forces u < -dy/2);
# the bisection on phi lets Gappa use it. (smt/stable/release_no_cancellation.smt2
# proves the hypotheses from the case.) The division by 2 is written unrounded: with
# an unbounded exponent it is exact, and Gappa, which has no rule for that exactness,
# would otherwise count one rounding too many (4.5 ulps instead of 3.5).
# proofs.model_agreement checks that the unrounded quotient is exact in double on
# every input it runs.
#@ -Eprecision=200
#@ -Echange-threshold=0
@rnd = float<53, ne>;
u = rnd(u_);
dy = rnd(dy_);
phi = rnd(phi_);

# computed, operation by operation as in the code
st = rnd(rnd(phi * dy) * dy);
root = rnd(sqrt(rnd(fma(u, u, rnd(4 * st)))));
s = rnd(root - u) / 2;
# exact (A.32): (-u + sqrt(u^2 + 4 phi dy^2)) / 2
St = (phi * dy) * dy;
Root = sqrt(fma(u, u, 4 * St));
S = (Root - u) / 2;

{ phi in [0, 1b1100] /\ dy in [1, 2] /\ u in [-1b2200, 0] /\ u - dy * (phi - 1) <= 0
  -> s -/ S in ? }

$ phi in (0.5);
