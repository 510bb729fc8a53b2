; Claim: in case (A.30) the square root of stable_form::impact's discriminant is positive
; and at most the other term of the numerator, 0 < r <= u + 2 push (push = phi gap), since
; r^2 = u^2 + 4 push (u - gap) <= u^2 + 4 push u + 4 push^2 = (u + 2 push)^2. So the root
; is at most half the numerator: the hypothesis (u + 2 push) / r >= 1 of
; proofs/gappa/stable_impact.g, which bounds the root's share of the numerator's error.
; expect: unsat
; show: u dy phi gap r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const gap Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (= gap (- dy)))
(assert (is_sqrt r (+ (* u u) (* 4.0 (* (* phi gap) (- u gap))))))
; hints
(assert (> u 0.0))
(assert (>= gap 0.0))
(assert (>= (* phi gap) 0.0))
(assert (>= (* (* phi gap) (- u gap)) 0.0))

; then the square root is at least u, and its square at most (u + 2 push)^2
(assert (>= (* r r) (* u u)))
(assert (> r 0.0))
(assert (<= (* r r) (* (+ u (* 2.0 (* phi gap))) (+ u (* 2.0 (* phi gap))))))

; then (r - (u + 2 push)) (r + (u + 2 push)) <= 0 with r + (u + 2 push) > 0
(assert (<= (* (- r (+ u (* 2.0 (* phi gap)))) (+ r (+ u (* 2.0 (* phi gap))))) 0.0))
(assert (> (+ r (+ u (* 2.0 (* phi gap)))) 0.0))
; goal
(assert (not (and (> r 0.0) (<= r (+ u (* 2.0 (* phi gap)))))))
(check-sat)
