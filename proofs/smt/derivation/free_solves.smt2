; Claim: in case (A.29) (dy <= 0, u <= -dy) the formula s = -u solves (A.2).
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
(assert (not (solves u dy phi (free_num u))))
(check-sat)
