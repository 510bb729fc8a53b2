; Claim: the derivation (A.26) -> (A.28): for dy > 0 the side condition s > dy of the
; (A.32) root, 2 dy < -u + sqrt(u^2 + 4 phi dy^2) (A.26), is equivalent to u^2 + 4 phi
; dy^2 > (2 dy + u)^2 (A.27) and to u < dy (phi - 1) (A.28).
; expect: unsat
; show: u dy phi r
; cvc5-options: --simplification=none
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (> dy 0.0))
(assert (is_sqrt r (release_disc u dy phi)))
; c names 2 dy + u (a definition: it restricts nothing)
(declare-const c Real)
(assert (= c (+ (* 2.0 dy) u)))
(define-fun a26 () Bool (< (* 2.0 dy) (- r u)))
(define-fun a27 () Bool (> (release_disc u dy phi) (* (+ (* 2.0 dy) u) (+ (* 2.0 dy) u))))
(define-fun a28 () Bool (< u (* dy (- phi 1.0))))
; hints
(assert (= (- (release_disc u dy phi) (* (+ (* 2.0 dy) u) (+ (* 2.0 dy) u))) (* 4.0 dy (- (* dy (- phi 1.0)) u))))
(assert (= a27 a28))

(assert (=> (and (>= c 0.0) (> r c)) (> (* r r) (* c c))))
(assert (=> (and (>= c 0.0) (<= r c)) (<= (* r r) (* c c))))

(assert (=> (< (+ (* 2.0 dy) u) 0.0) (and a26 a28)))
; goal
(assert (not (and (= a26 a27) (= a27 a28))))
(check-sat)
