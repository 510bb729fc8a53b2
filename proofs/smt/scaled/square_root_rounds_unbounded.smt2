; Claim: scaled<double>'s square_root rounds as binary64 with an unbounded exponent. An
; odd exponent first halves the significand (exact, smt/floating/
; division_by_power_of_two_exact) and moves to the even exponent above, so the root is
; taken of m in [0.25, 1) and the exponent halves exactly; there binary64's square root
; rounds as Wide's. Bit-precise; cvc5 with --fp-exp, about 15 s.
; expect: unsat
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const m Float64)
(assert (fp.leq ((_ to_fp 11 53) RNE 0.25) m))
(assert (fp.lt m ((_ to_fp 11 53) RNE 1.0)))
; goal
(assert (not (fp.eq (widen (fp.sqrt RNE m)) (fp.sqrt RNE (widen m)))))
