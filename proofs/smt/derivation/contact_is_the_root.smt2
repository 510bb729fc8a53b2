; Claim: in case (A.31) the value s of its formula is THE root of (A.2): any root t equals
; it. From contact_root (s is a root) and root_unique (no two roots).
; expect: unsat
; show: u dy phi s t
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
(declare-const t Real)
(declare-const q1 Real)
(declare-const q2 Real)
; include prelude
(assert (>= phi 0.0))
(assert (contact_case u dy phi))
; s is the formula
(assert (= (contact_num u dy phi) (* s (contact_den phi))))
; t is any root
(assert (solves u dy phi t))
; q1, q2 name the difference quotients at s and t (every s has one: this restricts nothing)
(assert (quotient_is dy s q1))
(assert (quotient_is dy t q2))
; hints
; lemma derivation/contact_root
; lemma derivation/root_unique s1:=s s2:=t
; lemma derivation/root_unique s1:=t s2:=s q1:=q2 q2:=q1
; goal
(assert (not (= t s)))
(check-sat)
