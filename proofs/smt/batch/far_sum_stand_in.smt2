; Claim: far_eight's sum (batch.hpp, operator+ on scaled_eight) gives scaled<double>'s
; where the smaller term lies more than 1000 binades below the larger: scaled<T> adds
; shifted(b, d), d = b.exponent - a.exponent in [-2043, -1001], to the significand a, the
; batch kernel the stand-in of shifted(b, d) (batch/prelude): both sums round to a.
; Bit-precise; cvc5 with --fp-exp.
; expect: unsat
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
; include batch/prelude
(declare-const a Float64)
(declare-const b Float64)
(declare-const d (_ BitVec 13))
(assert (significand a))
(assert (significand b))
(assert (bvsle d (bvneg (_ bv1001 13))))
(assert (bvsge d (bvneg (_ bv2043 13))))
; goal
(assert (not (fp.eq (fp.add RNE a (shifted b d)) (fp.add RNE a (stand_in b d)))))
