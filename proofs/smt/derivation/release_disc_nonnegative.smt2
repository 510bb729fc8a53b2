; Claim: the discriminant u^2 + 4 phi dy^2 of (A.32) is non-negative for every input, so
; its square root exists.
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
; goal
(assert (not (>= (release_disc u dy phi) 0.0)))
(check-sat)
