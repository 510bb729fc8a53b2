; Claim: for dy <= 0 and s < dy (A.7), (A.2) reduces to (A.8) and, multiplied by s, to
; (A.9): (1 + phi) s^2 + (u - 2 phi dy) s + phi dy^2 = 0.
; expect: unsat
; show: u dy phi s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (<= dy 0.0))
(assert (< s dy))
; goal
(assert (not (= (solves u dy phi s) (= (+ (* (+ 1.0 phi) s s) (* (- u (* 2.0 phi dy)) s) (* phi dy dy)) 0.0))))
(check-sat)
