; Claim: in case (A.31) the value s = num / den of its formula solves (A.2):
; contact_solves checks the fraction form, frac_form_is_a2 says that the fraction form is
; (A.2).
; expect: unsat
; show: u dy phi s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (contact_case u dy phi))
; s is the formula
(assert (= (contact_num u dy phi) (* s (contact_den phi))))
; hints
; lemma derivation/contact_solves
; lemma derivation/frac_form_is_a2 n:=(contact_num u dy phi) d:=(contact_den phi)
; goal
(assert (not (solves u dy phi s)))
(check-sat)
