; Erratum (A.23): printed s^2 + u s + phi dy^2 = 0; the constant term is -phi dy^2
; ((A.24), (A.25) solve the corrected equation). Refuted claim: for dy > 0 and s > dy,
; (A.2) is equivalent to (A.23) as printed.
; expect: sat
; show: u dy phi s
; witness: u -5/2 dy 1 phi 1 s 2
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
(assert (not (= (solves u dy phi s) (= (+ (* s s) (* u s) (* phi dy dy)) 0.0))))
(check-sat)
