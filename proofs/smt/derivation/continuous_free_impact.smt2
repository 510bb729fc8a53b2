; Claim: s is continuous across u = -dy (dy <= 0): the (A.30) formula, evaluated on the
; boundary (its discriminant is u^2 there), gives the (A.29) value s = -u = dy.
; expect: unsat
; show: u dy phi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (<= dy 0.0))
(assert (= u (- dy)))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (= (impact_num u dy phi r) (* (free_num u) (impact_den phi)))))
(check-sat)
