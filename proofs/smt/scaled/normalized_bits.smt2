; Claim: scaled<double>::normalized's bit path is frexp: for a normal binary64 m (its
; exponent field neither 0 nor all ones), the exponent field set to that of [0.5, 1)
; gives a significand r with 0.5 <= |r| < 1 and m = r 2^(field - 1022) exactly.
; Bit-precise, both solvers (cvc5 with --fp-exp for Wide), under a second.
; expect: unsat
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const m (_ BitVec 64))
(define-fun field () (_ BitVec 11) ((_ extract 62 52) m))
(assert (not (= field #b00000000000)))
(assert (not (= field #b11111111111)))
(define-fun r () (_ BitVec 64)
  (bvor (bvand m (bvnot (bvshl ((_ zero_extend 53) #b11111111111) (_ bv52 64)))) (bvshl (_ bv1022 64) (_ bv52 64))))
; goal
(assert (not (and (significand ((_ to_fp 11 53) r))
                  (fp.eq (widen ((_ to_fp 11 53) m))
                         (fp.mul RNE (widen ((_ to_fp 11 53) r))
                                 (wide_power_of_two (bvsub ((_ zero_extend 2) field) (_ bv1022 13))))))))
