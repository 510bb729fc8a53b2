; Claim: in case (A.30) the value s = num / den of its formula solves (A.2): impact_solves
; checks the fraction form, frac_form_is_a2 says that the fraction form is (A.2).
; expect: unsat
; show: u dy phi s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (is_sqrt r (impact_disc u dy phi)))
; s is the formula
(assert (= (impact_num u dy phi r) (* s (impact_den phi))))
; hints
; lemma derivation/impact_solves
; lemma derivation/frac_form_is_a2 n:=(impact_num u dy phi r) d:=(impact_den phi)
; goal
(assert (not (solves u dy phi s)))
(check-sat)
