; Claim: in case (A.29) the formula s = -u lies on the side (A.4) claims: s >= dy.
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (free_case u dy phi))
; goal
(assert (not (>= (free_num u) dy)))
(check-sat)
