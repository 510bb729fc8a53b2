; Claim: in case (A.31) the formula lies on the side (A.17) claims: s <= dy.
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (contact_case u dy phi))
; goal
(assert (not (<= (contact_num u dy phi) (* dy (contact_den phi)))))
(check-sat)
