; Claim: in case (A.32) (dy > 0, u < dy (phi - 1)) the formula s = (-u + sqrt(u^2 + 4 phi
; dy^2)) / 2 solves (A.2).
; expect: unsat
; show: u dy phi r
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (release_case u dy phi))
(assert (is_sqrt r (release_disc u dy phi)))
; hints
; lemma derivation/release_side
; goal
(assert (not (solves_frac u dy phi (release_num u r) release_den)))
(check-sat)
