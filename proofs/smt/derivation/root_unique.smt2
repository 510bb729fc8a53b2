; Claim: for phi >= 0, (A.2) has at most one root: no s1 < s2 both solve it (the claim is
; symmetric, so s1 < s2 loses nothing). It follows from residual_increasing and
; residual_is_a2; with the *_solves obligations (each case formula is a root) the root is
; unique and the case formulas give it.
; expect: unsat
; show: u dy phi s1 s2
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s1 Real)
(declare-const s2 Real)
(declare-const q1 Real)
(declare-const q2 Real)
; include prelude
(assert (>= phi 0.0))
(assert (< s1 s2))
; q1, q2 name the difference quotients; every s has one, so this restricts nothing
(assert (quotient_is dy s1 q1))
(assert (quotient_is dy s2 q2))
; hints
; lemma derivation/residual_increasing
; lemma derivation/residual_is_a2 s:=s1 q:=q1
; lemma derivation/residual_is_a2 s:=s2 q:=q2
; goal
(assert (not (not (and (solves u dy phi s1) (solves u dy phi s2)))))
(check-sat)
