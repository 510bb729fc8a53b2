; Claim: in case (A.30), when the computed s is not below dy, the clamp
; `s < dy ? s : next_down(dy)` (impact_clamped, impact) puts s on the root's side: the
; root t of (A.2) is < dy, so the clamped s1 = dy - g (g > 0 the distance to the next double
; below dy) either moves towards t without passing it (|s1 - t| <= |s - t|) or passes it,
; and then |s1 - t| < g, less than one spacing of the doubles at dy.
; (impact_upper_clamp_can_increase_error: passing it can increase the error.)
; expect: unsat
; show: u dy phi t s g
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
(assert (not (and (< t dy)
                  (or (<= (abs (- (- dy g) t)) (abs (- s t)))
                      (< (abs (- (- dy g) t)) g)))))
(check-sat)
