; Claim: s is continuous across u = dy (phi - 1) (dy > 0): the (A.32) formula on the
; boundary gives the (A.31) value, s = dy.
; expect: unsat
; show: u dy phi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (> dy 0.0))
(assert (= u (* dy (- phi 1.0))))
(assert (is_sqrt r (release_disc u dy phi)))
; goal
(assert (not (and (= (release_num u r) (* dy release_den))
                  (= (contact_num u dy phi) (* dy (contact_den phi))))))
(check-sat)
