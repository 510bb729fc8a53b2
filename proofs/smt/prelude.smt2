; Definitions shared by the obligations. run_smt pastes this file where an
; obligation says "; include prelude". Real arithmetic only; nothing here is
; assumed, these are names for the terms of the appendix.
;
; Variables, as in the appendix: u, dy (= Delta y^n, the compression at step n),
; phi >= 0, s (= s_b, the step). The case formulas are written as a numerator
; over a positive denominator, s = n / d, so that no obligation divides.

; floor(x) = max(x, 0), the appendix's half-bracket
(define-fun fl ((x Real)) Real (ite (>= x 0.0) x 0.0))

; (A.2) holds at s:  s + u + phi (floor(dy - s)^2 - floor(dy)^2) / s = 0.
; For s /= 0 it is multiplied by s. At s = 0 the quotient is 0/0 and (A.2) is
; read with its continuous extension: the quotient tends to -2 floor(dy)
; (residual_limit_at_zero.smt2), so (A.2) at 0 is u - 2 phi floor(dy) = 0.
(define-fun solves ((u Real) (dy Real) (phi Real) (s Real)) Bool
  (ite (= s 0.0)
       (= (- u (* 2.0 phi (fl dy))) 0.0)
       (= (+ (* s s) (* u s)
             (* phi (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy)))))
          0.0)))

; (A.2) at s = n / d for d > 0, multiplied by d^2 (d floor(dy - n/d) = floor(d dy - n)).
; frac_form_is_a2.smt2 proves (solves_frac u dy phi (s d) d) = (solves u dy phi s).
(define-fun solves_frac ((u Real) (dy Real) (phi Real) (n Real) (d Real)) Bool
  (ite (= n 0.0)
       (= (- u (* 2.0 phi (fl dy))) 0.0)
       (= (+ (* n n) (* u n d)
             (* phi (- (* (fl (- (* dy d) n)) (fl (- (* dy d) n))) (* (fl dy) (fl dy) d d))))
          0.0)))

; q is the difference quotient (floor(dy - s)^2 - floor(dy)^2) / s, extended at s = 0
; by its limit; the residual of (A.2) is then s + u + phi q, defined for every s.
(define-fun quotient_is ((dy Real) (s Real) (q Real)) Bool
  (ite (= s 0.0)
       (= q (* (- 2.0) (fl dy)))
       (= (* q s) (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy))))))

; r = sqrt(x), as a relation
(define-fun is_sqrt ((r Real) (x Real)) Bool (and (>= r 0.0) (= (* r r) x)))

; ---- the case criteria, as derived from (A.2) (the printed (A.29)/(A.30) differ at u = -dy)
(define-fun free_case ((u Real) (dy Real) (phi Real)) Bool (and (<= dy 0.0) (<= u (- dy))))                ; (A.29)
(define-fun impact_case ((u Real) (dy Real) (phi Real)) Bool (and (<= dy 0.0) (> u (- dy))))               ; (A.30)
(define-fun contact_case ((u Real) (dy Real) (phi Real)) Bool (and (> dy 0.0) (>= u (* dy (- phi 1.0)))))  ; (A.31)
(define-fun release_case ((u Real) (dy Real) (phi Real)) Bool (and (> dy 0.0) (< u (* dy (- phi 1.0)))))   ; (A.32)

; ---- the case formulas s = num / den, as derived from (A.2); r is the square root of the disc
; (A.29) s = -u
(define-fun free_num ((u Real)) Real (- u))
; (A.30) s = (2 phi dy - u - sqrt(u^2 - 4 phi dy (u + dy))) / (2 (1 + phi))   [printed: 2 psi dy]
(define-fun impact_disc ((u Real) (dy Real) (phi Real)) Real (- (* u u) (* 4.0 phi dy (+ u dy))))
(define-fun impact_num ((u Real) (dy Real) (phi Real) (r Real)) Real (- (* 2.0 phi dy) u r))
(define-fun impact_den ((phi Real)) Real (* 2.0 (+ 1.0 phi)))
; (A.31) s = (2 phi dy - u) / (1 + phi)   [printed: (u - 2 phi dy) / (1 + phi)]
(define-fun contact_num ((u Real) (dy Real) (phi Real)) Real (- (* 2.0 phi dy) u))
(define-fun contact_den ((phi Real)) Real (+ 1.0 phi))
; (A.32) s = -u/2 + sqrt(u^2 + 4 phi dy^2)/2
(define-fun release_disc ((u Real) (dy Real) (phi Real)) Real (+ (* u u) (* 4.0 phi dy dy)))
(define-fun release_num ((u Real) (r Real)) Real (- r u))
(define-fun release_den () Real 2.0)
