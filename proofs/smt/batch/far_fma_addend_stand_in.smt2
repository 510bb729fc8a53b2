; Claim: far_eight's fma (batch.hpp, fused_multiply_add on scaled_eight) gives scaled<double>'s
; where the addend lies more than 1000 binades below the product: there scaled<T> adds
; shifted(c, d), d = c.exponent - a.exponent - b.exponent in [-2043, -1001], which may round
; into the subnormals, and the batch kernel adds a stand-in instead, normal (no microcode
; assist): 0 with c's sign where shifted gives 0 (d <= -1075, or d = -1074 with |c| = 1/2),
; else 2^-1010 with c's sign. The exact product of two significands is a multiple of
; 2^-106 in [1/4, 1), so an addend below 2^-1000 moves it across no rounding boundary, and
; on a boundary (a tie) only its sign tells: the two fmas agree. Bit-precise; cvc5 with --fp-exp.
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
(assert (not (fp.eq (fp.fma RNE a b (shifted c d)) (fp.fma RNE a b (stand_in c d)))))
