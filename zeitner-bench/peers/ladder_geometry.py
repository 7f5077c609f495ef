"""The ladder of zeitner-bench/src/scaling/families.rs: its pinned span and sagging start, shared
by the peer scripts."""
import math

ANGLE = 0.3


def ladder_span(nodes):
    rods = nodes - 1
    level = 1.0 if rods % 2 == 1 else 0.0
    return (rods - level) * math.cos(ANGLE) + level


def sagging_ladder(nodes):
    """The bottom rail in a V (rods at -+ANGLE, a level rod in the middle when their number is
    odd), the top rail a rung above; node i's (bx, by, tx, ty) at 4i..4i+3."""
    rods = nodes - 1
    q = [0.0] * (4 * nodes)
    x = y = 0.0
    for i in range(nodes):
        q[4 * i: 4 * i + 4] = [x, y, x, y + 1.0]
        angle = -ANGLE if 2 * i + 1 < rods else (0.0 if 2 * i + 1 == rods else ANGLE)
        x += math.cos(angle)
        y += math.sin(angle)
    return q
