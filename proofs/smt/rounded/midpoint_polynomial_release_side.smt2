; Claim: rounded.hpp's residual_sign_at, dy > 0 and m > dy (the (A.32) side, so
; m > 0): m R(m) = m^2 + u m - phi dy^2, the (A.32) numerator, and the six
; monomials the code adds for m = c + h (c^2, 2 c h, h^2, u c, u h, -phi dy^2)
; add up to it. As m > 0, R(m) has the sign of the sum.
; expect: unsat
; show: u dy phi c h q
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const c Real)
(declare-const h Real)
(declare-const q Real)
(declare-const m Real)
(declare-const p Real)
; include prelude
; m names the midpoint c + h
(assert (= m (+ c h)))
(assert (>= phi 0.0))
(assert (> dy 0.0))
(assert (> m dy))
(assert (quotient_is dy m q))
(assert (= p (+ (* c c) (* 2.0 c h) (* h h) (* u c) (* u h) (* (- 1.0) phi dy dy))))
; hints
(assert (= (* q m) (- (* dy dy))))
(assert (= (* m (+ m u (* phi q))) p))
(assert (> m 0.0))
(assert (=> (> (+ m u (* phi q)) 0.0) (> p 0.0)))
(assert (=> (< (+ m u (* phi q)) 0.0) (< p 0.0)))
; goal
(assert (not (and (= (* m (+ m u (* phi q))) p)
                  (= (> (+ m u (* phi q)) 0.0) (> p 0.0))
                  (= (= (+ m u (* phi q)) 0.0) (= p 0.0)))))
(check-sat)
