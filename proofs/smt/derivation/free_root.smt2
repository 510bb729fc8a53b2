; Claim: in case (A.29) the value s = num / den of its formula solves (A.2): free_solves
; checks the fraction form, frac_form_is_a2 says that the fraction form is (A.2).
; expect: unsat
; show: u dy phi s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
; include prelude
(assert (>= phi 0.0))
(assert (free_case u dy phi))
; s is the formula
(assert (= (free_num u) (* s 1.0)))
; hints
; lemma derivation/free_solves
; lemma derivation/frac_form_is_a2 n:=(free_num u) d:=1.0
; goal
(assert (not (solves u dy phi s)))
(check-sat)
