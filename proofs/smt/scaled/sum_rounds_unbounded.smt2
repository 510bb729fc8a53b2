; Claim: scaled<double>'s sum rounds as binary64 with an unbounded exponent, whatever the
; two exponents. With a.exponent >= b.exponent (the other order is the same sum) it is
; normalized(a.significand + shifted(b.significand, d), a.exponent), d = b.exponent -
; a.exponent <= 0, and shifted is ldexp, which rounds when b's significand falls below
; binary64's normal range. The claim covers d from 0 down to -2043; below that shifted
; gives 0 and the code's sum is a.significand, as at d = -2043, and so is the exact sum
; rounded, since |b| is then below 2^-2043 |a|, nowhere near half an ulp of a. So the
; flushed term never changes the rounding (a sum of a significand and anything below
; 2^-1022 rounds to that significand). Bit-precise; cvc5 with --fp-exp, about 90 s.
;
; The signs of scaled<T>'s > and == are those of this sum (a - b is a + (-b)); a sum
; rounded to nearest in Wide is zero only when it is exactly zero (the sums here are
; multiples of 2^-2096, far above Wide's least subnormal) and otherwise keeps its sign.
; expect: unsat
; solvers: cvc5
; cvc5-options: --fp-exp
; include scaled/prelude
(declare-const a Float64)
(declare-const b Float64)
(declare-const d (_ BitVec 13))
(assert (significand a))
(assert (significand b))
(assert (bvsle d (_ bv0 13)))
(assert (bvsge d (bvneg (_ bv2043 13))))
; goal
(assert (not (fp.eq (widen (fp.add RNE a (shifted b d)))
                    (fp.add RNE (widen a) (fp.mul RNE (widen b) (wide_power_of_two d))))))
