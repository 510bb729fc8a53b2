; Erratum (A.1): it writes V_b(dy + s); with V_b(x) = (k_b / 2) floor(x)^2 and phi = theta
; k_b / 2 that is s + u + phi (floor(dy + s)^2 - floor(dy)^2) / s = 0, which is not (A.2)
; (the compression at n+1 is dy - s). Refuted claim: every root s /= 0 of (A.2) solves
; (A.1) as printed.
; expect: sat
; show: u dy phi s
; witness: u 0 dy 1 phi 1 s 1
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (not (= s 0.0)))
(assert (solves u dy phi s))
; goal
(assert (not (= (+ (* s s) (* u s) (* phi (- (* (fl (+ dy s)) (fl (+ dy s))) (* (fl dy) (fl dy))))) 0.0)))
(check-sat)
