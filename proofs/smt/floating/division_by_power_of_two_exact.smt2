; Claim: in binary64, dividing by a power of two 2^e is exact whenever the quotient lies
; in the normal range: (root - u) / 2 in stable_form::release and the halving of an odd
; exponent's significand in scaled<T>'s sqrt add no rounding error. Bit-precise binary64.
; expect: unsat
; show: x e
(set-logic QF_BVFP)
(declare-const x Float64)
(declare-const e (_ BitVec 11))
(define-fun p () Float64 (fp #b0 e #b0000000000000000000000000000000000000000000000000000))
(assert (fp.isNormal p))
(assert (fp.isNormal (fp.div RTZ x p)))
(assert (not (fp.isInfinite (fp.div RTP x p))))
(assert (not (fp.isInfinite (fp.div RTN x p))))
; goal
(assert (not (fp.eq (fp.div RTP x p) (fp.div RTN x p))))
(check-sat)
