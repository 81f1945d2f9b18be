"""Never a command beyond a limit, whatever the input: properties over every encoder."""

from __future__ import annotations

import dataclasses
import math

from hypothesis import given, settings
from hypothesis import strategies as st

from servicebot_cli.drive.emulator.arduino_firmware import ArduinoFirmware
from servicebot_cli.drive.emulator.firmware import MotorModel
from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.arduino import ArduinoConfig, ArduinoLink
from servicebot_cli.drive.protocols.binary import BinaryLink
from servicebot_cli.drive.protocols.framing import Decoder
from servicebot_cli.drive.shaping import WheelShaper

ANY_FLOAT = st.floats(allow_nan=True, allow_infinity=True)
FOUR = st.lists(ANY_FLOAT, min_size=4, max_size=4)
LIMIT = st.floats(0.001, 30.0)


def limited(motors, wheel_limit, arm_low, arm_span):
    return dataclasses.replace(
        motors, wheel_max_rad_s=(wheel_limit,) * 4,
        arm_lower=(arm_low,) * 4, arm_upper=(min(arm_low + arm_span, 32.0),) * 4)


def test_the_limits_come_from_the_urdf(real_motors):
    assert real_motors.wheel_max_rad_s == (0.5,) * 4
    assert real_motors.arm_lower == (-1.57,) * 4 and real_motors.arm_upper == (1.57,) * 4
    assert (real_motors.wheel_radius_m, real_motors.track_m) == (0.07, 0.54)


@settings(max_examples=500, deadline=None)
@given(FOUR, FOUR)
def test_nothing_encodable_exceeds_the_real_robots_limits(real_motors, wheels, arm):
    check_binary(real_motors, wheels, arm)


@settings(max_examples=500, deadline=None)
@given(FOUR, FOUR, LIMIT, st.floats(-31.0, 0.0), st.floats(0.002, 30.0))
def test_nothing_encodable_exceeds_any_limits(real_motors, wheels, arm, wheel_limit, low, span):
    check_binary(limited(real_motors, wheel_limit, low, span), wheels, arm)


def check_binary(motors, wheels, arm):
    link = BinaryLink(motors)
    for data in (link.wheels(wheels)[0], link.arm(arm)[0]):
        (frame,) = Decoder().feed(data)
        values = msg.decode_values(frame)
        if frame.type == msg.MsgType.SET_WHEELS:
            assert all(abs(v) <= lim for v, lim in zip(values, motors.wheel_max_rad_s, strict=True))
            assert all(abs(v) <= abs(w) for v, w in zip(values, wheels, strict=True)
                       if not math.isnan(w))  # never faster than asked
        else:
            assert all(lo <= v <= hi for v, lo, hi in
                       zip(values, motors.arm_lower, motors.arm_upper, strict=True))


@settings(max_examples=300, deadline=None)
@given(FOUR, st.floats(1.0, 100000.0), st.floats(1.0, 1000.0))
def test_arduino_ticks_never_exceed_the_limit(real_motors, wheels, ticks_per_rev, pid_rate):
    config = ArduinoConfig(ticks_per_rev, pid_rate)
    link = ArduinoLink(real_motors, config)
    left, right = link.side_ticks(wheels)
    for ticks in (left, right):
        assert abs(config.speed_rad_s(ticks)) <= real_motors.max_wheel_rad_s
    # and the firmware side agrees: whatever arrives, the emulated wheels stay within limits
    model = MotorModel(real_motors, 0.5)
    ArduinoFirmware(model, config, 9600).receive(link.wheels(wheels)[0], 0.1)
    assert all(abs(v) <= 0.5 for v in model.wheel_velocity_rad_s)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(ANY_FLOAT, ANY_FLOAT, st.floats(0.0, 1.0)), min_size=1, max_size=30))
def test_shaped_wheel_speeds_stay_within_speed_and_acceleration_limits(real_motors, twists):
    accel = 1.0
    shaper = WheelShaper(real_motors, accel)
    previous = (0.0,) * 4
    for linear, angular, dt in twists:
        speeds = shaper.step(linear, angular, dt)
        assert all(abs(v) <= 0.5 for v in speeds)
        assert all(abs(v - p) <= accel * dt + 1e-12 for v, p in zip(speeds, previous, strict=True))
        previous = speeds


@settings(max_examples=200, deadline=None)
@given(st.floats(-10, 10), st.floats(-10, 10))
def test_saturation_keeps_the_curvature(real_motors, linear, angular):
    shaper = WheelShaper(real_motors, 1.0)
    wanted = shaper.unlimited(linear, angular)
    got = shaper.target(linear, angular)
    assert max(abs(got[0]), abs(got[1])) <= 0.5 + 1e-12
    assert math.isclose(wanted[0] * got[1], wanted[1] * got[0], rel_tol=1e-9, abs_tol=1e-12)


def test_the_ramp_reaches_the_target_with_both_sides_together(real_motors):
    shaper = WheelShaper(real_motors, 1.0)
    history = [shaper.step(0.02, 0.05, 0.05) for _ in range(40)]
    target = shaper.target(0.02, 0.05)
    left, right = history[-1][0], history[-1][1]
    assert math.isclose(left, target[0]) and math.isclose(right, target[1])
    for speeds in history:  # the ratio of the sides is the target's all along
        assert math.isclose(speeds[0] * target[1], speeds[1] * target[0], abs_tol=1e-12)


def test_the_emulated_firmware_clamps_and_flags_limit(real_motors):
    from servicebot_cli.drive.emulator.firmware import BinaryFirmware
    from servicebot_cli.drive.protocols.framing import Frame, encode_frame

    model = MotorModel(real_motors, 0.5)
    firmware = BinaryFirmware(model)
    import struct

    too_fast = Frame(1, msg.MsgType.SET_WHEELS, struct.pack("<4h", 900, -900, 100, 0))
    reply = Decoder().feed(firmware.receive(encode_frame(too_fast), 0.0))[0]
    assert model.wheel_velocity_rad_s == [0.5, -0.5, 0.1, 0.0]
    assert msg.Fault.LIMIT in msg.decode_telemetry(reply).faults
