"""SB017: each warning xacro gives comes with what to change (the real xacro, in-process)."""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
LINK = '<link name="a"/>'


@pytest.mark.parametrize(("body", "args", "message", "fix"), [
    # only for a name xacro defines itself (math's pi, Python's len): a property defined twice
    # is no warning; the fix said to define it once
    ('<xacro:property name="pi" value="3"/>', [], "redefining global symbol: pi",
     "rename the property: it hides xacro's own 'pi' in every ${} expression"),
    ('<xacro:property name="len" value="3"/>', [], "redefining global symbol: len",
     "rename the property: it hides xacro's own 'len'"),
    ('<xacro:include filename="parts/*.xacro"/>', [], 'matched no files',
     "fix the pattern '"),  # the pattern as xacro resolved it: from the file's directory
    ('<xacro:macro name="m" params="" colour="red"/>', [], "unknown attribute(s): colour",
     "remove colour from <xacro:macro>"),
    ('<xacro:property name="n" value="${len(range(2))}"/><link name="b${n}"/>', [],
     "Using range() directly is deprecated", "write python.range()"),
    ("", ["speed:=2"], "xacro argument 'speed' is not declared",
     "drop speed:=VALUE, or declare it"),
    ('<xacro:include filename="parts/*.xacro"><xacro:arg name="g" default="1"/>'
     '</xacro:include>', [], "Child elements of a <xacro:include> tag are ignored",
     "remove them: the included file already sees"),
    ('<xacro:macro name="wheel" params=""><link name="w"/></xacro:macro><wheel/>', [],
     "<wheel> is not a macro call", "write <xacro:wheel .../>"),
])
def test_each_xacro_warning_says_what_to_change(run, tmp_path, body, args, message, fix):
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f"{HEAD}{body}{LINK}</robot>")
    result = run("check", "urdf", path, *args, "--format", "json", "--isolated",
                 "--select", "SB017")
    (found,) = [f for f in findings(result.stdout) if message in f["message"]]
    assert found["fix"].startswith(fix), found["fix"]


def test_a_urdf_that_xacro_must_expand_says_to_name_it_xacro(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(f'{HEAD}<xacro:property name="l" value="a"/><link name="${{l}}"/></robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB017")
    (found,) = findings(result.stdout)
    assert found["fix"] == "name it .urdf.xacro"


def test_what_a_file_prints_itself_is_reported_as_it_printed_it(run, tmp_path):
    """xacro.message() is the file's information, xacro.error() a warning (xacro writes the
    robot all the same), xacro.warning() a warning that says so: a message was a warning
    with the generic fix "Each finding's fix says what to change"."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f"{HEAD}<link name=\"a${{xacro.message('using sim', color='green')}}"
                    "${xacro.error('Unknown', 'gripper')}${xacro.warning('deprecated', 5)}\"/>"
                    "</robot>")
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB017")
    said = {f["message"]: (f["severity"], f["fix"]) for f in findings(result.stdout)}
    assert said == {
        "the file's xacro.message(): using sim":
            ("info", "nothing to change: the file prints this while xacro expands it"),
        "the file's xacro.error(), after which xacro goes on: Unknown gripper":
            ("warning", "do what it says: xacro still writes the robot, as the file stands"),
        "deprecated 5": ("warning", "do what the warning says: the file wrote it with "
                         "xacro.warning(), or xacro did")}
    assert result.exit_code == 0
    assert {f["line"] for f in findings(result.stdout)} == {1}  # placed at the <link>
    expanded = run("expand", path)
    assert expanded.stderr.splitlines() == [
        f"{path}:1:61: using sim", f"warning: {path}:1:61: the file's xacro.error(): Unknown "
        "gripper", f"warning: {path}:1:61: deprecated 5"]


def test_a_warning_xacro_writes_on_three_lines_is_one_finding(run, tmp_path):
    """inconsistent namespace redefinitions: the old and the new URI on lines of their own
    were two more warnings, each with the generic fix."""
    (tmp_path / "part.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" xmlns:s="b"/>')
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'{HEAD[:-1]} xmlns:s="a"><xacro:include filename="part.xacro"/>'
                    f"{LINK}</robot>")
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB017")
    (found,) = findings(result.stdout)
    assert found["message"] == ("inconsistent namespace redefinitions for xmlns:s: old: a "
                                f"new: b ({tmp_path / 'part.xacro'})")
    assert found["fix"] == "declare xmlns:s with one namespace URI in every included file"


def test_xacros_own_warnings_are_placed_at_the_element_that_warned(run, tmp_path):
    """xacro names only the file ('when processing file: ...'): SARIF and GitHub annotations
    had line 0. Baxter's two includes with children are two findings, one at each."""
    (tmp_path / "part.xacro").write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"/>')
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f"{HEAD}\n{LINK}\n"
                    '<xacro:include filename="part.xacro"><xacro:arg name="g" default="1"/>'
                    '</xacro:include>\n<xacro:property name="len" value="2"/>\n'
                    '<xacro:include filename="part.xacro"><xacro:arg name="g" default="1"/>'
                    "</xacro:include>\n</robot>")
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB017")
    assert [(f["line"], f["column"], f["message"][:26]) for f in findings(result.stdout)] == [
        (3, 1, "Child elements of a <xacro"), (4, 1, "redefining global symbol: "),
        (5, 1, "Child elements of a <xacro")]


def test_a_macro_parameter_not_passed_names_the_macro_and_the_fix_that_works(run, tmp_path):
    """'Undefined parameters [mass]' said neither which macro nor a fix that works: its fix
    was 'pass the missing NAME:=VALUE', which sets an argument, not a macro parameter."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'{HEAD}\n<xacro:macro name="wheel" params="side mass"><link name="${{side}}"/>'
                    '</xacro:macro>\n<xacro:wheel side="l"/>\n</robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert (found["code"], found["line"]) == ("SB006", 3)
    assert found["message"] == "Undefined parameters [mass] of macro 'wheel'"
    assert found["fix"].startswith('write mass="..." in this call, or give the macro\'s '
                                   'parameter a default (params="... mass:=VALUE")')


def test_an_error_inside_a_macro_names_the_macros_and_their_calls(run, tmp_path):
    """An error in a macro's body was placed in the body alone: which call of which macro
    (xacro prints 'when instantiating macro: wheel') was not said, nor its parameter fix."""
    (tmp_path / "parts.xacro").write_text(
        f'{HEAD}\n<xacro:macro name="tire" params="side">\n'
        '  <link name="${side}" radius="${radius}"/>\n</xacro:macro>\n'
        '<xacro:macro name="wheel" params="side">\n  <xacro:tire side="${side}"/>\n'
        '</xacro:macro>\n</robot>')
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'{HEAD}\n<xacro:include filename="parts.xacro"/>\n{LINK}\n'
                    '<xacro:call macro="wheel" side="l"/>\n</robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert (found["code"], found["file"].endswith("parts.xacro"), found["line"]) == \
        ("SB006", True, 3)
    assert found["message"].endswith(
        f"(in macro 'tire', called at {tmp_path / 'parts.xacro'}:6:3, in macro 'wheel', "
        f"called at {path}:4:1)")
    assert found["fix"].startswith("give macro 'tire' a parameter 'radius'")


def test_an_error_at_the_call_itself_names_no_call(run, tmp_path):
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'{HEAD}\n<xacro:macro name="wheel" params="side"><link name="${{side}}"/>'
                    '</xacro:macro>\n<xacro:wheel side="l" bogus="1"/>\n</robot>')
    (found,) = findings(run("check", "urdf", path, "--format", "json", "--isolated").stdout)
    assert (found["line"], found["message"]) == (
        3, "Invalid parameter \"bogus\" of macro 'wheel' (its parameters: side)")
    assert found["fix"] == ("write one of the parameters of macro 'wheel' instead of 'bogus', "
                            "or add 'bogus' to its params")


def test_an_empty_expression_is_said_so(run, tmp_path):
    """${} was Python's 'invalid syntax (<expression>, line 0)'."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'{HEAD}\n<link name="a"><visual><geometry><box size="1 1 ${{}}"/>'
                    "</geometry></visual></link>\n</robot>")
    (found,) = findings(run("check", "urdf", path, "--format", "json", "--isolated").stdout)
    assert found["message"] == "an empty expression ${}: write what it should compute"


def test_a_directives_unknown_attribute_is_placed_at_the_directive(run, tmp_path):
    """xacro:if, xacro:unless and xacro:arg are read while their parent is processed: their
    warnings were placed at the parent (<robot>, 2:1, for a directive on line 5)."""
    path = tmp_path / "r.urdf.xacro"
    path.write_text(f'{HEAD}\n<link name="a">\n  <xacro:if value="1" foo="bar"/>\n</link>\n'
                    '<xacro:arg name="g" default="1" yy="1"/>\n'
                    '<xacro:unless value="0" qq="1"/>\n</robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB017")
    placed = {f["message"].split(": ")[0]: (f["line"], f["column"])
              for f in findings(result.stdout)}
    assert placed == {"xacro:if": (3, 3), "xacro:arg": (5, 1), "xacro:unless": (6, 1)}
