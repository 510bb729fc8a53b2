; Claim: far_eight's fma (batch.hpp) gives scaled<double>'s where the product lies more than
; 1000 binades below the addend: there scaled<T> computes fma(a, shifted(b, d), c), d =
; a.exponent + b.exponent - c.exponent in [-2043, -1001], and the batch kernel takes the
; stand-in of shifted(b, d) (batch/prelude) instead: both products lie below 2^-1000, far
; below a quarter ulp of the significand c, which both fmas return. Bit-precise; cvc5 with --fp-exp.
; expect: unsat
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
; include batch/prelude
(declare-const a Float64)
(declare-const b Float64)
(declare-const c Float64)
(declare-const d (_ BitVec 13))
(assert (significand a))
(assert (significand b))
(assert (significand c))
(assert (bvsle d (bvneg (_ bv1001 13))))
(assert (bvsge d (bvneg (_ bv2043 13))))
; goal
(assert (not (fp.eq (fp.fma RNE a (shifted b d) c) (fp.fma RNE a (stand_in b d) c))))
