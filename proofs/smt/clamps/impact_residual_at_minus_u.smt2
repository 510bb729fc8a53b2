; Claim: in case (A.30) the residual of (A.2) at s = -u is <= 0:
; R(-u) = -u + u + phi q(-u) = -phi (dy + u)^2 / u. R is increasing (residual_increasing)
; and vanishes at the root, so the root is >= -u: the clamp `s < -u ? -u : s` in
; impact_clamped moves s towards it (impact_lower_clamp_toward_root proves the distance).
; expect: unsat
; show: u dy phi q
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const q Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (quotient_is dy (- u) q))
; goal
(assert (not (<= (+ (- u) u (* phi q)) 0.0)))
(check-sat)
