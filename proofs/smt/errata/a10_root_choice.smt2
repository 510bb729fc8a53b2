; Erratum, text after (A.10): 'the solution must be negative, which is assured only for
; the solution with the negative root'. Both roots of (A.9) are <= 0 (their product phi
; dy^2 / (1 + phi) is >= 0, their sum is negative); the + root is excluded because it is
; >= dy (derivation/impact_plus_root_excluded). Refuted claim: in case (A.30) with phi >
; 0, the + root is not negative.
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
(assert (impact_case u dy phi))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (>= (+ (- (* 2.0 phi dy) u) r) 0.0)))
(check-sat)
