; Gap in the derivation (A.12) -> (A.15): it divides by dy (the text assumes dy < 0, but
; (A.3) allows dy = 0). Refuted claim: for dy <= 0, (A.14) even corrected, dy (dy + u) (1
; + phi) < 0, is equivalent to (A.15) u > -dy (at dy = 0 it is false while (A.12) and
; (A.15) hold for u > 0; impact_criterion_steps proves the chain for dy < 0).
; expect: sat
; show: u dy phi
; witness: u 1/2 dy 0 phi 1
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (<= dy 0.0))
; goal
(assert (not (= (< (* dy (+ dy u) (+ 1.0 phi)) 0.0) (> u (- dy)))))
(check-sat)
