; Claim: rounded.hpp's residual_sign_at, dy > 0 and m <= dy (the (A.31) side):
; R(m) = (1 + phi) m + u - 2 phi dy, the (A.31) numerator times 1, and the six
; terms the code adds for m = c + h (c, h, phi c, phi h, u, -2 phi dy) add up to
; it. So the sign of the exact sum is the sign of R(m). (m /= 0.)
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
; include prelude
; m names the midpoint c + h
(assert (= m (+ c h)))
(assert (>= phi 0.0))
(assert (> dy 0.0))
(assert (<= m dy))
(assert (not (= m 0.0)))
(assert (quotient_is dy m q))
; hints
(assert (= (* (- q (- m (* 2.0 dy))) m) 0.0))
(assert (= q (- m (* 2.0 dy))))
; goal
(assert (not (= (+ m u (* phi q)) (+ c h (* phi c) (* phi h) u (* (- 2.0) phi dy)))))
(check-sat)
