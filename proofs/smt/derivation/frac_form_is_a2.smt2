; Claim: for d > 0 and n = s d, (A.2) holds at s exactly when its fraction form holds at
; (n, d): solves_frac, the form in which the case formulas s = n / d are checked (it is
; (A.2) at n / d multiplied by d^2), is (A.2) itself.
; expect: unsat
; show: u dy phi s d n
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
(declare-const d Real)
(declare-const n Real)
; include prelude
(assert (> d 0.0))
(assert (= n (* s d)))
; hints
(assert (= (* (fl (- (* dy d) n)) (fl (- (* dy d) n))) (* d d (fl (- dy s)) (fl (- dy s)))))
(assert (= (* n n) (* s s d d)))
(assert (= (* u n d) (* u s d d)))
; then, the multiplied form is d^2 times s (A.2)
(assert (= (+ (* n n) (* u n d) (* phi (- (* (fl (- (* dy d) n)) (fl (- (* dy d) n))) (* (fl dy) (fl dy) d d)))) (* d d (+ (* s s) (* u s) (* phi (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy))))))))

(assert (= (= (* d d (+ (* s s) (* u s) (* phi (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy)))))) 0.0) (= (+ (* s s) (* u s) (* phi (- (* (fl (- dy s)) (fl (- dy s))) (* (fl dy) (fl dy))))) 0.0)))

(assert (= (= n 0.0) (= s 0.0)))
; goal
(assert (not (= (solves_frac u dy phi n d) (solves u dy phi s))))
(check-sat)
