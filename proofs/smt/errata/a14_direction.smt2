; Erratum (A.14): printed dy (dy + u) (1 + phi) > 0; the inequality is reversed. Refuted
; claim: for dy < 0, (A.12) (with phi) is equivalent to (A.14) as printed.
; expect: sat
; show: u dy phi r
; witness: u 2 dy -1 phi 5/4 r 3
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (< dy 0.0))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (= (< (impact_num u dy phi r) (* dy (impact_den phi)))
                (> (* dy (+ dy u) (+ 1.0 phi)) 0.0))))
(check-sat)
