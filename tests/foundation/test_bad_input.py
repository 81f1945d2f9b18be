"""Bad input, for every command: one line on stderr naming the file, exit 2, no traceback."""

from __future__ import annotations

import stat
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from servicebot_cli.common.errors import UnsafeXmlError, XmlError
from servicebot_cli.description.safe_xml import parse_xml
from tests.check.helpers import findings
from tests.conftest import SIM_URDF, XACRO_SOURCE, assert_one_line_error, run_servicebot

COMMANDS = ["check", "inspect", "fk", "ik", "simulate", "drive", "emulate", "expand"]
# check reports a malformed file as a finding (exit 1); every other command refuses it (exit 2)
LOADING_COMMANDS = ["inspect", "fk", "ik", "simulate", "drive", "emulate", "expand"]
# what a command needs besides the robot before it has work to do
NEEDS = {"ik": ("--position", "0.3", "0", "0.3")}


@pytest.mark.parametrize("command", COMMANDS)
def test_missing_file(run, command, tmp_path):
    missing = tmp_path / "nope.urdf"
    assert_one_line_error(
        run(command, missing, *NEEDS.get(command, ())), 2, str(missing), "no such file")


@pytest.mark.parametrize("command", COMMANDS)
def test_directory(run, command, tmp_path):
    assert_one_line_error(
        run(command, tmp_path / ".", *NEEDS.get(command, ())), 2, "is a directory")


@pytest.mark.parametrize("command", LOADING_COMMANDS)
def test_malformed_xml_names_line_and_column(run, command, tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r">\n  <link name="a">\n</robot>\n')
    assert_one_line_error(
        run(command, bad, *NEEDS.get(command, ())), 2, f"{bad}:3:3", "mismatched tag")


@pytest.mark.parametrize("command", LOADING_COMMANDS)
def test_xacro_error(run, command, tmp_path):
    bad = tmp_path / "bad.urdf.xacro"
    bad.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                   '  <xacro:nosuch_macro/>\n</robot>\n')
    assert_one_line_error(
        run(command, bad, *NEEDS.get(command, ())), 2, f"{bad}:2:3", "unknown macro name")


@pytest.mark.parametrize("command", COMMANDS)
def test_unknown_bundled_robot(run, command):
    assert_one_line_error(
        run(command, "--robot", "mars", *NEEDS.get(command, ())), 2, "no bundled robot 'mars'",
                          "sim, real")


@pytest.mark.parametrize("command", COMMANDS)
def test_file_and_robot_together(run, command):
    assert_one_line_error(
        run(command, SIM_URDF, "--robot", "real", *NEEDS.get(command, ())), 2, "not both")


@pytest.mark.parametrize("command", ["inspect", "fk", "ik", "simulate", "drive", "emulate"])
def test_not_a_robot(run, command, tmp_path):
    other = tmp_path / "model.sdf"
    other.write_text('<sdf version="1.6"><model name="m"/></sdf>')
    assert_one_line_error(
        run(command, other, *NEEDS.get(command, ())), 2, "root element is <sdf>, not <robot>")


@pytest.mark.parametrize("command", ["inspect", "fk", "ik", "simulate", "drive", "emulate"])
def test_urdf_that_pinocchio_rejects(run, command, tmp_path):
    bad = tmp_path / "nolimits.urdf"
    bad.write_text('<robot name="r"><link name="a"/><link name="b"/>'
                   '<joint name="j" type="revolute"><parent link="a"/><child link="b"/>'
                   "</joint></robot>")
    line = assert_one_line_error(
        run(command, bad, *NEEDS.get(command, ())), 2, "not a valid URDF",
                                 "does not specify limits", "servicebot check")
    assert "urdfdom" not in line and "model.cpp" not in line


_AS_NOBODY = """
import os, sys
from servicebot_cli.cli import main
import importlib, pkgutil, servicebot_cli  # noqa: E401
for module in pkgutil.walk_packages(servicebot_cli.__path__, "servicebot_cli."):
    if not module.name.endswith("__main__"):
        importlib.import_module(module.name)  # while still allowed to read the venv
if os.geteuid() == 0:  # root reads everything: drop to nobody for a real permission check
    os.setgroups([]); os.setgid(65534); os.setuid(65534)
main(sys.argv[1:], prog_name="servicebot")
"""


def test_unreadable_file():
    directory = Path(tempfile.mkdtemp(prefix="sb-perm-"))
    try:
        directory.chmod(0o755)
        secret = directory / "secret.urdf"
        secret.write_bytes(SIM_URDF.read_bytes())
        secret.chmod(0)
        result = subprocess.run([sys.executable, "-c", _AS_NOBODY, "fk", str(secret)],
                                capture_output=True, text=True, timeout=60, cwd=directory)
        assert_one_line_error(result, 2, str(secret), "permission denied")
    finally:
        for path in directory.iterdir():
            path.chmod(stat.S_IWUSR | stat.S_IRUSR)
            path.unlink()
        directory.rmdir()


def test_empty_file(run, tmp_path):
    empty = tmp_path / "empty.urdf"
    empty.write_bytes(b"")
    assert_one_line_error(run("fk", empty), 2, "file is empty")


def test_invalid_utf8(run, tmp_path):
    bad = tmp_path / "latin1.urdf"
    bad.write_bytes('<robot name="r">\n  <link name="caf\u00e9"/>\n</robot>'.encode("latin-1"))
    assert_one_line_error(run("fk", bad), 2, f"{bad}:2:18", "invalid UTF-8",
                          "save the file as UTF-8")


def test_entity_that_reads_a_file_is_refused_and_leaks_nothing(run, tmp_path):
    evil = tmp_path / "evil.urdf"
    evil.write_text('<?xml version="1.0"?>\n<!DOCTYPE robot [<!ENTITY passwd SYSTEM '
                    '"file:///etc/passwd">]>\n<robot name="&passwd;"><link name="a"/></robot>\n')
    result = run("fk", evil)
    assert_one_line_error(result, 2, "entity declaration 'passwd' refused")
    assert "root:" not in result.stdout + result.stderr


def test_billion_laughs_is_refused_at_once():
    lol = b'<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">' + b"".join(
        b'<!ENTITY lol%d "%s">' % (i, b"&lol%d;" % (i - 1) * 10 if i > 1 else b"&lol;" * 10)
        for i in range(1, 10)
    ) + b']><robot name="&lol9;"/>'
    with pytest.raises(UnsafeXmlError, match="entity declaration"):
        parse_xml(lol, "lol.urdf")


def test_an_external_dtd_is_named_never_loaded(tmp_path):
    """As in tinyxml2 (urdfdom, Gazebo, MuJoCo): the DTD a DOCTYPE names is never read."""
    dtd = tmp_path / "evil.dtd"
    dtd.write_text('<!ENTITY secret "LEAKED">')
    head = f'<?xml version="1.0"?>\n<!DOCTYPE robot SYSTEM "{dtd.as_uri()}">\n'.encode()
    doc = parse_xml(head + b'<robot name="r"><link name="a"/></robot>', "x")
    assert doc.root.get("name") == "r" and doc.doctype == "robot"
    assert doc.external_dtd is not None
    assert (doc.external_dtd.identifier, doc.external_dtd.line) == (dtd.as_uri(), 2)
    # expat would drop the reference silently, tinyxml2 keep '&secret;': refused
    with pytest.raises(UnsafeXmlError, match="'&secret;' would come from the external DTD"):
        parse_xml(head + b'<robot name="r"><link name="a&secret;"/></robot>', "x")
    plain = parse_xml(head + b'<robot name="r&amp;&#65;&#x42;"/>', "x")
    assert plain.root.get("name") == "r&AB"
    # a comment and a CDATA section hold text, never a reference (check_urdf and xacro agree)
    text = parse_xml(head + b'<robot name="r"><!-- a&nbsp;b --><link name="a">'
                     b'<![CDATA[ &bar; ]]></link></robot>', "x")
    assert text.external_dtd is not None


def test_size_limit_refuses_quickly():
    with pytest.raises(XmlError, match="over the 1 MB limit"):
        parse_xml(b"<robot>" + b" " * 2_000_000 + b"</robot>", "big.urdf", max_bytes=1_000_000)


def test_element_positions_are_recorded():
    doc = parse_xml(b'<robot name="r">\n  <!-- note -->\n  <link name="a"/>\n</robot>', "x")
    (link,) = list(doc.root)
    assert (link.sourceline, link.column, link.leading_comments) == (3, 3, (" note ",))


def test_xacro_arguments_for_a_plain_urdf(run):
    assert_one_line_error(run("fk", SIM_URDF, "hardware:=real"), 2, "not a xacro file")


def test_a_xacro_argument_with_two_assignments_is_refused_as_xacro_refuses_it(run):
    """xacro stops on x:=a:=b ('Invalid remapping argument'); expand took the value 'a:=b'."""
    assert_one_line_error(run("expand", XACRO_SOURCE, "hardware:=sim:=real"), 2,
                          "'hardware:=sim:=real' holds ':=' twice, which xacro refuses")


def test_xacro_arguments_without_a_file(run):
    assert_one_line_error(run("fk", "hardware:=real"), 2, "need a xacro FILE")


def test_two_files_for_a_single_robot_command(run):
    assert_one_line_error(run("fk", SIM_URDF, XACRO_SOURCE), 2, "one robot description at a time")


def test_missing_option_value_points_at_the_subcommand_help(run):
    assert_one_line_error(run("expand", "-o"), 2, "requires an argument",
                          "servicebot expand --help")
    # a subcommand of check: its own help, not the group's (which shows check urdf's)
    assert_one_line_error(run("check", "controllers", "--urdf"), 2, "requires an argument",
                          "servicebot check controllers --help")
    assert_one_line_error(run("check", "urdf", "x.urdf", "--select"), 2,
                          "requires an argument", "servicebot check urdf --help")


def test_unknown_option_is_one_line(run):
    assert_one_line_error(run("fk", "--no-such-option"), 2, "No such option",
                          "servicebot fk --help")


TREE_FIXTURES = Path(__file__).parents[1] / "check" / "fixtures"


@pytest.mark.parametrize("command", [c for c in LOADING_COMMANDS if c != "expand"])
@pytest.mark.parametrize(("name", "link", "joints"), [
    ("SB106_two_parents.urdf", "tool", "'tool_on_base' and 'tool_on_arm'"),
    ("SB107_kinematic_loop.urdf", "arm", "'shoulder' and 'closure'")])
def test_a_link_with_two_parent_joints_is_refused_before_pinocchio(command, name, link, joints):
    """Pinocchio drops one of the joints silently, and a loop crashes it (a real process: a
    crash would end the test run otherwise)."""
    result = run_servicebot(command, TREE_FIXTURES / name, *NEEDS.get(command, ()),
                            *(["--headless"] if command == "simulate" else []))
    assert_one_line_error(result, 2, f"link '{link}' is the child of joints {joints}",
                          "a URDF is a tree")


def test_the_check_hint_names_the_xacro_arguments_the_file_was_expanded_with(tmp_path):
    """`servicebot check FILE` alone would check another expansion (or need the argument)."""
    robot = tmp_path / "my robot.urdf.xacro"
    robot.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:arg name="limit" default="true"/><link name="base"/><link name="arm"/>'
        '<joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>'
        '<axis xyz="0 0 1"/><xacro:if value="$(arg limit)">'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></xacro:if></joint></robot>')
    result = run_servicebot("fk", robot, "limit:=false")
    line = assert_one_line_error(result, 2, "not a valid URDF", "does not specify limits")
    assert line.endswith(f"(run 'servicebot check \"{robot}\" limit:=false' for details)")
    assert run_servicebot("fk", robot).returncode == 0  # its default expansion builds


_PLAIN_ENTITY = ('<?xml version="1.0"?>\n<!DOCTYPE robot [<!ENTITY len "0.5">]>\n'
                 '<robot name="r"{ns}><link name="a"><visual><geometry><box size="&len; 1 1"/>'
                 "</geometry></visual></link></robot>\n")


def test_a_plain_entity_is_expanded_in_a_xacro_as_xacro_does(run, tmp_path):
    """xacro's expat expands it (and check_urdf takes xacro's output): refused before."""
    source = tmp_path / "r.urdf.xacro"
    source.write_text(_PLAIN_ENTITY.format(ns=' xmlns:xacro="http://www.ros.org/wiki/xacro"'))
    result = run("expand", source)
    assert result.exit_code == 0, result.output
    assert '<box size="0.5 1 1"/>' in result.stdout
    output = tmp_path / "out.urdf"
    output.write_text(result.stdout)  # the DOCTYPE stays, its entity used nowhere
    assert run("check", "urdf", output, "--isolated").exit_code == 0


def test_a_plain_entity_in_a_urdf_is_an_error_as_urdfdom_reads_it_as_written(run, tmp_path):
    robot = tmp_path / "r.urdf"
    robot.write_text(_PLAIN_ENTITY.format(ns=""))
    result = run("check", "urdf", robot, "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB005"]
    assert found["severity"] == "error" and (found["line"], found["column"]) == (3, 61)
    assert "does not expand entities and reads '&len;' as written" in found["message"]


@pytest.mark.parametrize("command", [["inspect"], ["fk"], ["inspect", "--section", "tree"]])
def test_commands_refuse_a_urdf_whose_entity_urdfdom_reads_as_written(run, tmp_path, command):
    """An entity holding a <link>: read here it was a link, which urdfdom (and Pinocchio on
    it) never sees; inspect stopped with an internal error (KeyError) on the difference."""
    robot = tmp_path / "r.urdf"
    robot.write_text('<?xml version="1.0"?>\n<!DOCTYPE robot [<!ENTITY lk "<link '
                     "name='extra'/>\">]>\n<robot name=\"r\"><link name=\"base\"/>"
                     '<link name="arm"/><joint name="j" type="revolute"><parent link="base"/>'
                     '<child link="arm"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" '
                     'effort="1" velocity="1"/></joint>\n&lk;</robot>\n')
    assert_one_line_error(run(*command, robot), 2, "r.urdf:4:1: entity '&lk;'",
                          "reads '&lk;' as written")


@pytest.mark.parametrize("declaration", ['<!ENTITY % p "x">', '<!ENTITY a "&b;">',
                                         f'<!ENTITY long "{"x" * 5000}">'])
def test_entities_other_than_plain_text_are_refused(declaration):
    with pytest.raises(UnsafeXmlError, match="entity declaration .* refused"):
        parse_xml(f'<!DOCTYPE robot [{declaration}]><robot name="r"/>'.encode(), "e.urdf")


@pytest.mark.parametrize(("command", "include"), [("check", "inc.xacro"),
                                                   ("expand", "parts.xml")])
def test_an_output_that_is_a_file_the_xacro_includes_is_refused(run, tmp_path, command,
                                                                include):
    """check main.urdf.xacro -o inc.xacro replaced the include with the report."""
    (tmp_path / include).write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="part">'
        '<link name="part"/></xacro:macro></robot>')
    main = tmp_path / "main.urdf.xacro"
    main.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                    f'<xacro:include filename="{include}"/><link name="base"/><xacro:part/>'
                    '<joint name="j" type="fixed"><parent link="base"/><child link="part"/>'
                    "</joint></robot>")
    before = (tmp_path / include).read_text()
    result = run(command, main, "-o", tmp_path / include)
    assert_one_line_error(result, 2, "is the file it reads")
    assert (tmp_path / include).read_text() == before


def test_a_read_only_file_system_is_named_as_such_not_as_permissions(run, tmp_path):
    """EROFS was 'permission denied writing in ro', which sends the user to chmod."""
    mount_point = tmp_path / "ro"
    mount_point.mkdir()
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "ro,size=64k", "none",
                              str(mount_point)], capture_output=True, check=False)
    if mounted.returncode != 0:
        pytest.skip("mounting a read-only tmpfs needs root (CI runs as root): "
                    + mounted.stderr.decode(errors="replace").strip())
    try:
        result = run("expand", "-o", mount_point / "out.urdf")
        assert_one_line_error(result, 2, "is on a read-only file system")
    finally:
        subprocess.run(["umount", str(mount_point)], check=False)


@pytest.mark.parametrize(("args", "says"), [
    (["simulate", "--headless", "--plot", "/dev/full"], "'/dev/full' is a device, and its name"),
    (["inspect", "--render", "/dev/full"], "its name gives no format (.png, .svg, .pdf)"),
    (["fk", "--configs", "/dev/null", "-o", "/dev/full"], "or '-' for standard output"),
    (["simulate", "--headless", "--plot", "a" * 300 + ".png"], "is too long: 304 bytes"),
])
def test_an_output_that_cannot_be_written_is_refused_before_the_work(run, args, says):
    """simulate --plot /dev/full (or a name too long) was refused after the whole run."""
    assert_one_line_error(run(*args), 2, says)


def test_a_link_into_a_missing_directory_is_refused_before_the_work(run, tmp_path):
    link = tmp_path / "plot.png"
    link.symlink_to(tmp_path / "missing" / "plot.png")
    assert_one_line_error(run("simulate", "--headless", "--plot", link), 2,
                          "whose directory does not exist")
