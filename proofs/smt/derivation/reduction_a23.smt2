; Claim: for dy > 0 and s > dy (A.22), (A.2) reduces to s^2 + u s - phi dy^2 = 0 ((A.23)
; with its constant term's sign corrected).
; expect: unsat
; show: u dy phi s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (> dy 0.0))
(assert (> s dy))
; goal
(assert (not (= (solves u dy phi s) (= (- (+ (* s s) (* u s)) (* phi dy dy)) 0.0))))
(check-sat)
