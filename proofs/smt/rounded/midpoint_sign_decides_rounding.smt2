; Claim: the sign of R at the midpoint m = (lo + hi) / 2 of neighbours lo < hi
; decides the rounding of the root s of (A.2) (walk_to_rounded_root,
; residual_sign_between): R(m) < 0 puts s above m, nearer hi than lo; R(m) > 0
; below m, nearer lo; R(m) = 0 makes s = m, equally near both, a tie (which
; even_of gives to the even neighbour). From residual_increasing and
; residual_is_a2: R is strictly increasing and vanishes exactly at the root.
; expect: unsat
; show: u dy phi lo hi s
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const lo Real)
(declare-const hi Real)
(declare-const m Real)
(declare-const s Real)
(declare-const qm Real)
(declare-const qs Real)
; include prelude
(assert (>= phi 0.0))
(assert (< lo hi))
(assert (= m (/ (+ lo hi) 2.0)))
(assert (solves u dy phi s))
; qm, qs name the difference quotients; every point has one
(assert (quotient_is dy m qm))
(assert (quotient_is dy s qs))
; hints
; lemma derivation/residual_is_a2 s:=s q:=qs
; lemma derivation/residual_increasing s1:=m s2:=s q1:=qm q2:=qs
; lemma derivation/residual_increasing s1:=s s2:=m q1:=qs q2:=qm
(assert (= (+ s u (* phi qs)) 0.0))
; goal
(assert (not (and (=> (< (+ m u (* phi qm)) 0.0) (and (> s m) (< (- hi s) (- s lo))))
                  (=> (> (+ m u (* phi qm)) 0.0) (and (< s m) (< (- s lo) (- hi s))))
                  (=> (= (+ m u (* phi qm)) 0.0) (and (= s m) (= (- s lo) (- hi s)))))))
(check-sat)
