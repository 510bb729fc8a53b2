; Claim: in case (A.32) every sum stable_form::release forms adds terms of one sign, and
; its inputs satisfy the hypotheses of proofs/gappa/stable_release_*.g: dy > 0, st = phi
; dy^2 >= 0 (the discriminant is u^2 plus a non-negative term), for u > 0 the denominator
; u + root adds positive terms, for u <= 0 root - u adds non-negative terms and u - dy
; (phi - 1) <= 0.
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
(assert (is_sqrt r (+ (* u u) (* 4.0 (* (* phi dy) dy)))))
; goal
(assert (not (and (> dy 0.0) (>= (* (* phi dy) dy) 0.0) (>= r 0.0)
                  (=> (> u 0.0) (> (+ u r) 0.0))
                  (=> (<= u 0.0) (and (>= (- u) 0.0) (<= (- u (* dy (- phi 1.0))) 0.0))))))
(check-sat)
