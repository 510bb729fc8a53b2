# Branch: solve_stable, dy > 0 and stays_in_contact, case (A.31), stable_form::contact:
#   return fused_multiply_add(phi, Num(2) * dy, -u) / (Num(1) + phi);
#
# fused_multiply_add is std::fma for double: one rounding, fma() below.
# Arithmetic: binary64 significands with an unbounded exponent, float<53,ne> (round to
# nearest even, no underflow, no overflow). Inside safe_window this is plain double
# arithmetic; outside it scaled<double> runs the same operations on the same significands
# (see proofs/README.md). Inputs are 53-bit floats; phi >= 0. No rescaling is needed: the
# bound holds for every u and dy (the case criterion is not used), so the ranges below
# just cover all doubles.
#@ -Eprecision=200
@rnd = float<53, ne>;
u = rnd(u_);
dy = rnd(dy_);
phi = rnd(phi_);

# computed, operation by operation as in the code
s = rnd(rnd(fma(phi, rnd(2 * dy), -u)) / rnd(1 + phi));
# exact (A.31): (2 phi dy - u) / (1 + phi)
S = fma(phi, 2 * dy, -u) / (1 + phi);

{ phi in [0, 1b1100] /\ u in [-1b1100, 1b1100] /\ dy in [-1b1100, 1b1100]
  -> s -/ S in ? }
