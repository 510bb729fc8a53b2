; Claim: the discriminant u^2 - 4 phi dy (u + dy) of (A.30) is non-negative on the closure
; of its case (dy <= 0, u >= -dy), so its square root exists there, and positive inside
; the case, as the text after (A.10) says.
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (<= dy 0.0))
(assert (>= u (- dy)))
; goal
(assert (not (and (>= (impact_disc u dy phi) 0.0)
                  (=> (impact_case u dy phi) (> (impact_disc u dy phi) 0.0)))))
(check-sat)
