; Claim: in case (A.32) the formula lies on the side (A.22) claims: s > dy.
; expect: unsat
; show: u dy phi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (release_case u dy phi))
(assert (is_sqrt r (release_disc u dy phi)))
; goal
(assert (not (> (release_num u r) (* dy release_den))))
(check-sat)
