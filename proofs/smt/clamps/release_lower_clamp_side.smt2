; Claim: in case (A.32), when the computed s is not above dy, the clamp
; `s > dy ? s : next_up(dy)` (clamped_above_positive, release) puts s on the root's side: the
; root t of (A.2) is > dy, so the clamped s1 = dy + g (g > 0 the distance to the next double
; above dy) either moves towards t without passing it (|s1 - t| <= |s - t|) or passes it,
; and then |s1 - t| < g.
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
(assert (release_case u dy phi))
(assert (solves u dy phi t))
(assert (<= s dy))
(assert (> g 0.0))
; hints
(assert (=> (<= t dy) (= (* t (+ (* (+ 1.0 phi) t) u (- (* 2.0 phi dy)))) 0.0)))
(assert (not (= t 0.0)))
; then at t <= dy, t /= 0, (A.2) is (A.18), whose root is > dy in case (A.32)
(assert (=> (<= t dy) (= (+ (* (+ 1.0 phi) t) u (- (* 2.0 phi dy))) 0.0)))
(assert (> t dy))
; goal
(assert (not (and (> t dy)
                  (or (<= (abs (- (+ dy g) t)) (abs (- s t)))
                      (< (abs (- (+ dy g) t)) g)))))
(check-sat)
