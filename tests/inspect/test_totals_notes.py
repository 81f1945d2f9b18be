"""inspect's totals say what they leave out."""

from __future__ import annotations

from tests.conftest import SIM_URDF, run_servicebot


def test_a_link_whose_mass_is_no_number_is_named_in_a_note(tmp_path):
    """A link with <mass value="nan"> was left out of the total without a word: the bundled
    robot weighed 10.35 kg instead of 20.35 kg, with its centre of mass moved."""
    text = SIM_URDF.read_text()
    start = text.index("<mass value=", text.index('<link name="base_link"'))
    end = text.index("/>", start)
    path = tmp_path / "robot.urdf"
    path.write_text(text[:start] + '<mass value="nan"' + text[end:])
    result = run_servicebot("inspect", path, "--section", "totals")
    assert result.returncode == 0, result.stderr
    assert "left out of the mass and its centre: base_link, whose mass is not a finite" \
        in " ".join(result.stdout.split())
