; Claim: with phi = 0 (no barrier) every case formula gives s = -u.
; expect: unsat
; show: u dy r1 r2
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r1 Real)
(declare-const r2 Real)
; include prelude
(assert (= phi 0.0))
(assert (is_sqrt r1 (impact_disc u dy phi)))
(assert (is_sqrt r2 (release_disc u dy phi)))
; goal
(assert (not (and (=> (free_case u dy phi) (= (free_num u) (- u)))
                  (=> (impact_case u dy phi) (= (impact_num u dy phi r1) (* (- u) (impact_den phi))))
                  (=> (contact_case u dy phi) (= (contact_num u dy phi) (* (- u) (contact_den phi))))
                  (=> (release_case u dy phi) (= (release_num u r2) (* (- u) release_den))))))
(check-sat)
