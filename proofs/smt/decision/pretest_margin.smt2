; Claim: the fma pre-test of (A.21) (detail::contact_estimate, run by stays_in_contact and
; both batch kernels) decides right whenever it decides at all. With
;   sum      = rnd(u + dy)
;   estimate = rnd(fma(-phi, dy, sum))            one rounding (std::fma)
;   margin   = rnd(2^-52 |sum|)                   (epsilon = 2^-52)
; |estimate| > margin gives estimate > 0 exactly when E = u + dy - phi dy >= 0 (E /= 0
; there). Why: rounding keeps the sign, so the estimate has the sign of the fma's exact
; value sum - phi dy, which differs from E by sum's rounding error alone, at most
; 2^-53 |sum|, less than the margin.
; Units: 2^emin = 1 (the claim is about ratios, and the underflow threshold is the one
; scale it has). In the window and the phi bands gappa/window/pretest.g.in proves that
; u + dy and the fma's exact value are multiples of 2^emin and that nothing overflows:
; such a number rounds with a relative error of at most 2^-53, and exactly below
; 2^(emin + 53). The margin's product may underflow: it is exact from 2^emin up, and
; within half the least subnormal, 2^(emin - 53), below; there |sum| < 2^(emin + 53)
; is exact, and the estimate has E's own sign.
; expect: unsat
; show: u dy phi d_sum d_estimate underflow
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const d_sum Real)
(declare-const d_estimate Real)
(declare-const underflow Real)
(define-fun unit_roundoff () Real (/ 1.0 9007199254740992.0))                 ; 2^-53
(define-fun epsilon () Real (/ 1.0 4503599627370496.0))                       ; 2^-52
(define-fun exact_below () Real 9007199254740992.0)                           ; 2^53 = 2^(emin + 53)
(define-fun half_least_subnormal () Real (/ 1.0 9007199254740992.0))          ; 2^(emin - 53)
(define-fun small ((d Real)) Bool (and (<= (- unit_roundoff) d) (<= d unit_roundoff)))
(define-fun absolute ((x Real)) Real (ite (>= x 0.0) x (- x)))
(assert (small d_sum))
(assert (small d_estimate))
(define-fun sum_exact () Real (+ u dy))
(define-fun sum () Real (* sum_exact (+ 1.0 d_sum)))
(define-fun estimate_exact () Real (- sum (* phi dy)))
(define-fun estimate () Real (* estimate_exact (+ 1.0 d_estimate)))
(define-fun margin_exact () Real (* epsilon (absolute sum)))
(define-fun margin () Real (+ margin_exact underflow))
; multiples of 2^emin round exactly below 2^(emin + 53)
(assert (=> (< (absolute sum_exact) exact_below) (= d_sum 0.0)))
(assert (=> (< (absolute estimate_exact) exact_below) (= d_estimate 0.0)))
; the margin's one product: exact from 2^emin up, else within half the least subnormal, never negative
(assert (=> (>= margin_exact 1.0) (= underflow 0.0)))
(assert (<= (absolute underflow) half_least_subnormal))
(assert (>= margin 0.0))
(define-fun exact () Real (- (+ u dy) (* phi dy)))
; hints
(assert (<= (absolute (- sum sum_exact)) (* unit_roundoff (absolute sum_exact))))
(assert (<= (absolute sum_exact) (* (+ 1.0 (* 2.0 unit_roundoff)) (absolute sum))))
(assert (<= (absolute estimate) (* (+ 1.0 unit_roundoff) (absolute estimate_exact))))
(assert (= (- estimate_exact exact) (- sum sum_exact)))

; then sum's error is about half the margin, or sum is exact
(assert (=> (>= margin_exact 1.0) (<= (absolute (- sum sum_exact)) (* (/ 1.0 2.0) (+ 1.0 (* 2.0 unit_roundoff)) margin))))
(assert (=> (< margin_exact 1.0) (= sum sum_exact)))

; then the estimate has the sign of its exact value
(assert (= (> estimate 0.0) (> estimate_exact 0.0)))
(assert (= (< estimate 0.0) (< estimate_exact 0.0)))
; goal
(assert (not (=> (> (absolute estimate) margin) (= (> estimate 0.0) (>= exact 0.0)))))
(check-sat)
