"""fk and ik without the command line: a request in, a typed result out, notes included."""

from __future__ import annotations

import contextlib
import csv
import io
import itertools

import pytest

from servicebot_cli.batch import fk as fk_batch
from servicebot_cli.batch import ik as ik_batch
from servicebot_cli.common.errors import AnswerIsNo, OutOfLimits
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.kinematics import fk, ik
from servicebot_cli.kinematics.inverse import IkSettings
from servicebot_cli.output import ik_report
from tests.conftest import FIXTURES, SIM_URDF
from tests.kinematics.robots import PANDA

SIM = RobotSource.of(SIM_URDF)


class ListSink:
    """Result rows kept in a list, the way output.batch_rows.RowFile writes them to a file.

    Rows written as text (CSV a chunk at a time) are read back by csv, as cells of text.
    """

    delimiter = ","

    def __init__(self, kind="jsonl"):
        self.kind, self.rows, self.columns = kind, [], None

    @contextlib.contextmanager
    def open(self, columns):
        self.columns = list(columns)
        yield self

    def __call__(self, row):
        self.rows.append(row)

    def text(self, rows):
        self.rows.extend(csv.DictReader(io.StringIO(rows), fieldnames=self.columns))


def stepped_clock(step_s=0.25):
    """A clock that advances ``step_s`` each time it is read."""
    ticks = itertools.count()
    return lambda: next(ticks) * step_s


def test_fk_result_is_poses_and_notes():
    result = fk.run(fk.FkRequest(fk.FrameQuery(RobotSource.of(FIXTURES / "planar_2r.urdf"))))
    assert [p.frame for p in result.poses] == ["tip"] and result.relative_to == "base"
    assert result.notes == ("note: no --frame given; using 'tip', the tip of the longest "
                            "chain (2 joints)",)
    panda = fk.run(fk.FkRequest(fk.FrameQuery(RobotSource.of(PANDA)), (("panda_joint1", 0.1),)))
    assert panda.notes == ("note: panda_joint4 not given: 0, outside the limits (give "
                           "panda_joint4=VALUE for a reachable pose)",)


def test_fk_clamp_notes_each_joint_with_the_value_and_the_limit():
    query = fk.FrameQuery(SIM, deg=True, clamp=True)
    result = fk.run(fk.FkRequest(query, (("arm_link1_to_link2", 100.0),
                                         ("arm_link2_to_link3", -200.0),
                                         ("arm_base_to_link1", 10.0))))
    assert result.joints["arm_link1_to_link2"] == pytest.approx(89.9544, abs=1e-4)
    assert result.notes == (
        "note: --clamp: joint 'arm_link1_to_link2' = 100 deg is outside its limits; using "
        "its upper limit 89.9544 deg",
        "note: --clamp: joint 'arm_link2_to_link3' = -200 deg is outside its limits; using "
        "its lower limit -89.9544 deg",
    )
    with pytest.raises(OutOfLimits):
        fk.run(fk.FkRequest(fk.FrameQuery(SIM), (("arm_link1_to_link2", 2.0),)))


def test_ik_answer_with_an_injected_clock():
    problem = ik.IkProblem(SIM, seed=1, start=(("arm_link1_to_link2", 0.4),))
    answer = ik.run(ik.IkRequest(problem, ik.TargetSpec((0.5, 0.2, 0.4))), clock=stepped_clock())
    assert answer.success and answer.frame == "arm_tool_link" and answer.notes == ()
    assert answer.outcome.elapsed_s == 0.25  # one step of the clock: read before and after
    assert answer.outcome.result.position_error_m <= 1e-6


def test_ik_not_reached_is_a_result_and_its_refusal_says_why():
    problem = ik.IkProblem(SIM, seed=1, settings=IkSettings(max_attempts=3))
    answer = ik.run(ik.IkRequest(problem, ik.TargetSpec((4.0, 0.0, 0.0))), clock=stepped_clock())
    assert not answer.success and answer.outcome.hint.startswith("out of reach")
    assert ik_report.refusal(answer).startswith("no IK solution for arm_tool_link: best "
                                                "position error")
    assert issubclass(AnswerIsNo, Exception) and AnswerIsNo("").exit_code == 1


def test_ik_start_values_clamped_are_noted():
    problem = ik.IkProblem(SIM, start=(("arm_link1_to_link2", 3.0),), clamp=True, seed=0)
    session = ik.IkSession(problem, stepped_clock())
    assert session.notes == ("note: --clamp: joint 'arm_link1_to_link2' = 3 rad is outside its "
                             "limits; using its upper limit 1.57 rad",)


def test_fk_batch_streams_rows_to_the_sink_and_counts_clamps(tmp_path):
    configs = tmp_path / "configs.csv"
    configs.write_text("arm_link1_to_link2,arm_link2_to_link3\n0.1,0.2\n2,0\n3,-3\nx,0\n")
    sink, warnings = ListSink(), []
    request = fk_batch.FkBatchRequest(fk.FrameQuery(SIM, clamp=True), str(configs), "skip")
    summary = fk_batch.run(request, sink, warn=warnings.append)
    assert [row["line"] for row in sink.rows] == [2, 3, 4]
    assert summary.rows == 4 and summary.skipped == 1 and summary.source == str(configs)
    assert warnings[-1] == (f"note: --clamp moved 3 joint values onto a limit, on 2 of 4 "
                            f"lines of {configs}")


def test_ik_batch_summary_lists_the_lines_not_reached(tmp_path):
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m\n0.5,0.2,0.4\n4,0,0\n")
    sink = ListSink("csv")
    problem = ik.IkProblem(SIM, seed=0, settings=IkSettings(max_attempts=3))
    summary = ik_batch.run(ik_batch.IkBatchRequest(problem, str(targets)), sink,
                           warn=print, clock=stepped_clock())
    assert summary.failed == (3,)
    assert [str(row["success"]).lower() for row in sink.rows] == ["true", "false"]
    assert sink.columns[:2] == ["line", "success"]
    assert ik_report.batch_refusal(summary) == f"1 of 2 targets not reached (line 3 of {targets})"
