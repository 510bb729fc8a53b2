; Claim: for u > 0 in case (A.32) the rationalised root stable_form::release returns, s =
; 2 st / (u + root) with st = (phi dy) dy and root = sqrt(fused_multiply_add(u, u, 4 st)),
; is the (A.32) value (-u + root) / 2, and its denominator u + root is positive.
; expect: unsat
; show: u dy phi r s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (release_case u dy phi))
(assert (> u 0.0))
(assert (is_sqrt r (+ (* u u) (* 4.0 (* (* phi dy) dy)))))
(assert (= (* s (+ u r)) (* 2.0 (* (* phi dy) dy))))
; hints
(assert (> (+ u r) 0.0))
(assert (= (* (- r u) (+ u r)) (* 4.0 (* (* phi dy) dy))))
; goal
(assert (not (and (is_sqrt r (release_disc u dy phi))
                  (= (* s release_den) (release_num u r))
                  (> (+ u r) 0.0))))
(check-sat)
