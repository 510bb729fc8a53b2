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
#@ -Eprecision=200
@rnd = float<53, ne>;
u = rnd(u_);
gap = rnd(gap_);
phi = rnd(phi_);

# computed, operation by operation as in the code
push = rnd(phi * gap);
disc = rnd(fma(u, u, rnd(4 * rnd(push * rnd(u - gap)))));
s = rnd(-(rnd(rnd(u + rnd(2 * push)) + rnd(sqrt(disc)))) / rnd(2 * rnd(1 + phi)));
# exact: the same expression in real arithmetic, which is (A.30)
# (smt/stable/impact_rewrite.smt2)
Push = phi * gap;
Disc = fma(u, u, 4 * (Push * (u - gap)));
S = -((u + 2 * Push) + sqrt(Disc)) / (2 * (1 + phi));

{ phi in [0, 1b1100] /\ u in [1, 2] /\ gap in [0, 2] /\ u - gap in [0, 2]
  -> s -/ S in ? }
