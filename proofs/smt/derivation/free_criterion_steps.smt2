; Claim: the derivation (A.4) -> (A.6): for dy <= 0 the side condition s >= dy of s = -u
; (A.5) is equivalent to u <= -dy (A.6).
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
; include prelude
(assert (>= phi 0.0))
(assert (<= dy 0.0))
; goal
(assert (not (= (>= (free_num u) dy) (<= u (- dy)))))
(check-sat)
