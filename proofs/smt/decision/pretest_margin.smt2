; Claim: stays_in_contact's fma pre-test (plain path) decides (A.21) right whenever it
; decides at all. With
;   sum      = rnd(u + dy)
;   estimate = rnd(fma(-phi, dy, sum))            one rounding (std::fma)
;   margin   = 2^-50 * rnd(rnd(|u| + |dy|) + |rnd(phi dy)|)
; (4 * epsilon = 2^-50, and the product by it is exact in the window), the error of the
; estimate against E = u + dy - phi dy is at most the margin, so |estimate| > margin gives
; estimate > 0 exactly when E >= 0 (E /= 0 there). Each rounding is x (1 + d), |d| <= 2^-53:
; binary64 to nearest with no underflow or overflow, which inside the plain window
; gappa/window/*.g proves for these intermediates.
; expect: unsat
; show: u dy phi
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const d_sum Real)
(declare-const d_estimate Real)
(declare-const d_product Real)
(declare-const d_magnitudes Real)
(declare-const d_total Real)
(define-fun unit_roundoff () Real (/ 1.0 9007199254740992.0))
; 4 * std::numeric_limits<double>::epsilon() = 2^-50
(define-fun four_epsilon () Real (/ 1.0 1125899906842624.0))
(define-fun small ((d Real)) Bool (and (<= (- unit_roundoff) d) (<= d unit_roundoff)))
(define-fun absolute ((x Real)) Real (ite (>= x 0.0) x (- x)))
(assert (>= phi 0.0))
(assert (small d_sum))
(assert (small d_estimate))
(assert (small d_product))
(assert (small d_magnitudes))
(assert (small d_total))
(define-fun sum () Real (* (+ u dy) (+ 1.0 d_sum)))
(define-fun estimate () Real (* (- sum (* phi dy)) (+ 1.0 d_estimate)))
(define-fun product () Real (* phi dy (+ 1.0 d_product)))
(define-fun margin () Real
  (* four_epsilon
     (* (+ (* (+ (absolute u) (absolute dy)) (+ 1.0 d_magnitudes)) (absolute product)) (+ 1.0 d_total))))
(define-fun exact () Real (- (+ u dy) (* phi dy)))
; hints
(assert (<= (absolute (- sum (+ u dy))) (* unit_roundoff (+ (absolute u) (absolute dy)))))
(assert (<= (absolute (- estimate (- sum (* phi dy)))) (* unit_roundoff (absolute (- sum (* phi dy))))))
(assert (<= (absolute (- product (* phi dy))) (* unit_roundoff (absolute (* phi dy)))))

; then the error is a small multiple of the margin's sum
(assert (<= (absolute (- estimate exact)) (* 3.0 unit_roundoff (+ (absolute u) (absolute dy) (absolute (* phi dy))))))
(assert (>= margin (* four_epsilon (/ 1.0 2.0) (+ (absolute u) (absolute dy) (absolute (* phi dy))))))
; goal
(assert (not (and (<= (absolute (- estimate exact)) margin)
                  (=> (> (absolute estimate) margin) (= (> estimate 0.0) (>= exact 0.0))))))
(check-sat)
