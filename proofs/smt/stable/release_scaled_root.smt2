; Claim: in case (A.32) with u <= 0, scaled so that s = (root - u) / 2 lies in [1, 2]:
; u lies in [-2, 0], the root in [1, 4], phi dy^2 = (root^2 - u^2) / 4 in [0, 4], and
; the discriminant is root^2. These are the hypotheses u in [-2, 0], Root in [1, 4],
; St in [..., 4], St - P in [0, 0] and Disc - Root * Root in [0, 0] of
; proofs/gappa/stable_release_u_nonpositive.g (Gappa knows no identity of square roots).
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
(assert (<= u 0.0))
(assert (is_sqrt r (+ (* u u) (* 4.0 (* (* phi dy) dy)))))
(assert (<= 1.0 (/ (- r u) 2.0)))
(assert (<= (/ (- r u) 2.0) 2.0))
; hints
(assert (>= (* (* phi dy) dy) 0.0))
(assert (>= (* r r) (* u u)))
(assert (>= r (- u)))
; goal
(assert (not (and (<= (- 2.0) u) (<= u 0.0) (<= 1.0 r) (<= r 4.0)
                  (= (* (* phi dy) dy) (/ (- (* r r) (* u u)) 4.0))
                  (<= 0.0 (* (* phi dy) dy)) (<= (* (* phi dy) dy) 4.0)
                  (= (+ (* u u) (* 4.0 (* (* phi dy) dy))) (* r r)))))
(check-sat)
