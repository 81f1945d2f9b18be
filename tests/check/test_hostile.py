"""Hostile input gets a finding, never a crash, a hang or a leak."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from servicebot_cli.check.env import CheckEnv
from servicebot_cli.check.runner import check_source
from servicebot_cli.check.settings import Settings
from servicebot_cli.description.loader import RobotSource
from tests.check.helpers import FIXTURES, codes, findings
from tests.conftest import SIM_URDF

INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" '
            'iyz="0" izz="0.01"/></inertial>')


def test_an_entity_reading_etc_passwd_is_refused_and_leaks_nothing(run, tmp_path):
    evil = tmp_path / "evil.urdf"
    evil.write_text('<?xml version="1.0"?>\n<!DOCTYPE robot [<!ENTITY passwd SYSTEM '
                    '"file:///etc/passwd">]>\n<robot name="&passwd;"><link name="a"/></robot>\n')
    result = run("check", evil, "--format", "json")
    assert result.exit_code == 1
    (finding,) = findings(result.stdout)
    assert (finding["code"], finding["line"]) == ("SB005", 2)
    assert "root:" not in result.stdout + result.stderr


def test_billion_laughs_is_refused(run, tmp_path):
    entities = "".join(f'<!ENTITY lol{i} "{f"&lol{i - 1};" * 10}">' for i in range(1, 10))
    lol = tmp_path / "lol.urdf"
    lol.write_text(f'<?xml version="1.0"?><!DOCTYPE r [<!ENTITY lol0 "lol">{entities}]>'
                   '<robot name="&lol9;"><link name="a"/></robot>')
    result = run("check", lol, "--format", "json")
    assert codes(result.stdout) == {"SB005"} and result.exit_code == 1


def test_a_50_mb_file_is_refused_unread(run, tmp_path):
    big = tmp_path / "big.urdf"
    line = b'  <link name="padding"/>\n'
    with big.open("wb") as handle:
        handle.write(b'<robot name="big">\n')
        handle.write(line * (50_000_000 // len(line)))
        handle.write(b"</robot>\n")
    result = run("check", big, "--format", "json")
    (finding,) = findings(result.stdout)
    assert finding["code"] == "SB015" and "50.0 MB" in finding["message"]


def test_too_many_links_are_refused_before_any_graph_work(run, tmp_path):
    many = tmp_path / "many.urdf"
    many.write_text('<robot name="many">' + "".join(f'<link name="l{i}"/>' for i in range(20001))
                    + "</robot>")
    result = run("check", many, "--format", "json")
    assert codes(result.stdout) == {"SB015"}


def _chain(n: int, close: bool = False) -> str:
    parts = ['<robot name="chain">']
    parts += [f'<link name="l{i}">{INERTIAL}</link>' for i in range(n + 1)]
    parts += [f'<joint name="j{i}" type="continuous"><parent link="l{i}"/>'
              f'<child link="l{i + 1}"/><axis xyz="0 0 1"/></joint>' for i in range(n)]
    if close:
        parts.append(f'<joint name="closure" type="fixed"><parent link="l{n}"/>'
                     '<child link="l1"/></joint>')
    return "".join(parts) + "</robot>"


def test_a_3000_joint_chain_is_checked(run, tmp_path):
    chain = tmp_path / "chain.urdf"
    chain.write_text(_chain(3000))
    result = run("check", chain, "--format", "json", "--ignore", "SB301")
    assert result.exit_code == 0, result.stdout
    assert codes(result.stdout) == {"SB309"}


def test_a_loop_prints_its_cycle(run, tmp_path):
    small = tmp_path / "loop.urdf"
    small.write_text(_chain(3, close=True))
    messages = [f["message"] for f in findings(run("check", small, "--format", "json").stdout)
                if f["code"] == "SB107"]
    assert messages == ["kinematic loop: l1 -[j1]-> l2 -[j2]-> l3 -[closure]-> l1"]
    big = tmp_path / "big_loop.urdf"
    big.write_text(_chain(3000, close=True))
    (message,) = [f["message"] for f in findings(run("check", big, "--format", "json").stdout)
                  if f["code"] == "SB107"]
    assert message.startswith("kinematic loop: l1 -[j1]-> l2") and "(2989 more joints)" in message
    assert message.endswith("-[closure]-> l1")


# -- property: mutated valid URDFs never make check raise ------------------------------------

SEEDS = [SIM_URDF.read_text(), (FIXTURES / "SB303_massless_moving_link.urdf").read_text(),
         (FIXTURES / "SB502_sensor_parameter.urdf").read_text(),
         (FIXTURES / "SB508_control_limits.urdf").read_text()]
NASTY = st.sampled_from(["", "0", "-1", "nan", "inf", "-inf", "1e400", "1 2", "a b c", "0 0 0",
                         "3.14 0 0 0", "  ", "\u00e9", "&amp;", "<", "base_link", "fixed", "ball",
                         "package://x/y.stl", "/dev/null", "../../etc/passwd", "1e-30"])


@st.composite
def mutated(draw: st.DrawFn) -> bytes:
    text = draw(st.sampled_from(SEEDS))
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(["attr", "cut", "dup", "drop", "insert", "tag"]))
        if kind == "attr":
            values = [i for i in range(len(text)) if text.startswith('="', i)]
            if not values or '"' not in text[values[-1] + 2:]:
                continue
            i = draw(st.sampled_from(values[:-1] or values)) + 2
            j = text.index('"', i)
            text = text[:i] + draw(NASTY) + text[j:]
        elif kind == "cut":
            text = text[: draw(st.integers(0, len(text)))]
        else:
            starts = [i for i in range(len(text)) if text.startswith("\n  <", i)]
            if not starts:
                continue
            i = draw(st.sampled_from(starts))
            j = text.find("\n  <", i + 1) if i + 1 < len(text) else len(text)
            j = len(text) if j < 0 else j
            block = text[i:j]
            if kind == "dup":
                text = text[:j] + block + text[j:]
            elif kind == "drop":
                text = text[:i] + text[j:]
            elif kind == "insert":
                text = text[:i] + draw(st.text(max_size=20)) + text[i:]
            else:
                text = text[:i] + block.replace("<", "<" + draw(st.sampled_from(
                    ["joint ", "link ", "x", "gazebo "])), 1) + text[j:]
    return text.encode("utf-8", "surrogatepass") if draw(st.booleans()) else \
        text.encode("utf-8", "replace")


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow],
          derandomize=True)
@given(data=mutated())
def test_check_never_raises_on_mutated_urdfs(tmp_path_factory, data):
    path = Path(tmp_path_factory.mktemp("mutant")) / "mutant.urdf"
    path.write_bytes(data)
    report = check_source(RobotSource.of(path), Settings(), CheckEnv())
    for finding in report.findings:
        assert finding.code and finding.message and finding.file
