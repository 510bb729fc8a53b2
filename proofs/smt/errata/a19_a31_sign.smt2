; Erratum (A.19) and (A.31): printed s = (u - 2 phi dy) / (1 + phi), the negative of what
; (A.18) gives. Refuted claim: in case (A.31) the printed formula solves (A.2).
; expect: sat
; show: u dy phi
; witness: u 1 dy 1 phi 1
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (contact_case u dy phi))
; goal
(assert (not (solves_frac u dy phi (- u (* 2.0 phi dy)) (contact_den phi))))
(check-sat)
