; Claim: stable_form::impact computes (A.30): with gap = -dy its discriminant u^2 + 4 (phi
; gap) (u - gap) is that of (A.30), and -((u + 2 phi gap) + r) / (2 (1 + phi)) is the
; (A.30) formula (numerator and denominator as in the prelude).
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
; r is the square root the code takes: sqrt(fused_multiply_add(u, u, 4 * (push * (u - gap)))), push = phi gap
(assert (is_sqrt r (+ (* u u) (* 4.0 (* (* phi gap) (- u gap))))))
; goal
(assert (not (and (is_sqrt r (impact_disc u dy phi))
                  (= (- (+ (+ u (* 2.0 (* phi gap))) r)) (impact_num u dy phi r))
                  (= (* 2.0 (+ 1.0 phi)) (impact_den phi)))))
(check-sat)
