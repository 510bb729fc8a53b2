; Claim: in case (A.30) every sum stable_form::impact forms adds terms of one sign (so
; each rounding error stays relative to the result), and its inputs satisfy the hypotheses
; of proofs/gappa/stable_impact.g: u > 0, 0 <= gap < u, u - gap > 0, push = phi gap >= 0,
; push (u - gap) >= 0 (the discriminant is u^2 plus a non-negative term), u + 2 push > 0
; and sqrt >= 0 (the numerator is a sum of positive terms), 1 + phi >= 1.
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
; goal
(assert (not (and (> u 0.0) (>= gap 0.0) (< gap u) (> (- u gap) 0.0)
                  (>= (* phi gap) 0.0) (>= (* (* phi gap) (- u gap)) 0.0)
                  (> (+ u (* 2.0 (* phi gap))) 0.0) (>= r 0.0) (>= (+ 1.0 phi) 1.0))))
(check-sat)
