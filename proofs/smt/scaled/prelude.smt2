; Definitions shared by the scaled<T> obligations (included by "; include scaled/prelude").
;
; scaled<double> holds x = m 2^e with a binary64 significand m, 0.5 <= |m| < 1, and an
; integer exponent e. "Rounds as binary64 with an unbounded exponent" is checked against
; Wide, a format with binary64's 53-bit significand and a 13-bit exponent field: every
; value these obligations build lies between 2^-2200 and 2^2, far inside Wide's normal
; range (2^-4094 .. 2^4096), so Wide rounds there exactly as an unbounded exponent does.
; An operator's exponent part is integer arithmetic (exact), and rounding with an
; unbounded exponent commutes with multiplying by 2^k, so it is enough to show that each
; operator's binary64 operation on the significands gives Wide's result.
(define-sort Wide () (_ FloatingPoint 13 53))
(define-fun widen ((m Float64)) Wide ((_ to_fp 13 53) RNE m))
(define-fun significand ((m Float64)) Bool
  (and (fp.leq ((_ to_fp 11 53) RNE 0.5) (fp.abs m)) (fp.lt (fp.abs m) ((_ to_fp 11 53) RNE 1.0))))
; 2^e for e in [-1022, 1023] as a binary64, and for e in [-4094, 4095] in Wide
(define-fun power_of_two ((e (_ BitVec 13))) Float64
  (fp #b0 ((_ extract 10 0) (bvadd e (_ bv1023 13))) #b0000000000000000000000000000000000000000000000000000))
(define-fun wide_power_of_two ((e (_ BitVec 13))) Wide
  (fp #b0 (bvadd e (_ bv4095 13)) #b0000000000000000000000000000000000000000000000000000))
; scaled<double>::shifted(m, d) for d in [-2043, 0], as ldexp rounds it: m 2^d1 with
; d1 >= -1021 is exact, and the second factor rounds once (to a subnormal or to zero)
(define-fun first_step ((d (_ BitVec 13))) (_ BitVec 13)
  (ite (bvsge d (bvneg (_ bv1021 13))) d (bvneg (_ bv1021 13))))
(define-fun shifted ((m Float64) (d (_ BitVec 13))) Float64
  (fp.mul RNE (fp.mul RNE m (power_of_two (first_step d))) (power_of_two (bvsub d (first_step d)))))
