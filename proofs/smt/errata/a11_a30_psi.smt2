; Erratum (A.11) and (A.30): printed with 2 psi dy. Refuted claim: in case (A.30), for any
; psi, s = (2 psi dy - u - sqrt(u^2 - 4 phi dy (u + dy))) / (2 (1 + phi)) solves (A.2).
; expect: sat
; show: u dy phi psi r
; witness: u 2 dy -1 phi 5/4 psi 0 r 3
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const psi Real)
(declare-const r Real)
; include prelude
(assert (>= phi 0.0))
(assert (impact_case u dy phi))
(assert (is_sqrt r (impact_disc u dy phi)))
; goal
(assert (not (solves_frac u dy phi (- (* 2.0 psi dy) u r) (impact_den phi))))
(check-sat)
