; Claim (for the erratum of (A.10), (A.11), (A.12), (A.30), which print psi): in case
; (A.30) the printed formula solves (A.2) only if psi dy = phi dy, i.e. psi = phi (dy = 0
; hides psi). Both values, s for phi and t for psi, would be roots of (A.2), and there is
; only one.
; expect: unsat
; show: u dy phi psi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const psi Real)
(declare-const r Real)
(declare-const s Real)
(declare-const t Real)
(declare-const q1 Real)
(declare-const q2 Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (is_sqrt r (impact_disc u dy phi)))
; the printed formula solves (A.2)
(assert (solves_frac u dy phi (- (* 2.0 psi dy) u r) (impact_den phi)))
; s: the (A.30) value with phi; t: the printed value with psi; q1, q2: their difference
; quotients (definitions: they restrict nothing)
(assert (= (impact_num u dy phi r) (* s (impact_den phi))))
(assert (= (- (* 2.0 psi dy) u r) (* t (impact_den phi))))
(assert (quotient_is dy s q1))
(assert (quotient_is dy t q2))
; hints
; lemma derivation/impact_root
; lemma derivation/frac_form_is_a2 s:=t n:=(- (* 2.0 psi dy) u r) d:=(impact_den phi)
; then, both are roots, so they are equal
(assert (solves u dy phi s))
(assert (solves u dy phi t))
; lemma derivation/root_unique s1:=s s2:=t
; lemma derivation/root_unique s1:=t s2:=s q1:=q2 q2:=q1
(assert (= s t))
; goal
(assert (not (= (* psi dy) (* phi dy))))
(check-sat)
