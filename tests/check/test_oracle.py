"""check_urdf as the oracle: every file it rejects, servicebot rejects; good robots pass.

The corpus is every URDF shipped by example-robot-data and pybullet_data, every fixture, and
the bundled robots. check_urdf accepts a link with two parents, prints a loop forever (a
timeout here) and ignores Gazebo, ros2_control and inertia, so servicebot finds more:
each example-robot-data file with an error is listed below with the defects it really has.
"""

from __future__ import annotations

import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import pytest

from servicebot_cli.check.env import CheckEnv
from servicebot_cli.check.findings import Severity
from servicebot_cli.check.runner import check_source
from servicebot_cli.check.settings import Settings
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.description.packages import PackageResolver
from tests.check.corpus import check_urdf_rejects, erd_root, erd_urdfs, pybullet_urdfs
from tests.check.helpers import FIXTURES
from tests.conftest import REAL_URDF, SIM_URDF

# Reviewed defects, by rule: SB209 mimic of a joint that is not there; SB308 CAD inertias that
# break the triangle inequality by 10-90 %; SB306 inertias with a negative principal moment;
# SB310 feet whose mass was rounded to 0 on export, keeping their inertia; SB401 meshes
# under /usr/Romeo; SB501 <gazebo reference> to links that were renamed; ur3.urdf holds an
# empty <robot>. (talos_left_arm also keeps a transmission for a joint cut from the reduced
# model: a warning, SB511, since no reader of transmissions is in the file.)
KNOWN_DEFECTS = {
    "alex_description/urdf/alex_psyonic_hands.urdf": {"SB209", "SB308"},
    "allegro_hand_description/urdf/allegro_left_hand.urdf": {"SB308"},
    "allegro_hand_description/urdf/allegro_right_hand.urdf": {"SB308"},
    "anymal_c_simple_description/urdf/anymal.urdf": {"SB308"},
    "pr2_description/urdf/pr2.urdf": {"SB308", "SB501"},
    "bolt_description/robots/bolt.urdf": {"SB310"},
    # head, l_ankle_2, l_wrist_1...: mass and no inertia on links joints move (MuJoCo:
    # 'inertia must have positive eigenvalues', checked on the file without its meshes)
    "icub_description/robots/icub.urdf": {"SB307"},
    "icub_description/robots/icub_reduced.urdf": {"SB307"},
    "romeo_description/urdf/romeo_laas_small.urdf": {"SB306", "SB308", "SB401"},
    "romeo_description/urdf/romeo_small.urdf": {"SB308"},
    "talos_data/robots/talos_left_arm.urdf": {"SB501"},
    "tiago_description/robots/tiago.urdf": {"SB306"},
    "tiago_description/robots/tiago_dual.urdf": {"SB306", "SB501"},
    "tiago_description/robots/tiago_no_hand.urdf": {"SB306"},
    "ur_description/urdf/ur3.urdf": {"SB009", "SB109"},
}


@pytest.fixture(scope="module")
def env():
    return CheckEnv(resolver=PackageResolver.from_environment({"example-robot-data": erd_root()}))


def _errors(path, env) -> set[str]:
    report = check_source(RobotSource.of(path), Settings(), env)
    return {f.code for f in report.findings if f.severity is Severity.ERROR}


def _fixture_urdfs(tmp_path) -> list:
    """Fixtures as plain URDF: xacro ones expanded (those xacro refuses are not URDF)."""
    found = []
    for path in sorted(FIXTURES.iterdir()):
        if path.suffix in (".urdf", ".xml"):
            found.append(path)
        elif path.suffix == ".xacro":
            out = tmp_path / (path.stem + ".urdf")
            result = subprocess.run([sys.executable, "-m", "servicebot_cli", "expand", str(path),
                                     "-o", str(out)],
                                    capture_output=True)
            if result.returncode == 0:
                found.append(out)
    return found


def test_every_fixture_check_urdf_rejects_is_rejected(env, tmp_path):
    paths = _fixture_urdfs(tmp_path)
    with ThreadPoolExecutor(4) as pool:  # the loop fixtures wait for their timeouts together
        verdicts = list(pool.map(check_urdf_rejects, paths))
    rejected = [p for p, rejects in zip(paths, verdicts, strict=True) if rejects]
    assert len(rejected) >= 20  # the oracle is really running
    missed = [p.name for p in rejected if not _errors(p, env)]
    assert not missed


def test_erd_corpus_agrees_with_check_urdf(env):
    files = erd_urdfs()
    assert len(files) >= 60
    for path in files:
        errors = _errors(path, env)
        if check_urdf_rejects(path):
            assert errors, f"check_urdf rejects {path}, servicebot does not"
        known = KNOWN_DEFECTS.get(str(path.relative_to(erd_root() / "robots")), set())
        assert errors == known, f"{path}: errors {errors}, reviewed defects {known}"


def test_pybullet_corpus_check_urdf_rejects_is_rejected(env):
    missed = [p for p in pybullet_urdfs() if check_urdf_rejects(p) and not _errors(p, env)]
    assert not missed


@pytest.mark.parametrize("path", [SIM_URDF, REAL_URDF])
def test_the_bundled_robots_pass_both(env, path):
    assert not check_urdf_rejects(path)
    assert not _errors(path, env)
