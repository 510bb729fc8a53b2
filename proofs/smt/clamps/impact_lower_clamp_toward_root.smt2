; Claim: in case (A.30), when the computed s lies below -u, the clamp `s < -u ? -u : s`
; (impact_clamped, impact) does not move s away from the root t of (A.2): |-u - t| <= |s - t|,
; because t >= -u (at t < -u every term of (A.2) times t is positive).
; expect: unsat
; show: u dy phi t s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const t Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (solves u dy phi t))
(assert (< s (- u)))
; goal
(assert (not (<= (abs (- (- u) t)) (abs (- s t)))))
(check-sat)
