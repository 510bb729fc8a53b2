# Branch: solve_stable, dy <= 0 and u <= -dy, case (A.29) free:
#   if (u <= -dy) return {-u, contact_case::free};
# The code's one operation, the negation, is modelled as a rounded binary64 operation
# with the bounded format (subnormals and overflow included) over every finite double,
# and Gappa proves it exact: the returned s is -u, the (A.29) value, with no error
# (derivation/free_solves proves that -u is the root in this case). A model that dropped
# the negation or rounded differently fails proofs.model_agreement.
#@ -Eprecision=200
@rnd = float<ieee_64, ne>;
u = rnd(u_);

s = rnd(-u);     # computed
S = -u;          # exact (A.29)

# 9007199254740991b971 is the largest finite double
{ u in [-9007199254740991b971, 9007199254740991b971] -> s -/ S in ? }
