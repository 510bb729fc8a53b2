; Claim: in case (A.32) with u > 0 (the rationalised root), phi > 1, the root is positive
; and at least u, so X = u / root lies in (0, 1], and phi dy^2's share of the
; discriminant is W = 4 phi dy^2 / (u^2 + 4 phi dy^2) = 1 - X^2 (root^2 is the
; discriminant). proofs/gappa/stable_release_u_positive.g takes phi in [1, ...] and
; u / root in [0, 1] as hypotheses; its hints weight the root's error by the root's
; share of u + root, 1 / (1 + X).
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
(assert (> u 0.0))
(assert (is_sqrt r (+ (* u u) (* 4.0 (* (* phi dy) dy)))))
; hints
(assert (> dy 0.0))
(assert (> (* dy (- phi 1.0)) 0.0))
(assert (> phi 1.0))

; then phi dy^2 > 0, so the root's square exceeds u^2
(assert (> (* phi dy) 0.0))
(assert (> (* (* phi dy) dy) 0.0))
(assert (> (* r r) (* u u)))
(assert (> r 0.0))

; then root >= u: (root - u) (root + u) >= 0 with root + u > 0
(assert (>= (* (- r u) (+ r u)) 0.0))
(assert (> (+ r u) 0.0))
(assert (>= r u))

; then the quotients: X r = u, 0 < X <= 1, X^2 r^2 = u^2
(assert (= (* (/ u r) r) u))
(assert (> (/ u r) 0.0))
(assert (<= (/ u r) 1.0))
(assert (= (* (* (/ u r) (/ u r)) (* r r)) (* u u)))

; then W (u^2 + 4 phi dy^2) = 4 phi dy^2, and (1 - X^2) r^2 = r^2 - u^2 = 4 phi dy^2
(assert (= (* (/ (* 4.0 (* (* phi dy) dy)) (+ (* u u) (* 4.0 (* (* phi dy) dy)))) (* r r)) (* 4.0 (* (* phi dy) dy))))
(assert (= (* (- 1.0 (* (/ u r) (/ u r))) (* r r)) (* 4.0 (* (* phi dy) dy))))
; goal
(assert (not (and (> phi 1.0) (> r 0.0) (> (/ u r) 0.0) (<= (/ u r) 1.0)
                  (= (/ (* 4.0 (* (* phi dy) dy)) (+ (* u u) (* 4.0 (* (* phi dy) dy))))
                     (- 1.0 (* (/ u r) (/ u r)))))))
(check-sat)
