; Claim: the derivation (A.12) -> (A.15), corrected: for dy < 0 (as the text assumes) the
; side condition (A.7) of the (A.30) root, dy > s, is equivalent to (2 dy + u)^2 < u^2 - 4
; phi dy (u + dy) [(A.13) printed with >], to dy (dy + u) (1 + phi) < 0 [(A.14) printed
; with >], to dy + u > 0 [the text says < 0], and to u > -dy (A.15).
; expect: unsat
; show: u dy phi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (< dy 0.0))
(assert (is_sqrt r (impact_disc u dy phi)))
(define-fun a12 () Bool (< (impact_num u dy phi r) (* dy (impact_den phi))))
(define-fun a13 () Bool (< (* (+ (* 2.0 dy) u) (+ (* 2.0 dy) u)) (impact_disc u dy phi)))
(define-fun a14 () Bool (< (* dy (+ dy u) (+ 1.0 phi)) 0.0))
(define-fun after_a14 () Bool (> (+ dy u) 0.0))
(define-fun a15 () Bool (> u (- dy)))
; goal
(assert (not (and (= a12 a13) (= a13 a14) (= a14 after_a14) (= after_a14 a15))))
(check-sat)
