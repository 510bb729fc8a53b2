; Claim: (A.2) holds at s exactly when the residual s + u + phi q(s) vanishes, q the
; (extended) difference quotient: `solves` and the residual used for monotonicity agree.
; expect: unsat
; show: u dy phi s q
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const s Real)
(declare-const q Real)
; include prelude
(assert (quotient_is dy s q))
; goal
(assert (not (= (solves u dy phi s) (= (+ s u (* phi q)) 0.0))))
(check-sat)
