; Erratum, text after (A.14): 'since dy < 0 and phi > 0, it follows that (dy + u) < 0,
; thus u > -dy' (the two halves contradict each other; it is dy + u > 0). Refuted claim:
; in case (A.30) with dy < 0 and phi > 0, where (A.12) holds, dy + u < 0.
; expect: sat
; show: u dy phi r
; witness: u 2 dy -1 phi 5/4 r 3
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (> phi 0.0))
(assert (< dy 0.0))
(assert (is_sqrt r (impact_disc u dy phi)))
(assert (< (impact_num u dy phi r) (* dy (impact_den phi))))
; goal
(assert (not (< (+ dy u) 0.0)))
(check-sat)
