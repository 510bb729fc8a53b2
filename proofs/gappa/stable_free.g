# Branch: solve_stable, dy <= 0 and u <= -dy, case (A.29) free:
#   if (u <= -dy) return {-u, contact_case::free};
# Negation is exact: the relative error is 0.
#@ -Eprecision=200
@rnd = float<53, ne>;
u = rnd(u_);

s = -u;     # computed
S = -u;     # exact (A.29)

{ u in [-1b1100, 1b1100] -> s -/ S in ? }
