; Claim: scaled<double>'s fused_multiply_add rounds as binary64 with an unbounded exponent
; where the addend lies 61 to 1021 binades below the product. With a.exponent +
; b.exponent >= c.exponent it is fma(a.significand, b.significand, shifted(c.significand,
; d)), d = c.exponent - a.exponent - b.exponent; for d in [-1021, -61] the shift is
; exact (the shifted significand is a normal binary64) and the addend lies far below
; half an ulp of the product. Bit-precise; cvc5 with --fp-exp, about 15 s.
; From d = -1022 on, the shift itself rounds (case (a) of scaled.hpp: a product that is
; a tie can then round the other way); for d in [-60, 0] this query took cvc5 750 s, too
; long for ctest: that range is checked exhaustively on 5-bit formats
; (proofs.scaled_exhaustive).
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
(assert (not (fp.eq (widen (fp.fma RNE a b (fp.mul RNE c (power_of_two d))))
                    (fp.fma RNE (widen a) (widen b) (fp.mul RNE (widen c) (wide_power_of_two d))))))
