# Branch: solve_stable, dy > 0 and not stays_in_contact, case (A.32),
# stable_form::release(u, dy, phi), sub-branch u <= 0:
#   stiffness_term = (phi * dy) * dy;
#   root = sqrt(fused_multiply_add(u, u, Num(4) * stiffness_term));
#   return (root - u) / Num(2);
#
# fused_multiply_add is std::fma for double: one rounding, fma() below.
# Arithmetic: float<53,ne>, binary64 significands with an unbounded exponent (see
# stable_contact.g and proofs/README.md). The division by 2 is written unrounded: with
# an unbounded exponent it is exact (proofs.model_agreement checks it in double).
#
# The goal is the absolute error in units of an S in [1, 2], that is in ulps of S
# (gappa_bounds: d * 2^52 ulps), not the relative error: a relative bound pays for
# every rounding as if its result lay at the bottom of its binade, and cannot go below
# the 3.22 units of 2^-53 the searches find, which is up to 3.5 ulps where S lies just
# below a power of two. Rescaling: homogeneous in (u, dy), so a power of two brings S
# (> 0 in this case) into [1, 2]. Then root - u = 2 S with both terms >= 0, so
# u in [-2, 0] and Root in [1, 4]; phi dy^2 = (Root^2 - u^2) / 4 <= 4 (P below) and
# Disc = Root^2 (smt/stable/release_scaled_root.smt2 proves these; Gappa knows no
# identity of square roots). phi and dy are any doubles times the power of two
# (dy then lies within [2^-2200, 2^600]). phi = 0 is left out, since the hint on
# phi dy's rounding divides by it: then st = 0, root = sqrt(rnd(u^2)) rounds to |u| and
# s = -u exactly (argued; the exhaustive tests and model_agreement run it).
#
# The hints follow each rounding to s through the root, weighting the discriminant's
# error by 1 / (2 Root) and phi dy^2's by its share, with Root and u split so that
# each intermediate's range, hence its half-ulp, is that of its binade: u in 32 pieces
# (a second split variable, Root, makes Gappa stop at its iteration limit, and its
# result then depends on memory layout; gappa_bounds fails on that). The splits at 4
# (root - u, and phi dy), and of the discriminant at 16, keep a computed value just
# above a power of two, when the exact one lies just below, from being charged the
# upper binade's half-ulp.
#@ -Eprecision=200
#@ -Echange-threshold=0
@rnd = float<53, ne>;
u = rnd(u_);
dy = rnd(dy_);
phi = rnd(phi_);
# computed, operation by operation as in the code
p = rnd(phi * dy);
st = rnd(p * dy);
disc = rnd(fma(u, u, 4 * st));
root = rnd(sqrt(disc));
num = rnd(root - u);
s = num / 2;
# exact (A.32): (-u + sqrt(u^2 + 4 phi dy^2)) / 2
St = (phi * dy) * dy;
Disc = fma(u, u, 4 * St);
Root = sqrt(Disc);
S = (Root - u) / 2;
# phi dy^2 in terms of the root
P = (Root * Root - u * u) / 4;

{ u in [-2, 0] /\ S in [1, 2] /\ Root in [1, 4] /\ St in [1b-12000, 4] /\ St - P in [0, 0] /\ Disc - Root * Root in [0, 0]
  /\ phi in [1b-1100, 1b1100] /\ dy in [1b-12000, 1b12000]
  -> s - S in ? }

s - S -> (num - (root - u)) / 2 + (root - Root) / 2;
root - Root -> (root - sqrt(disc)) + Root * ((sqrt(disc) - Root) / Root);
disc - Disc -> (disc - (u * u + 4 * st)) + 4 * (st - p * dy) + 4 * St * ((p - phi * dy) / (phi * dy));
St -> P + (St - P);
root - u -> 2 * S + (root - Root);
u * u + 4 * st -> Disc + 4 * (st - St);
p * dy -> St + (p - phi * dy) * dy;
Disc -> Root * Root + (Disc - Root * Root);
$ u in 32, root - u in (4), u * u + 4 * st in (16), p * dy in (4);
