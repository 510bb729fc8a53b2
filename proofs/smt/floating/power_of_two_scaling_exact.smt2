; Claim: in binary64, multiplying by a power of two 2^e is exact whenever the product lies
; in the normal range (rounded toward zero it is normal) and does not overflow: rounding
; it up and rounding it down give the same double. This is what makes the rescaling of the
; stable algorithm (ldexp / scaled<T>, multiplications and divisions by 2 and 4 in the
; formulas) exact. Bit-precise: IEEE 754 binary64 (Float64).
; expect: unsat
; show: x e
(set-logic QF_BVFP)
(declare-const x Float64)
(declare-const e (_ BitVec 11))
; p = 2^(e - 1023): sign 0, biased exponent e, significand 0, a positive normal power of two
(define-fun p () Float64 (fp #b0 e #b0000000000000000000000000000000000000000000000000000))
(assert (fp.isNormal p))
(assert (fp.isNormal (fp.mul RTZ x p)))
(assert (not (fp.isInfinite (fp.mul RTP x p))))
(assert (not (fp.isInfinite (fp.mul RTN x p))))
; goal
(assert (not (fp.eq (fp.mul RTP x p) (fp.mul RTN x p))))
(check-sat)
