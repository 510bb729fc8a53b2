; Claim: for phi >= 0 the residual R(s) = s + u + phi q(s) of (A.2) is strictly increasing
; in s: q, the difference quotient of the convex floor(dy - s)^2 at 0, never decreases.
; (The hints walk cvc5 through the regions: on each side of the kink s = dy, q is
; monotone, and q lies below its kink value on the left, above it on the right.)
; expect: unsat
; show: u dy phi s1 s2 q1 q2
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s1 Real)
(declare-const s2 Real)
(declare-const q1 Real)
(declare-const q2 Real)
; include prelude
(assert (>= phi 0.0))
(assert (< s1 s2))
(assert (quotient_is dy s1 q1))
(assert (quotient_is dy s2 q2))
; hints
(assert (=> (and (<= dy 0.0) (>= s1 dy)) (= q1 0.0)))
(assert (=> (and (<= dy 0.0) (>= s2 dy)) (= q2 0.0)))
(assert (=> (and (<= dy 0.0) (< s1 dy)) (<= q1 0.0)))

(assert (=> (and (<= dy 0.0) (< s2 dy)) (= (* q1 s1 s2) (* (- dy s1) (- dy s1) s2))))
(assert (=> (and (<= dy 0.0) (< s2 dy)) (= (* q2 s2) (* (- dy s2) (- dy s2)))))
(assert (=> (and (<= dy 0.0) (< s2 dy)) (= (* q2 s1 s2) (* (- dy s2) (- dy s2) s1))))
(assert (=> (and (<= dy 0.0) (< s2 dy)) (< (* (- q1 q2) s1 s2) 0.0)))
(assert (=> (and (<= dy 0.0) (< s2 dy)) (< q1 q2)))

(assert (=> (and (> dy 0.0) (<= s1 dy)) (= (* (- q1 (- s1 (* 2.0 dy))) s1) 0.0)))
(assert (=> (and (> dy 0.0) (<= s1 dy)) (= q1 (- s1 (* 2.0 dy)))))

(assert (=> (and (> dy 0.0) (<= s2 dy)) (= (* (- q2 (- s2 (* 2.0 dy))) s2) 0.0)))
(assert (=> (and (> dy 0.0) (<= s2 dy)) (= q2 (- s2 (* 2.0 dy)))))

(assert (=> (and (> dy 0.0) (> s2 dy)) (>= q2 (- dy))))

(assert (=> (and (> dy 0.0) (> s1 dy)) (= (* q1 s1 s2) (- (* dy dy s2)))))
(assert (=> (and (> dy 0.0) (> s1 dy)) (= (* q2 s1 s2) (- (* dy dy s1)))))
(assert (=> (and (> dy 0.0) (> s1 dy)) (< q1 q2)))

; then, the regions together: q never decreases
(assert (<= q1 q2))
; goal
(assert (not (< (+ s1 u (* phi q1)) (+ s2 u (* phi q2)))))
(check-sat)
