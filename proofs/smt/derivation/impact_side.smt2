; Claim: in case (A.30) the formula lies on the side (A.7) claims: s < dy, i.e. num < dy
; den (den > 0).
; expect: unsat
; show: u dy phi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (< (impact_num u dy phi r) (* dy (impact_den phi)))))
(check-sat)
