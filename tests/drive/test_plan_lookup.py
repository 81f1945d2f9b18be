"""A plan's setpoint at a time: the step under way, with every arm target given so far.

Looked up by the steps' end times (a 16,000-line script was rescanned from its start at
every tick); the answers are those of a scan from the start, which this test makes too.
"""

from __future__ import annotations

from servicebot_cli.drive.plan import Plan, Setpoint, Step

STEPS = [Step(1.0, 0.2, 0.0, (("a", 0.1),)), Step(0.0, 0.0, 0.0, (("b", 0.2),)),
         Step(2.0, 0.0, 0.5, (("a", 0.3),)), Step(0.5, -0.1, 0.0)]


def _scanned(steps: list[Step], t_s: float) -> Setpoint | None:
    start, arm = 0.0, {}
    for step in steps:
        arm.update(step.arm)
        if t_s < start + step.duration_s:
            return Setpoint(step.linear_m_s, step.angular_rad_s, tuple(arm.items()))
        start += step.duration_s
    return None


def test_every_time_gets_the_setpoint_a_scan_gives():
    plan = Plan(STEPS)
    times = [-1.0, 0.0, 0.5, 0.999, 1.0, 1.5, 2.999, 3.0, 3.25, 3.5, 4.0]
    times += [k * 0.125 for k in range(30)]
    for t_s in times:
        assert plan.setpoint(t_s) == _scanned(STEPS, t_s), t_s
    assert plan.setpoint(1.0) == Setpoint(0.0, 0.5, (("a", 0.3), ("b", 0.2)))
    assert plan.setpoint(3.5) is None and plan.duration_s == 3.5


def test_a_plan_without_steps_is_over_at_once():
    assert Plan([]).setpoint(0.0) is None
