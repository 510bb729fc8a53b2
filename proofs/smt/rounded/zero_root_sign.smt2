; Claim: signed_zero_for_root: a root s /= 0 of (A.2) is positive exactly when
; the limit of R at 0, u - 2 phi floor(dy), is negative (R increasing through
; its continuous extension at 0), so the zero a tiny root rounds to carries the
; sign the code gives it.
; expect: unsat
; show: u dy phi s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
(declare-const qs Real)
(declare-const q0 Real)
; include prelude
(assert (>= phi 0.0))
(assert (not (= s 0.0)))
(assert (solves u dy phi s))
(assert (quotient_is dy s qs))
(assert (quotient_is dy 0.0 q0))
; hints
; lemma derivation/residual_is_a2 s:=s q:=qs
; lemma derivation/residual_increasing s1:=0.0 s2:=s q1:=q0 q2:=qs
; lemma derivation/residual_increasing s1:=s s2:=0.0 q1:=qs q2:=q0
(assert (= (+ s u (* phi qs)) 0.0))
(assert (= q0 (* (- 2.0) (fl dy))))
; goal
(assert (not (= (> s 0.0) (< (- u (* 2.0 phi (fl dy))) 0.0))))
(check-sat)
