; Counterexample: binary64's own product of two normal numbers does not round as an
; unbounded exponent would (it underflows or overflows). This is why scaled<T> multiplies
; significands in [0.5, 1) and carries the exponent apart, and it shows that
; product_rounds_unbounded is not true for want of a difference between the formats.
; expect: sat
; show: a b
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const a Float64)
(declare-const b Float64)
(assert (fp.isNormal a))
(assert (fp.isNormal b))
; goal
(assert (not (fp.eq (widen (fp.mul RNE a b)) (fp.mul RNE (widen a) (widen b)))))
