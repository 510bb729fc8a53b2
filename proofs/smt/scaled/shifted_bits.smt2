; Claim: scaled<double>::shifted's bit path is ldexp: for a normal binary64 x whose
; exponent field plus the shift stays inside (0, 2047), adding the shift to the exponent
; field gives x 2^shift exactly (the sign bit is untouched). Bit-precise, both solvers
; (cvc5 with --fp-exp for Wide), under a second.
; expect: unsat
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const x (_ BitVec 64))
(declare-const shift (_ BitVec 13))
(define-fun field () (_ BitVec 13) ((_ zero_extend 2) ((_ extract 62 52) x)))
(assert (not (= field (_ bv0 13))))
(assert (not (= field (_ bv2047 13))))
(assert (bvsge shift (bvneg (_ bv2046 13))))
(assert (bvsle shift (_ bv2046 13)))
(assert (bvsgt (bvadd field shift) (_ bv0 13)))
(assert (bvslt (bvadd field shift) (_ bv2047 13)))
; goal
(assert (not (fp.eq (widen ((_ to_fp 11 53) (bvadd x (bvshl ((_ sign_extend 51) shift) (_ bv52 64)))))
                    (fp.mul RNE (widen ((_ to_fp 11 53) x)) (wide_power_of_two shift)))))
