; Erratum (A.29)/(A.30): printed (A.29) u < -dy and (A.30) u >= -dy. On u = -dy the (A.30)
; formula gives s = dy, which violates its own side condition (A.7) s < dy (A.29 gives the
; same s, with s >= dy as (A.4) requires). Refuted claim: in the printed (A.30) region
; (psi read as phi) the formula satisfies s < dy.
; expect: sat
; show: u dy phi r
; witness: u 1 dy -1 phi 1 r 1
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (<= dy 0.0))
(assert (>= u (- dy)))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (< (impact_num u dy phi r) (* dy (impact_den phi)))))
(check-sat)
