; Claim: for dy <= 0 exactly one of the criteria of (A.29) and (A.30) holds.
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (<= dy 0.0))
; goal
(assert (not (distinct (free_case u dy phi) (impact_case u dy phi))))
(check-sat)
