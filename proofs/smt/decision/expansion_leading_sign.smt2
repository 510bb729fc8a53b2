; Claim: the sign of a non-overlapping expansion is the sign of its largest component,
; which is what sign_of_exact_sum (float_tools.hpp) returns. Components e1..e4 (the
; at most four non-zero ones of stays_in_contact's four terms), increasing; component i
; is a non-zero multiple of a power of two L_i that its bits start at, and lies below
; L_(i+1), where the next one's bits start: so L_i <= |e_i| <= L_(i+1) - L_i. Then
; |e1 + e2 + e3| <= L4 - L1 < |e4|, and the sum has e4's sign.
; That Shewchuk's Grow-Expansion with zero elimination keeps the expansion non-overlapping
; (his Theorem 10) and that two_sum is exact are not proven here.
; expect: unsat
; show: e1 e2 e3 e4
(set-logic QF_LRA)
(declare-const e1 Real)
(declare-const e2 Real)
(declare-const e3 Real)
(declare-const e4 Real)
(declare-const L1 Real)
(declare-const L2 Real)
(declare-const L3 Real)
(declare-const L4 Real)
(define-fun absolute ((x Real)) Real (ite (>= x 0.0) x (- x)))
(assert (> L1 0.0))
(assert (and (<= L1 (absolute e1)) (<= (absolute e1) (- L2 L1))))
(assert (and (<= L2 (absolute e2)) (<= (absolute e2) (- L3 L2))))
(assert (and (<= L3 (absolute e3)) (<= (absolute e3) (- L4 L3))))
(assert (<= L4 (absolute e4)))
; goal
(assert (not (and (= (> (+ e1 e2 e3 e4) 0.0) (> e4 0.0)) (= (< (+ e1 e2 e3 e4) 0.0) (< e4 0.0)))))
(check-sat)
