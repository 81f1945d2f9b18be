"""check's other inputs, hostile: settings files that are not text, empty controllers, devices.

Each is one line naming the file with exit 2, or a finding (exit 1) when it is the file
being checked; never a codec's message or an internal error.
"""

from __future__ import annotations

import codecs
import json
from pathlib import Path

import pytest

from tests.check.helpers import findings
from tests.conftest import ROBOTS, SIM_URDF, assert_one_line_error

SETTINGS = '[tool.servicebot.check]\n# r\u00e9glages\nstrict = true\n'


@pytest.mark.parametrize(("data", "says"), [
    (SETTINGS.encode("utf-16"), "UTF-16 text (it starts with a UTF-16 byte-order mark), not "
                                "UTF-8; save it as UTF-8"),
    (SETTINGS.encode("latin-1"), ":2:4: not UTF-8 text (byte 0xe9, '\u00e9' in Latin-1)"),
    (b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR", "a PNG image, not text; give a pyproject.toml"),
], ids=["utf16", "latin1", "png"])
def test_a_settings_file_that_is_not_text(run, tmp_path, data, says):
    config = tmp_path / "pyproject.toml"
    config.write_bytes(data)
    line = assert_one_line_error(run("check", "urdf", SIM_URDF, "--config", config), 2,
                                 str(config), says)
    assert "codec" not in line


def test_a_settings_file_with_a_utf8_byte_order_mark_is_read(run, tmp_path):
    config = tmp_path / "pyproject.toml"
    config.write_bytes(codecs.BOM_UTF8 + b'[tool.servicebot.check]\nignore = ["SB309"]\n')
    result = run("check", "urdf", SIM_URDF, "--config", config, "--format", "json")
    assert result.exit_code == 0
    assert "SB309" not in {f["code"] for f in findings(result.stdout)}


@pytest.mark.parametrize("device", [True, False])
def test_an_empty_controllers_file_is_one_finding_that_says_so(run, tmp_path, device):
    path = Path("/dev/null") if device else tmp_path / "empty.yaml"
    if not device:
        path.write_bytes(b"# only a comment\n")
    checked = run("check", "controllers", path, "--robot", "sim", "--format", "json")
    (finding,) = findings(checked.stdout)
    assert finding["code"] == "SB601"
    assert "holds no YAML (it is empty, or only comments)" in finding["message"]
    assert checked.exit_code == 1


def test_a_device_that_never_ends_is_read_to_a_limit(run):
    assert_one_line_error(run("check", "controllers", "/dev/zero"), 2,
                          "/dev/zero: holds more, over the 10 MB limit")
    assert_one_line_error(run("check", "urdf", SIM_URDF, "--config", "/dev/zero"), 2,
                          "/dev/zero: holds more, over the 10 MB limit")
    result = run("check", "urdf", "/dev/zero", "--format", "json")
    assert [f["code"] for f in findings(result.stdout)] == ["SB015"]


def test_a_file_that_is_no_controllers_yaml_is_one_finding_against_every_robot(run, tmp_path):
    # without --urdf the file is checked against both bundled robots; what is wrong with the
    # YAML itself is said once, not once per robot
    path = tmp_path / "controllers.yaml"
    path.write_text("# only a comment\n")
    checked = run("check", "controllers", path, "--format", "json")
    document = json.loads(checked.stdout)
    assert [f["code"] for f in findings(checked.stdout)] == ["SB601"]
    assert [file["file"] for file in document["files"]] == [str(path)]
    assert checked.exit_code == 1
    fine = run("check", "controllers", "--format", "json")  # the bundled file: both robots
    assert len(json.loads(fine.stdout)["files"]) == 2


def test_a_bad_item_of_one_controller_does_not_hide_the_other_robots(run, tmp_path):
    # SB601 also flags one controller's bad joints list: the file is still checked against
    # every robot named
    real = tmp_path / "real.urdf"
    real.write_text(SIM_URDF.read_text().replace('name="arm_link3_to_link4"',
                                                  'name="arm_wrist"'))
    yaml_text = (ROBOTS / "controllers.yaml").read_text()
    assert "arm_link3_to_link4" in yaml_text
    path = tmp_path / "controllers.yaml"
    path.write_text(yaml_text.replace("- arm_link3_to_link4",
                                      "- arm_link3_to_link4\n      - [oops]"))
    checked = run("check", "controllers", path, "--urdf", SIM_URDF, "--urdf", real,
                  "--format", "json")
    files = json.loads(checked.stdout)["files"]
    assert len(files) == 2
    against_real = [f["code"] for f in files[1]["findings"]]
    assert "SB601" in against_real and "SB602" in against_real
