; Claim: scaled<double>'s fused_multiply_add rounds as binary64 with an unbounded exponent
; where the product lies 61 to 1021 binades below the addend. With a.exponent +
; b.exponent < c.exponent it is fma(a.significand, shifted(b.significand, d),
; c.significand), d = a.exponent + b.exponent - c.exponent; for d in [-1021, -61] the
; shift is exact. Bit-precise; cvc5 with --fp-exp, a few seconds. For d from -1022 on
; the shifted factor rounds (case (a) of scaled.hpp); for d in [-60, -1] cvc5 did not
; finish in 15 minutes: checked exhaustively on 5-bit formats (proofs.scaled_exhaustive).
; expect: unsat
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const a Float64)
(declare-const b Float64)
(declare-const c Float64)
(declare-const d (_ BitVec 13))
(assert (significand a))
(assert (significand b))
(assert (significand c))
(assert (bvsle d (bvneg (_ bv61 13))))
(assert (bvsge d (bvneg (_ bv1021 13))))
; goal
(assert (not (fp.eq (widen (fp.fma RNE a (fp.mul RNE b (power_of_two d)) c))
                    (fp.fma RNE (widen a) (fp.mul RNE (widen b) (wide_power_of_two d)) (widen c)))))
