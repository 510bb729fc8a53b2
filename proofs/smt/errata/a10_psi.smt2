; Erratum (A.10): it prints 2 psi dy (psi is never defined; (A.9) has 2 phi dy). Refuted
; claim: in case (A.30), for any psi, both printed values (2 psi dy - u +- sqrt(u^2 - 4
; phi dy (u + dy))) / (2 (1 + phi)) are roots of (A.9).
; expect: sat
; show: u dy phi psi r
; witness: u 2 dy -1 phi 5/4 psi 0 r 3
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const psi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (is_sqrt r (impact_disc u dy phi)))
; (A.9) at s = n / d, times d^2
(define-fun a9 ((n Real) (d Real)) Bool
  (= (+ (* (+ 1.0 phi) n n) (* (- u (* 2.0 phi dy)) n d) (* phi dy dy d d)) 0.0))
; goal
(assert (not (and (a9 (- (* 2.0 psi dy) u r) (impact_den phi))
                  (a9 (+ (- (* 2.0 psi dy) u) r) (impact_den phi)))))
(check-sat)
