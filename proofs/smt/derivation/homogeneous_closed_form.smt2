; Claim: the corrected closed form is homogeneous of degree one in (s, u, dy): for k > 0
; every case criterion is unchanged by (u, dy) -> (k u, k dy), and every formula (its
; square root included) is multiplied by k. This is what lets the stable algorithm and the
; Gappa proofs rescale by powers of two.
; expect: unsat
; show: u dy phi k r1 r2
(set-logic QF_NRA)
(declare-const u Real)
(declare-const dy Real)
(declare-const phi Real)
(declare-const k Real)
(declare-const r1 Real)
(declare-const r2 Real)
; include prelude
(assert (>= phi 0.0))
(assert (> k 0.0))
(assert (is_sqrt r1 (impact_disc u dy phi)))
(assert (is_sqrt r2 (release_disc u dy phi)))
; hints
(assert (= (free_case (* k u) (* k dy) phi) (free_case u dy phi)))

(assert (= (impact_case (* k u) (* k dy) phi) (impact_case u dy phi)))

(assert (= (contact_case (* k u) (* k dy) phi) (contact_case u dy phi)))

(assert (= (release_case (* k u) (* k dy) phi) (release_case u dy phi)))

(assert (= (* k k r1 r1) (* k k (impact_disc u dy phi))))

(assert (= (* k k r2 r2) (* k k (release_disc u dy phi))))
; goal
(assert (not (and (= (free_case (* k u) (* k dy) phi) (free_case u dy phi))
                  (= (impact_case (* k u) (* k dy) phi) (impact_case u dy phi))
                  (= (contact_case (* k u) (* k dy) phi) (contact_case u dy phi))
                  (= (release_case (* k u) (* k dy) phi) (release_case u dy phi))
                  (= (free_num (* k u)) (* k (free_num u)))
                  (is_sqrt (* k r1) (impact_disc (* k u) (* k dy) phi))
                  (= (impact_num (* k u) (* k dy) phi (* k r1)) (* k (impact_num u dy phi r1)))
                  (= (contact_num (* k u) (* k dy) phi) (* k (contact_num u dy phi)))
                  (is_sqrt (* k r2) (release_disc (* k u) (* k dy) phi))
                  (= (release_num (* k u) (* k r2)) (* k (release_num u r2))))))
(check-sat)
