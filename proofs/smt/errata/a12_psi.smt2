; Erratum (A.12): printed with 2 psi dy. Refuted claim: for dy < 0 the printed (A.12), dy
; > (2 psi dy - u - sqrt(...)) / (2 (1 + phi)), is equivalent to (A.15) u > -dy.
; expect: sat
; show: u dy phi psi r
; witness: u 2 dy -1 phi 5/4 psi -1 r 3
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const psi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (< dy 0.0))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (= (< (- (* 2.0 psi dy) u r) (* dy (impact_den phi))) (> u (- dy)))))
(check-sat)
