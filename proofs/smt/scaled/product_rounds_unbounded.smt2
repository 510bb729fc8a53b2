; Claim: scaled<double>'s product rounds as binary64 with an unbounded exponent. It is
; normalized(a.significand * b.significand, a.exponent + b.exponent): the significands'
; product lies in [0.25, 1), where binary64 rounds as Wide does. Bit-precise.
; z3 does not finish this in minutes (two 53-bit multipliers in two formats); cvc5's
; floating-point solver for formats other than binary32/64 (--fp-exp) proves it in 1 s.
; expect: unsat
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const a Float64)
(declare-const b Float64)
(assert (significand a))
(assert (significand b))
; goal
(assert (not (fp.eq (widen (fp.mul RNE a b)) (fp.mul RNE (widen a) (widen b)))))
