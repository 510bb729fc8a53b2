; Claim: the derivation (A.17) -> (A.21), corrected: for dy > 0 the side condition s <= dy
; of the (A.31) formula, i.e. dy >= (2 phi dy - u) / (1 + phi) [(A.20) printed as dy <= (u
; - 2 phi dy) / (1 + phi)], is equivalent to u >= dy (phi - 1) (A.21).
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (> dy 0.0))
; goal
(assert (not (= (<= (contact_num u dy phi) (* dy (contact_den phi))) (>= u (* dy (- phi 1.0))))))
(check-sat)
