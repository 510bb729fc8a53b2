; Claim: in case (A.30) (dy <= 0, u > -dy) the formula s = (2 phi dy - u - sqrt(u^2 - 4
; phi dy (u + dy))) / (2 (1 + phi)) solves (A.2) (checked as solves_frac, see
; frac_form_is_a2).
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
; hints
; lemma derivation/impact_side
; r^2 = D multiplied by phi: the step cvc5 does not take by itself
(assert (= (* phi r r) (* phi (impact_disc u dy phi))))
; goal
(assert (not (solves_frac u dy phi (impact_num u dy phi r) (impact_den phi))))
(check-sat)
