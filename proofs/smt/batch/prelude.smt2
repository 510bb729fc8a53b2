; Definitions shared by the batch kernel's obligations (included by "; include batch/prelude",
; after scaled/prelude).
;
; shifted_down_eight (batch.hpp) for a significand m and d < -1000: the stand-in for
; scaled<double>::shifted(m, d), 0 with m's sign where shifted rounds to 0, else 2^-1010
; with m's sign.
(define-fun rounds_to_zero ((m Float64) (d (_ BitVec 13))) Bool
  (or (bvsle d (bvneg (_ bv1075 13)))
      (and (= d (bvneg (_ bv1074 13))) (fp.eq (fp.abs m) ((_ to_fp 11 53) RNE 0.5)))))
(define-fun stand_in ((m Float64) (d (_ BitVec 13))) Float64
  (ite (rounds_to_zero m d)
       (ite (fp.isNegative m) (_ -zero 11 53) (_ +zero 11 53))
       (ite (fp.isNegative m) (fp.neg (power_of_two (bvneg (_ bv1010 13)))) (power_of_two (bvneg (_ bv1010 13))))))
