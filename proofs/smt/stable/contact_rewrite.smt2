; Claim: stable_form::contact computes (A.31): fused_multiply_add(phi, 2 dy, -u) / (1 +
; phi) has the (A.31) numerator and denominator; and detail::stays_in_contact's test, the
; sign of the exact sum u + dy - phi dy, is the criterion (A.21) u >= dy (phi - 1).
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
; goal
(assert (not (and (= (+ (* phi (* 2.0 dy)) (- u)) (contact_num u dy phi))
                  (= (+ 1.0 phi) (contact_den phi))
                  (= (>= (+ u dy (- (* phi dy))) 0.0) (>= u (* dy (- phi 1.0)))))))
(check-sat)
