; Erratum (A.20): printed dy <= (u - 2 phi dy) / (1 + phi). Refuted claim: for dy > 0,
; (A.20) as printed is equivalent to (A.21) u >= dy (phi - 1) (the text says it is).
; expect: sat
; show: u dy phi
; witness: u 1 dy 1 phi 1
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (> dy 0.0))
; goal
(assert (not (= (<= (* dy (+ 1.0 phi)) (- u (* 2.0 phi dy))) (>= u (* dy (- phi 1.0))))))
(check-sat)
