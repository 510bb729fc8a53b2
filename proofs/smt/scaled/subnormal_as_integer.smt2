; Claim: scaled<double>'s subnormal path (normalized and shifted, scaled.hpp) is exact: a
; subnormal binary64 x is k 2^-1074 for the integer k of its bits without the sign, which
; converts to binary64 exactly (k < 2^52), so x = copysign(k, x) 2^-1074 and the normal
; k then takes the bit paths (normalized_bits, shifted_bits) with the exponent lowered by
; 1074. Bit-precise, both solvers (cvc5 with --fp-exp for Wide), under a second.
; expect: unsat
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const x (_ BitVec 64))
(assert (= ((_ extract 62 52) x) #b00000000000))
(define-fun magnitude () (_ BitVec 64) (bvand x #x7fffffffffffffff))
(assert (not (= magnitude (_ bv0 64))))
(define-fun k () Float64 ((_ to_fp 11 53) RNE magnitude))  ; the integer, as T(signed bits) converts it
(define-fun signed_k () Float64 (ite (= ((_ extract 63 63) x) #b1) (fp.neg k) k))
; goal
(assert (not (and (fp.isNormal k)
                  (fp.eq (widen ((_ to_fp 11 53) x))
                         (fp.mul RNE (widen signed_k) (wide_power_of_two (bvneg (_ bv1074 13))))))))
