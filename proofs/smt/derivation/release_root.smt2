; Claim: in case (A.32) the value s = num / den of its formula solves (A.2):
; release_solves checks the fraction form, frac_form_is_a2 says that the fraction form is
; (A.2).
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
(assert (release_case u dy phi))
(assert (is_sqrt r (release_disc u dy phi)))
; s is the formula
(assert (= (release_num u r) (* s release_den)))
; hints
; lemma derivation/release_solves
; lemma derivation/frac_form_is_a2 n:=(release_num u r) d:=release_den
; goal
(assert (not (solves u dy phi s)))
(check-sat)
