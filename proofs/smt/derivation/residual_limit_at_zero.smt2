; Claim: the difference quotient q(s) = (floor(dy - s)^2 - floor(dy)^2) / s satisfies
; |q(s) + 2 floor(dy)| <= |s| for every s /= 0 near 0 (s <= dy when dy > 0; any s when dy
; <= 0), so q -> -2 floor(dy) as s -> 0: the value that prelude's `solves` and
; `quotient_is` give (A.2) at s = 0 is its continuous extension.
; expect: unsat
; show: dy s q
(set-logic QF_NRA)
(declare-const dy Real)
(declare-const s Real)
(declare-const q Real)
; include prelude
(assert (not (= s 0.0)))
(assert (or (<= dy 0.0) (<= s dy)))
(assert (quotient_is dy s q))
; hints
(assert (=> (and (<= dy 0.0) (>= s dy)) (= q 0.0)))
(assert (=> (and (<= dy 0.0) (< s dy)) (<= q 0.0)))
(assert (=> (and (<= dy 0.0) (< s dy)) (<= (* (- dy s) (- dy s)) (* s s))))
(assert (=> (and (<= dy 0.0) (< s dy)) (>= q s)))
(assert (=> (> dy 0.0) (= (* (- q (- s (* 2.0 dy))) s) 0.0)))
(assert (=> (> dy 0.0) (= q (- s (* 2.0 dy)))))
; goal
(assert (not (and (<= (+ q (* 2.0 (fl dy))) (ite (>= s 0.0) s (- s)))
                  (>= (+ q (* 2.0 (fl dy))) (- (ite (>= s 0.0) s (- s)))))))
(check-sat)
