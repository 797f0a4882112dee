; Luminous-Sim planning domain: ALFRED's put_task (gen/planner/domains/PutTaskExtended_domain.pddl)
; extended with movable receptacles, slicing, heating, cooling, cleaning and toggling as the
; simulator's rules (luminous_sim/states/rules.py) define them, with ALFRED's action costs.
; Problems come from luminous_sim.planning.symbolic.problem.to_pddl_problem.
;
; Differences from ALFRED's domain, on purpose:
; * ALFRED's `object` type is called `item` (PDDL reserves `object` as the root type); `thing` is
;   the common parent of static receptacles and items, so predicates take either.
; * Containment follows AI2-THOR's parentReceptacles: (inReceptacle o r) for the first fixed
;   receptacle above o, (inReceptacleObject o m) for each movable receptacle between them.
; * GotoLocation does not require every receptacle closed (the simulator does not either; a goal
;   may ask for them closed).
; * Heat/Cool/Clean are the simulator's macros: the device ends closed and off, everything inside
;   it (and inside the held object) is heated/cooled/washed, as the rules do.
; * Slicing replaces an object by pre-declared slices: the problem lists them `removed` until the
;   SliceObject that creates them, and the whole becomes `removed`.
; * `gating` marks ALFRED's OPENABLE_CLASS_LIST (Fridge, Cabinet, Microwave, Drawer, Safe, Box):
;   while closed, nothing inside is reachable; other openables (Laptop, Toilet) open but gate nothing.

(define (domain luminous)
  (:requirements :adl :typing :action-costs)
  (:types
    agent location rtype otype thing - object
    receptacle item - thing)
  (:constants
    MicrowaveType FridgeType SinkBasinType BathtubBasinType - rtype
    KnifeType ButterKnifeType - otype)
  (:predicates
    (atLocation ?a - agent ?l - location)
    (receptacleAtLocation ?r - thing ?l - location)
    (objectAtLocation ?o - thing ?l - location)
    (receptacleType ?r - thing ?t - rtype)
    (objectType ?o - thing ?t - otype)
    (canContain ?rt - rtype ?ot - otype)
    (canContainObject ?mt - otype ?ot - otype)
    (inReceptacle ?o - thing ?r - thing)
    (inReceptacleObject ?o - thing ?m - thing)
    (isReceptacleObject ?o - thing)
    (holds ?a - agent ?o - thing)
    (holdsAny ?a - agent)
    (pickupable ?o - thing)
    (openable ?t - thing)
    (gating ?t - thing)
    (opened ?t - thing)
    (toggleable ?t - thing)
    (isToggled ?t - thing)
    (sliceable ?o - thing)
    (isSliced ?o - thing)
    (fillable ?o - thing)
    (isFilled ?o - thing)
    (isDirty ?o - thing)
    (isHot ?o - thing)
    (isCool ?o - thing)
    (isClean ?o - thing)
    (faucetFor ?f - thing ?r - thing)
    (sliceOf ?s - thing ?o - thing)
    (removed ?o - thing))
  (:functions (total-cost) - number)

  (:action GotoLocation
    :parameters (?a - agent ?lStart - location ?lEnd - location)
    :precondition (and (atLocation ?a ?lStart) (not (= ?lStart ?lEnd)))
    :effect (and (not (atLocation ?a ?lStart)) (atLocation ?a ?lEnd) (increase (total-cost) 1)))

  (:action OpenObject
    :parameters (?a - agent ?l - location ?r - thing)
    :precondition (and (atLocation ?a ?l) (or (receptacleAtLocation ?r ?l) (objectAtLocation ?r ?l))
                       (openable ?r) (not (opened ?r))
                       (forall (?c - thing) (imply (and (or (inReceptacle ?r ?c) (inReceptacleObject ?r ?c)) (gating ?c)) (opened ?c))))
    :effect (and (opened ?r)
                 (when (receptacleType ?r MicrowaveType) (not (isToggled ?r)))
                 (increase (total-cost) 1)))

  (:action CloseObject
    :parameters (?a - agent ?l - location ?r - thing)
    :precondition (and (atLocation ?a ?l) (or (receptacleAtLocation ?r ?l) (objectAtLocation ?r ?l))
                       (openable ?r) (opened ?r))
    :effect (and (not (opened ?r))
                 (forall (?x - item) (when (and (receptacleType ?r FridgeType) (inReceptacle ?x ?r)) (isCool ?x)))
                 (increase (total-cost) 1)))

  (:action PickupObject
    :parameters (?a - agent ?l - location ?o - item)
    :precondition (and (atLocation ?a ?l) (objectAtLocation ?o ?l) (pickupable ?o) (not (holdsAny ?a))
                       (forall (?c - thing) (imply (and (or (inReceptacle ?o ?c) (inReceptacleObject ?o ?c)) (gating ?c)) (opened ?c))))
    :effect (and (holds ?a ?o) (holdsAny ?a) (not (objectAtLocation ?o ?l))
                 (forall (?c - thing) (and (not (inReceptacle ?o ?c)) (not (inReceptacleObject ?o ?c))))
                 (forall (?x - item) (when (inReceptacleObject ?x ?o) (not (objectAtLocation ?x ?l))))
                 (forall (?x - item ?c - thing)
                   (when (and (inReceptacleObject ?x ?o) (or (inReceptacle ?x ?c) (inReceptacleObject ?o ?c)))
                         (and (not (inReceptacle ?x ?c)) (not (inReceptacleObject ?x ?c)))))
                 (increase (total-cost) 1)))

  (:action PutObject
    :parameters (?a - agent ?l - location ?o - item ?r - receptacle)
    :precondition (and (atLocation ?a ?l) (receptacleAtLocation ?r ?l) (holds ?a ?o)
                       (or (not (gating ?r)) (opened ?r))
                       (exists (?ot - otype ?rt - rtype) (and (objectType ?o ?ot) (receptacleType ?r ?rt) (canContain ?rt ?ot))))
    :effect (and (not (holds ?a ?o)) (not (holdsAny ?a)) (inReceptacle ?o ?r) (objectAtLocation ?o ?l)
                 (forall (?x - item) (when (inReceptacleObject ?x ?o) (and (inReceptacle ?x ?r) (objectAtLocation ?x ?l))))
                 (increase (total-cost) 1)))

  (:action PutObjectInReceptacleObject
    :parameters (?a - agent ?l - location ?o - item ?m - item)
    :precondition (and (atLocation ?a ?l) (objectAtLocation ?m ?l) (isReceptacleObject ?m) (holds ?a ?o)
                       (not (= ?o ?m)) (or (not (gating ?m)) (opened ?m))
                       (forall (?c - thing) (imply (and (or (inReceptacle ?m ?c) (inReceptacleObject ?m ?c)) (gating ?c)) (opened ?c)))
                       (exists (?ot - otype ?mt - otype) (and (objectType ?o ?ot) (objectType ?m ?mt) (canContainObject ?mt ?ot))))
    :effect (and (not (holds ?a ?o)) (not (holdsAny ?a)) (inReceptacleObject ?o ?m) (objectAtLocation ?o ?l)
                 (forall (?c - thing) (when (inReceptacle ?m ?c) (inReceptacle ?o ?c)))
                 (forall (?c - thing) (when (inReceptacleObject ?m ?c) (inReceptacleObject ?o ?c)))
                 (forall (?x - item) (when (inReceptacleObject ?x ?o) (and (inReceptacleObject ?x ?m) (objectAtLocation ?x ?l))))
                 (forall (?x - item ?c - thing)
                   (when (and (inReceptacleObject ?x ?o) (inReceptacle ?m ?c)) (inReceptacle ?x ?c)))
                 (forall (?x - item ?c - thing)
                   (when (and (inReceptacleObject ?x ?o) (inReceptacleObject ?m ?c)) (inReceptacleObject ?x ?c)))
                 (increase (total-cost) 1)))

  (:action HeatObject
    :parameters (?a - agent ?l - location ?r - receptacle ?o - item)
    :precondition (and (receptacleType ?r MicrowaveType) (atLocation ?a ?l) (receptacleAtLocation ?r ?l) (holds ?a ?o)
                       (exists (?ot - otype) (and (objectType ?o ?ot) (canContain MicrowaveType ?ot))))
    :effect (and (isHot ?o) (not (opened ?r)) (not (isToggled ?r))
                 (forall (?x - item) (when (or (inReceptacleObject ?x ?o) (inReceptacle ?x ?r)) (isHot ?x)))
                 (increase (total-cost) 5)))

  (:action CoolObject
    :parameters (?a - agent ?l - location ?r - receptacle ?o - item)
    :precondition (and (receptacleType ?r FridgeType) (atLocation ?a ?l) (receptacleAtLocation ?r ?l) (holds ?a ?o)
                       (exists (?ot - otype) (and (objectType ?o ?ot) (canContain FridgeType ?ot))))
    :effect (and (isCool ?o) (not (opened ?r))
                 (forall (?x - item) (when (or (inReceptacleObject ?x ?o) (inReceptacle ?x ?r)) (isCool ?x)))
                 (increase (total-cost) 5)))

  (:action CleanObject
    :parameters (?a - agent ?l - location ?r - receptacle ?o - item ?f - item)
    :precondition (and (faucetFor ?f ?r) (atLocation ?a ?l) (receptacleAtLocation ?r ?l) (holds ?a ?o)
                       (exists (?ot - otype ?rt - rtype) (and (objectType ?o ?ot) (receptacleType ?r ?rt) (canContain ?rt ?ot))))
    :effect (and (not (isToggled ?f))
                 (forall (?x - item)
                   (when (or (= ?x ?o) (inReceptacleObject ?x ?o) (inReceptacle ?x ?r))
                         (and (isClean ?x) (not (isDirty ?x)))))
                 (forall (?x - item)
                   (when (and (fillable ?x) (or (= ?x ?o) (inReceptacleObject ?x ?o) (inReceptacle ?x ?r)))
                         (isFilled ?x)))
                 (increase (total-cost) 5)))

  (:action ToggleObjectOn
    :parameters (?a - agent ?l - location ?o - thing)
    :precondition (and (atLocation ?a ?l) (or (receptacleAtLocation ?o ?l) (objectAtLocation ?o ?l))
                       (toggleable ?o) (not (isToggled ?o))
                       (or (not (receptacleType ?o MicrowaveType)) (not (opened ?o))))
    :effect (and (isToggled ?o)
                 (forall (?x - item) (when (and (receptacleType ?o MicrowaveType) (inReceptacle ?x ?o)) (isHot ?x)))
                 (forall (?x - item ?r - thing)
                   (when (and (faucetFor ?o ?r) (inReceptacle ?x ?r)) (and (isClean ?x) (not (isDirty ?x)))))
                 (forall (?x - item ?r - thing)
                   (when (and (faucetFor ?o ?r) (inReceptacle ?x ?r) (fillable ?x)) (isFilled ?x)))
                 (increase (total-cost) 5)))

  (:action ToggleObjectOff
    :parameters (?a - agent ?l - location ?o - thing)
    :precondition (and (atLocation ?a ?l) (or (receptacleAtLocation ?o ?l) (objectAtLocation ?o ?l))
                       (toggleable ?o) (isToggled ?o))
    :effect (and (not (isToggled ?o)) (increase (total-cost) 5)))

  (:action SliceObject
    :parameters (?a - agent ?l - location ?o - item ?k - item)
    :precondition (and (atLocation ?a ?l) (objectAtLocation ?o ?l) (sliceable ?o) (not (isSliced ?o)) (holds ?a ?k)
                       (or (objectType ?k KnifeType) (objectType ?k ButterKnifeType))
                       (forall (?c - thing) (imply (and (or (inReceptacle ?o ?c) (inReceptacleObject ?o ?c)) (gating ?c)) (opened ?c))))
    :effect (and (isSliced ?o) (removed ?o) (not (objectAtLocation ?o ?l))
                 (forall (?s - item)
                   (when (sliceOf ?s ?o) (and (not (removed ?s)) (objectAtLocation ?s ?l) (isSliced ?s))))
                 (forall (?s - item) (when (and (sliceOf ?s ?o) (isHot ?o)) (isHot ?s)))
                 (forall (?s - item) (when (and (sliceOf ?s ?o) (isCool ?o)) (isCool ?s)))
                 (forall (?s - item ?c - thing)
                   (when (and (sliceOf ?s ?o) (inReceptacle ?o ?c)) (inReceptacle ?s ?c)))
                 (forall (?s - item ?c - thing)
                   (when (and (sliceOf ?s ?o) (inReceptacleObject ?o ?c)) (inReceptacleObject ?s ?c)))
                 (forall (?c - thing) (and (not (inReceptacle ?o ?c)) (not (inReceptacleObject ?o ?c))))
                 (increase (total-cost) 5)))
)
