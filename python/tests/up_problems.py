"""Problems built in Python with Unified Planning's API, for the engine's tests and the
docs' example."""

from __future__ import annotations

from typing import Dict, List, Sequence, Tuple

from unified_planning.model import Fluent, InstantaneousAction, Object, Problem
from unified_planning.model.metrics import MinimizeActionCosts, MinimizeSequentialPlanLength
from unified_planning.shortcuts import BoolType, Equals, Not, UserType


def blocks(towers: Sequence[Sequence[str]], goal_towers: Sequence[Sequence[str]], name: str = "blocks") -> Problem:
    """Four-operator blocksworld; each tower is listed bottom first."""
    block = UserType("block")
    on = Fluent("on", BoolType(), x=block, y=block)
    ontable = Fluent("ontable", BoolType(), x=block)
    clear = Fluent("clear", BoolType(), x=block)
    holding = Fluent("holding", BoolType(), x=block)
    handempty = Fluent("handempty", BoolType())

    pick_up = InstantaneousAction("pick-up", x=block)
    x = pick_up.parameter("x")
    pick_up.add_precondition(clear(x))
    pick_up.add_precondition(ontable(x))
    pick_up.add_precondition(handempty())
    pick_up.add_effect(ontable(x), False)
    pick_up.add_effect(clear(x), False)
    pick_up.add_effect(handempty(), False)
    pick_up.add_effect(holding(x), True)

    put_down = InstantaneousAction("put-down", x=block)
    x = put_down.parameter("x")
    put_down.add_precondition(holding(x))
    put_down.add_effect(holding(x), False)
    put_down.add_effect(clear(x), True)
    put_down.add_effect(handempty(), True)
    put_down.add_effect(ontable(x), True)

    stack = InstantaneousAction("stack", x=block, y=block)
    x, y = stack.parameter("x"), stack.parameter("y")
    stack.add_precondition(holding(x))
    stack.add_precondition(clear(y))
    stack.add_effect(holding(x), False)
    stack.add_effect(clear(y), False)
    stack.add_effect(clear(x), True)
    stack.add_effect(handempty(), True)
    stack.add_effect(on(x, y), True)

    unstack = InstantaneousAction("unstack", x=block, y=block)
    x, y = unstack.parameter("x"), unstack.parameter("y")
    unstack.add_precondition(on(x, y))
    unstack.add_precondition(clear(x))
    unstack.add_precondition(handempty())
    unstack.add_effect(holding(x), True)
    unstack.add_effect(clear(y), True)
    unstack.add_effect(clear(x), False)
    unstack.add_effect(handempty(), False)
    unstack.add_effect(on(x, y), False)

    problem = Problem(name)
    for f in (on, ontable, clear, holding, handempty):
        problem.add_fluent(f, default_initial_value=False)
    for a in (pick_up, put_down, stack, unstack):
        problem.add_action(a)
    objects: Dict[str, Object] = {}
    for tower in towers:
        for b in tower:
            objects[b] = Object(b, block)
    problem.add_objects(objects.values())
    problem.set_initial_value(handempty(), True)
    for tower in towers:
        problem.set_initial_value(ontable(objects[tower[0]]), True)
        problem.set_initial_value(clear(objects[tower[-1]]), True)
        for below, above in zip(tower, tower[1:]):
            problem.set_initial_value(on(objects[above], objects[below]), True)
    for tower in goal_towers:
        for below, above in zip(tower, tower[1:]):
            problem.add_goal(on(objects[above], objects[below]))
    problem.add_quality_metric(MinimizeSequentialPlanLength())
    return problem


def cube_tower(tower: List[str], cubes: int = 4) -> Tuple[Problem, Dict[str, InstantaneousAction]]:
    """demoplan's cube domain (examples/cubes/domain.pddl: hands, cubes and a table,
    Reach, Take, Put and Stack, each of cost 1), with `cubes` cubes on the table and the
    goal `tower` (bottom first)."""
    thing = UserType("thing")
    hand = UserType("hand")
    cube = UserType("cube", thing)
    table_t = UserType("table", thing)
    acted_on = Fluent("acted-on", BoolType(), h=hand, t=thing)
    in_hand = Fluent("in-hand", BoolType(), h=hand, c=cube)
    on_top = Fluent("on-top", BoolType(), c=cube, t=thing)
    clear = Fluent("clear", BoolType(), t=thing)
    hand_free = Fluent("hand-free", BoolType(), h=hand)

    reach = InstantaneousAction("reach", h=hand, c=cube)
    h, c = reach.parameter("h"), reach.parameter("c")
    reach.add_precondition(hand_free(h))
    reach.add_precondition(clear(c))
    reach.add_precondition(Not(acted_on(h, c)))
    reach.add_effect(acted_on(h, c), True)

    take = InstantaneousAction("take", h=hand, c=cube, t=thing)
    h, c, t = take.parameter("h"), take.parameter("c"), take.parameter("t")
    take.add_precondition(acted_on(h, c))
    take.add_precondition(hand_free(h))
    take.add_precondition(on_top(c, t))
    take.add_precondition(clear(c))
    take.add_effect(in_hand(h, c), True)
    take.add_effect(clear(t), True)
    take.add_effect(hand_free(h), False)
    take.add_effect(acted_on(h, c), False)
    take.add_effect(on_top(c, t), False)

    put = InstantaneousAction("put", h=hand, c=cube, t=table_t)
    h, c, t = put.parameter("h"), put.parameter("c"), put.parameter("t")
    put.add_precondition(in_hand(h, c))
    put.add_effect(on_top(c, t), True)
    put.add_effect(hand_free(h), True)
    put.add_effect(in_hand(h, c), False)

    stack = InstantaneousAction("stack", h=hand, c=cube, d=cube)
    h, c, d = stack.parameter("h"), stack.parameter("c"), stack.parameter("d")
    stack.add_precondition(in_hand(h, c))
    stack.add_precondition(clear(d))
    stack.add_precondition(Not(Equals(c, d)))
    stack.add_effect(on_top(c, d), True)
    stack.add_effect(hand_free(h), True)
    stack.add_effect(clear(d), False)
    stack.add_effect(in_hand(h, c), False)

    problem = Problem("cube-tower")
    for f in (acted_on, in_hand, on_top, clear, hand_free):
        problem.add_fluent(f, default_initial_value=False)
    actions = {"reach": reach, "take": take, "put": put, "stack": stack}
    for a in actions.values():
        problem.add_action(a)
    hands = [Object("left", hand), Object("right", hand)]
    # UP wants one name per element: the type is `table`, its object `the-table`.
    table = Object("the-table", table_t)
    cube_objects = {f"c{i}": Object(f"c{i}", cube) for i in range(1, cubes + 1)}
    problem.add_objects(hands + [table] + list(cube_objects.values()))
    for hnd in hands:
        problem.set_initial_value(hand_free(hnd), True)
    problem.set_initial_value(clear(table), True)
    for obj in cube_objects.values():
        problem.set_initial_value(on_top(obj, table), True)
        problem.set_initial_value(clear(obj), True)
    for below, above in zip(tower, tower[1:]):
        problem.add_goal(on_top(cube_objects[above], cube_objects[below]))
    problem.add_quality_metric(MinimizeActionCosts({a: 1 for a in actions.values()}))
    return problem, actions
