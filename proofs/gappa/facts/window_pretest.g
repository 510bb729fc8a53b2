# The intermediates of stays_in_contact's plain pre-test, in the plain window: u, dy, phi
# doubles with |x| in [2^-240, 2^240], phi > 0 (window.hpp, E = 240; a zero input only
# removes terms). With the bounded binary64 format (subnormals, overflow):
#   * phi dy, the margin's sum |u| + |dy| + |phi dy| and the margin stay between 2^-1022
#     and 2^1024, so they round as with an unbounded exponent (the x (1 + d) model of
#     smt/decision/pretest_margin);
#   * u + dy and sum - phi dy may cancel, but their exact values are multiples of 2^-292
#     and 2^-584 (FIX): a non-zero one is >= 2^-584, normal, and a zero one rounds
#     exactly; both are below 2^482. So no intermediate of the pre-test over- or
#     underflows, and the pre-test's error analysis holds in the window.
#@ -Eprecision=200
#! refute: |product| in [1b-480, 1b480] => |product| in [1b-479, 1b480]
#! refute: @FIX(estimate_exact, -584) => @FIX(estimate_exact, -583)
@rnd = float<ieee_64, ne>;
u = rnd(u_);
dy = rnd(dy_);
phi = rnd(phi_);
product = rnd(phi * dy);
sum = rnd(u + dy);
estimate_exact = sum - phi * dy;
magnitudes = rnd(|u| + |dy|);
margin_sum = rnd(magnitudes + |product|);
margin = rnd(1b-50 * margin_sum);

{ |u| in [1b-240, 1b240] /\ |dy| in [1b-240, 1b240] /\ phi in [1b-240, 1b240]
  -> |product| in [1b-480, 1b480] /\ margin_sum in [1b-241, 1b482] /\ margin in [1b-291, 1b432]
     /\ |sum| <= 1b241 /\ |estimate_exact| <= 1b482
     /\ @FIX(u + dy, -292) /\ @FIX(estimate_exact, -584) }
