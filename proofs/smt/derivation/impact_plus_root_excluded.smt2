; Claim: in case (A.30) the other root of (A.9), with + sqrt in (A.10), is >= dy, against
; (A.7): this, not its sign, is why (A.11) takes the - root (both roots are <= 0, see
; errata/a10_root_choice).
; expect: unsat
; show: u dy phi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (>= (+ (- (* 2.0 phi dy) u) r) (* dy (impact_den phi)))))
(check-sat)
