; Claim: (A.2) is homogeneous of degree one in (s, u, dy): for k > 0, s solves it for (u,
; dy, phi) exactly when k s solves it for (k u, k dy, phi).
; expect: unsat
; show: u dy phi s k
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
(declare-const k Real)
; include prelude
(assert (>= phi 0.0))
(assert (> k 0.0))
; hints
(assert (= (* (fl (- (* k dy) (* k s))) (fl (- (* k dy) (* k s)))) (* k k (fl (- dy s)) (fl (- dy s)))))
(assert (= (* (fl (* k dy)) (fl (* k dy))) (* k k (fl dy) (fl dy))))
; then, s (A.2) at (k u, k dy, k s) is k^2 times s (A.2) at (u, dy, s)
(assert (= (+ (* (* k s) (* k s)) (* (* k u) (* k s)) (* phi (- (* (fl (- (* k dy) (* k s))) (fl (- (* k dy) (* k s)))) (* (fl (* k dy)) (fl (* k dy)))))) (* k k (+ (* s s) (* u s) (* phi (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy))))))))

(assert (= (= (* k k (+ (* s s) (* u s) (* phi (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy)))))) 0.0) (= (+ (* s s) (* u s) (* phi (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy))))) 0.0)))

(assert (= (* phi (fl (* k dy))) (* phi k (fl dy))))
(assert (= (- (* k u) (* 2.0 phi (fl (* k dy)))) (* k (- u (* 2.0 phi (fl dy))))))
(assert (= (= (* k (- u (* 2.0 phi (fl dy)))) 0.0) (= (- u (* 2.0 phi (fl dy))) 0.0)))

(assert (= (= (* k s) 0.0) (= s 0.0)))
; goal
(assert (not (= (solves (* k u) (* k dy) phi (* k s)) (solves u dy phi s))))
(check-sat)
