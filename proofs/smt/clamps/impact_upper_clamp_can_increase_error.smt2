; Claim refuted (sat): the clamp onto next_down(dy) in case (A.30) does not always reduce
; |s - t|. When the root t lies between dy - g and dy, nearer dy, a computed s = dy is
; closer to t than the clamped dy - g. So impact_upper_clamp_side's bound (below one
; spacing g) is what holds, not "never increases the error".
; Witness: dy = -1, phi = 1, u = 41/36: (A.9) 2 t^2 + (u + 2) t + 1 = 0 has the root
; t = -9/8 < dy; s = dy = -1 is 1/8 from it, the clamped -1 - g = -2 (g = 1) is 7/8 away.
; expect: sat
; show: u dy phi t s g
; witness: u 41/36 dy -1 phi 1 t -9/8 s -1 g 1
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const t Real)
(declare-const s Real)
(declare-const g Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (solves u dy phi t))
(assert (>= s dy))
(assert (> g 0.0))
; goal
(assert (not (<= (abs (- (- dy g) t)) (abs (- s t)))))
(check-sat)
