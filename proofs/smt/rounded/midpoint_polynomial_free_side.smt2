; Claim: rounded.hpp's residual_sign_at, dy <= 0 and m >= dy (the (A.29) side): the
; residual R(m) = m + u + phi q(m) of (A.2) is the polynomial m + u, and the terms
; the code sums, c, h and u for m = c + h, add up to it. So the sign of the
; exact sum is the sign of R(m). (m /= 0: a midpoint never is.)
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
(assert (<= dy 0.0))
(assert (>= m dy))
(assert (not (= m 0.0)))
(assert (quotient_is dy m q))
; hints
(assert (= (* q m) 0.0))
(assert (= q 0.0))
; goal
(assert (not (= (+ m u (* phi q)) (+ c h u))))
(check-sat)
