; Claim: scaled<double>::shifted where x 2^shift falls below the normal range is ldexp,
; which rounds x 2^shift once (to nearest, ties to even) to a subnormal or a zero. For
; a normal binary64 x whose exponent field plus the shift (`target`) lies in [-52, 0],
; the code moves x exactly to the field target + 54 (a normal number) and multiplies by
; the normal 2^-54: one rounding of the same exact value. Below -52 it returns a zero of
; x's sign, as x 2^shift < 2^-1075 (half the least subnormal; 2^-1075 itself is a tie
; that rounds to the even 0). Wide holds x 2^shift exactly, so its rounding to binary64
; is ldexp's result. Bit-precise; z3 only, in about a second: cvc5 1.0.3 crashes on the
; narrowing conversion from Wide to binary64 that states ldexp's rounding here.
; expect: unsat
; solvers: z3
; include scaled/prelude
(declare-const x (_ BitVec 64))
(declare-const shift (_ BitVec 13))
(define-fun field () (_ BitVec 13) ((_ zero_extend 2) ((_ extract 62 52) x)))
(define-fun target () (_ BitVec 13) (bvadd field shift))
(assert (not (= field (_ bv0 13))))
(assert (not (= field (_ bv2047 13))))
; shift > -2 * 2047, the code's test before it forms the target; shift <= 0, as the
; field is at least 1 and the target at most 0 (no 13-bit sum wraps around)
(assert (bvsgt shift (bvneg (_ bv4094 13))))
(assert (bvsle shift (_ bv0 13)))
(assert (bvsle target (_ bv0 13)))
; from target -1100 up Wide holds x 2^shift exactly (its least normal is 2^-4094); below,
; x 2^shift is smaller still than at -1100 and rounds to the same zero
(assert (bvsge target (bvneg (_ bv1100 13))))
(define-fun exact () Wide (fp.mul RNE (widen ((_ to_fp 11 53) x)) (wide_power_of_two shift)))
(define-fun moved () Float64
  ((_ to_fp 11 53) (concat ((_ extract 63 63) x) ((_ extract 10 0) (bvadd target (_ bv54 13))) ((_ extract 51 0) x))))
(define-fun computed () Float64
  (ite (bvsle target (bvneg (_ bv53 13)))
       (ite (= ((_ extract 63 63) x) #b1) (_ -zero 11 53) (_ +zero 11 53))
       (fp.mul RNE moved (power_of_two (bvneg (_ bv54 13))))))
; goal
; the same binary64, zeros with their sign
(assert (not (= computed ((_ to_fp 11 53) RNE exact))))
