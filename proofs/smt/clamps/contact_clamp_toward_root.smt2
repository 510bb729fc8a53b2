; Claim: in case (A.31), when the computed s lies above dy, the clamp `s > dy ? dy : s`
; (contact_clamped, contact) does not move s away from the root t of (A.2): |dy - t| <= |s - t|,
; because t <= dy (above dy, (A.2) times t is (t - dy)(t + dy + u) + dy (dy + u - phi dy) > 0).
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
(assert (contact_case u dy phi))
(assert (solves u dy phi t))
(assert (> s dy))
; goal
(assert (not (<= (abs (- dy t)) (abs (- s t)))))
(check-sat)
