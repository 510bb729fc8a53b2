; Claim: s is continuous across dy = 0: at dy = 0 the (A.31) formula (the limit dy -> 0+
; for u >= 0) equals (A.30) for u > 0 and (A.29) for u = 0, and the (A.32) formula (the
; limit for u < 0) equals (A.29).
; expect: unsat
; show: u dy phi r1 r2
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r1 Real)
(declare-const r2 Real)
; include prelude
(assert (>= phi 0.0))
(assert (= dy 0.0))
(assert (is_sqrt r1 (impact_disc u dy phi)))
(assert (is_sqrt r2 (release_disc u dy phi)))
; goal
(assert (not (and (=> (> u 0.0) (= (* (contact_num u dy phi) (impact_den phi)) (* (impact_num u dy phi r1) (contact_den phi))))
                  (=> (= u 0.0) (= (contact_num u dy phi) (* (free_num u) (contact_den phi))))
                  (=> (< u 0.0) (= (release_num u r2) (* (free_num u) release_den))))))
(check-sat)
