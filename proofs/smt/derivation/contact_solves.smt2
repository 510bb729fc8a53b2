; Claim: in case (A.31) (dy > 0, u >= dy (phi - 1)) the formula s = (2 phi dy - u) / (1 +
; phi) solves (A.2).
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (contact_case u dy phi))
; hints
; lemma derivation/contact_side
; then, on that side floor() is the identity
(assert (= (* (fl (- (* dy (contact_den phi)) (contact_num u dy phi))) (fl (- (* dy (contact_den phi)) (contact_num u dy phi)))) (* (- (* dy (contact_den phi)) (contact_num u dy phi)) (- (* dy (contact_den phi)) (contact_num u dy phi)))))
(assert (= (* (fl dy) (fl dy)) (* dy dy)))
(assert (= (* phi (fl dy)) (* phi dy)))
; goal
(assert (not (solves_frac u dy phi (contact_num u dy phi) (contact_den phi))))
(check-sat)
