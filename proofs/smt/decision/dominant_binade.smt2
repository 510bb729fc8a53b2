; Claim: sign_of_dominant_binade (stable.hpp), the scaled path's first test of (A.21),
; returns the sign of the exact sum u + dy - phi dy wherever it returns one.
; It knows each term only by its binade: 2^a <= |u| < 2^(a+1), 2^d <= dy < 2^(d+1),
; 2^p <= phi < 2^(p+1), so 2^(p+d) <= phi dy < 2^(p+d+2). A term decides when its least
; binade lies above both other terms' bounds (integers: lo > hi, i.e. 2^lo >= 2 2^hi).
; Pu, Pd, Pp stand for 2^a, 2^d, 2^p; u = 0 or phi = 0 is a term that is absent.
; Where none does, u + dy rounded to nearest decides: with 2^b = Pf its binade
; (max_exponent for an infinite sum), |u + dy| >= Pf (1 - eps), eps = 2^-prec (a
; rounding moves it by at most half an ulp, Pf eps; the overflow threshold lies
; Pf eps / 2 below 2^max_exponent), and fl(u + dy) has the sign of u + dy. It
; decides when b > p + d + 2 (phi dy's bound), or when phi = 0.
; The goal is the four branches' claims together: u decides with u's sign, dy with +,
; phi dy with -, u + dy with its own.
; expect: unsat
; show: u dy phi Pu Pd Pp Pf
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const Pu Real)
(declare-const Pd Real)
(declare-const Pp Real)
(declare-const Pf Real)
(declare-const eps Real)
(define-fun absolute ((x Real)) Real (ite (>= x 0.0) x (- x)))
(define-fun sum () Real (- (+ u dy) (* phi dy)))
(assert (and (> Pu 0.0) (> Pd 0.0) (> Pp 0.0)))
(assert (and (<= Pd dy) (< dy (* 2.0 Pd))))
(assert (or (= u 0.0) (and (<= Pu (absolute u)) (< (absolute u) (* 2.0 Pu)))))
(assert (or (= phi 0.0) (and (<= Pp phi) (< phi (* 2.0 Pp)))))
(assert (and (> Pf 0.0) (> eps 0.0) (<= eps 0.25)))
(assert (>= (absolute (+ u dy)) (* Pf (- 1.0 eps))))
; hints
(assert (or (= phi 0.0) (and (<= (* Pp Pd) (* phi dy)) (< (* phi dy) (* 4.0 Pp Pd)))))
; goal
(define-fun u_decides () Bool
  (and (not (= u 0.0)) (>= Pu (* 2.0 (* 2.0 Pd))) (or (= phi 0.0) (>= Pu (* 2.0 (* 4.0 Pp Pd))))))
(define-fun dy_decides () Bool
  (and (or (= u 0.0) (>= Pd (* 2.0 (* 2.0 Pu)))) (or (= phi 0.0) (>= Pd (* 2.0 (* 4.0 Pp Pd))))))
(define-fun product_decides () Bool
  (and (not (= phi 0.0)) (or (= u 0.0) (>= (* Pp Pd) (* 2.0 (* 2.0 Pu)))) (>= (* Pp Pd) (* 2.0 (* 2.0 Pd)))))
(define-fun sum_decides () Bool
  (or (= phi 0.0) (>= Pf (* 2.0 (* 4.0 Pp Pd)))))
(assert (not (and (=> u_decides (and (=> (> u 0.0) (> sum 0.0)) (=> (< u 0.0) (< sum 0.0))))
                  (=> dy_decides (> sum 0.0))
                  (=> product_decides (< sum 0.0))
                  (=> sum_decides (and (=> (> (+ u dy) 0.0) (> sum 0.0)) (=> (< (+ u dy) 0.0) (< sum 0.0)))))))
(check-sat)
