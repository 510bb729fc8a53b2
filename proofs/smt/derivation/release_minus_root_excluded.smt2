; Claim: in case (A.32) the other root of (A.23) corrected, with - sqrt in (A.24), is <= 0
; < dy, against (A.22), so (A.25) takes the + root.
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
(assert (not (<= (- (- u) r) (* dy release_den))))
(check-sat)
