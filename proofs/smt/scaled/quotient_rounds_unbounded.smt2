; Claim: scaled<double>'s quotient rounds as binary64 with an unbounded exponent. It is
; normalized(a.significand / b.significand, a.exponent - b.exponent): the significands'
; quotient lies in (0.5, 2), where binary64 rounds as Wide does. Bit-precise; cvc5 with
; --fp-exp, about 15 s (z3 does not finish in minutes).
; expect: unsat
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const a Float64)
(declare-const b Float64)
(assert (significand a))
(assert (significand b))
; goal
(assert (not (fp.eq (widen (fp.div RNE a b)) (fp.div RNE (widen a) (widen b)))))
