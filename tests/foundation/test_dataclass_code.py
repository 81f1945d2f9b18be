"""The code of servicebot's dataclasses' methods, kept between runs on Python 3.11.

The methods made from kept code must be the ones ``@dataclass`` compiles (the same bytecode,
the same behaviour), a second process must compile none of them, a changed class must get its
new methods, and a damaged file, a read-only one or ``PYTHONDONTWRITEBYTECODE`` must change
nothing but the time it takes.
"""

from __future__ import annotations

import dataclasses
import importlib.util
import marshal
import os
import subprocess
import sys
import textwrap
import typing
from pathlib import Path
from types import ModuleType

import pytest

from servicebot_cli.common import dataclass_code

pytestmark = pytest.mark.skipif(
    sys.version_info[:2] != (3, 11) or sys.implementation.name != "cpython",
    reason="only Python 3.11's dataclasses compile each method from text at every start")

PROBE = '''
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Pose:
    x_m: float
    y_m: float = 0.0
    names: tuple[str, ...] = field(default_factory=tuple)


@dataclass(order=True)
class Reading:
    value: float
    seen: dataclasses.InitVar[int] = 0
    twice: float = field(init=False, default=0.0)

    def __post_init__(self, seen: int) -> None:
        self.twice = 2 * self.value + seen


@dataclass(kw_only=True, eq=False)
class Settings:
    rate_hz: float = 10.0
'''


def _module(path: Path, name: str, text: str) -> ModuleType:
    """``text`` imported from ``path`` as module ``name``."""
    path.write_text(text)
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    finally:
        del sys.modules[name]
    return module


def _methods(cls: type) -> dict[str, object]:
    """What each method of ``cls`` is made of: its bytecode, constants and names."""
    out = {}
    for name in ("__init__", "__repr__", "__eq__", "__hash__", "__setattr__", "__delattr__",
                 "__lt__", "__le__", "__gt__", "__ge__"):
        method = cls.__dict__.get(name)
        code = getattr(getattr(method, "__wrapped__", method), "__code__", None)
        if code is not None:
            out[name] = (code.co_code, code.co_consts, code.co_names, code.co_varnames,
                         code.co_freevars, code.co_flags, method.__qualname__,
                         repr(getattr(method, "__annotations__", None)))
    return out


def _cache_in(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Code kept under ``tmp_path/cache``, written whatever PYTHONDONTWRITEBYTECODE says."""
    monkeypatch.setattr(sys, "pycache_prefix", str(tmp_path / "cache"))
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    _as_a_new_process(monkeypatch)


def _as_a_new_process(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("_kept", "_codes"):
        monkeypatch.setattr(dataclass_code, name, {})


def test_kept_code_makes_the_methods_dataclasses_compiles(tmp_path, monkeypatch):
    _cache_in(tmp_path, monkeypatch)
    ours_dir, theirs_dir = tmp_path / "ours", tmp_path / "theirs"
    ours_dir.mkdir()
    theirs_dir.mkdir()
    made = [_module(ours_dir / "probe.py", "servicebot_cli._probe_made", PROBE)]
    assert list((tmp_path / "cache").rglob("probe.*.dataclass-code"))  # compiled, and kept
    _as_a_new_process(monkeypatch)  # read from the file
    made.append(_module(ours_dir / "probe.py", "servicebot_cli._probe_made", PROBE))
    stdlib = _module(theirs_dir / "probe.py", "elsewhere_probe", PROBE)  # not ours: untouched
    for module in made:
        for name in ("Pose", "Reading", "Settings"):
            assert _methods(getattr(module, name)) == _methods(getattr(stdlib, name)), name
        pose = module.Pose(1.0, names=("a",))
        same = module.Pose(1.0, 0.0, ("a",))
        assert pose == same and hash(pose) == hash(same)
        assert repr(pose) == "Pose(x_m=1.0, y_m=0.0, names=('a',))"
        with pytest.raises(dataclasses.FrozenInstanceError):
            pose.x_m = 2.0
        assert module.Reading(1.0, 3).twice == 5.0 and module.Reading(1.0) < module.Reading(2.0)
        assert module.Settings(rate_hz=5.0) != module.Settings(rate_hz=5.0)  # eq=False
        # objects, not the strings this package's own `from __future__ import annotations` makes
        assert typing.get_type_hints(module.Pose.__init__)["x_m"] is float
        with pytest.raises(TypeError):
            module.Settings(5.0)  # kw_only


def _run(script: str, cache: Path, **env: str) -> str:
    done = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(script)], capture_output=True, text=True,
        timeout=120, check=True,
        env={**os.environ, "PYTHONPYCACHEPREFIX": str(cache), "PYTHONDONTWRITEBYTECODE": "",
             **env})
    return done.stdout.strip()


COUNT_COMPILES = """
    import servicebot_cli.common.dataclass_code as kept
    compiled = []
    kept.compile = lambda *args, **kw: compiled.append(args) or compile(*args, **kw)
    import servicebot_cli.simulate.scenario.definition as module
    print(len(compiled), len(kept._codes), module.load_scenario(None).duration_s > 0)
"""


def test_a_second_process_compiles_none_of_the_methods(tmp_path):
    cache = tmp_path / "cache"
    first = _run(COUNT_COMPILES, cache).split()
    assert int(first[0]) > 20 and int(first[1]) >= 2 and first[2] == "True"
    kept = list(cache.rglob("*.dataclass-code"))
    assert len(kept) == int(first[1])
    assert _run(COUNT_COMPILES, cache).split() == ["0", first[1], "True"]


def test_nothing_is_written_without_bytecode_and_a_bad_file_is_compiled_over(tmp_path):
    cache = tmp_path / "cache"
    quiet = _run(COUNT_COMPILES, cache, PYTHONDONTWRITEBYTECODE="1").split()
    assert int(quiet[0]) > 20 and not list(cache.rglob("*.dataclass-code"))
    count = int(_run(COUNT_COMPILES, cache).split()[0])
    kept = sorted(cache.rglob("*.dataclass-code"))
    kept[0].write_bytes(b"not marshal data")
    kept[1].write_bytes(importlib.util.MAGIC_NUMBER + b"\x00\x01")
    again = _run(COUNT_COMPILES, cache).split()
    assert 0 < int(again[0]) < count and again[2] == "True"  # those two modules' methods only
    assert _run(COUNT_COMPILES, cache).split()[0] == "0"  # written over, whole


def test_a_changed_class_gets_its_new_methods(tmp_path, monkeypatch):
    _cache_in(tmp_path, monkeypatch)
    before = _module(tmp_path / "changing.py", "servicebot_cli._probe_changing",
                     "from dataclasses import dataclass\n\n@dataclass\nclass A:\n    x: int\n")
    _as_a_new_process(monkeypatch)
    after = _module(tmp_path / "changing.py", "servicebot_cli._probe_changing",
                    "from dataclasses import dataclass\n\n"
                    "@dataclass\nclass A:\n    x: int\n    y: int = 7\n")
    assert repr(before.A(1)) == "A(x=1)" and repr(after.A(1)) == "A(x=1, y=7)"
    path = dataclass_code.cache_path("servicebot_cli._probe_changing")
    assert path is None  # the module is gone from sys.modules: its file is found by name
    kept = list((tmp_path / "cache").rglob("changing*.dataclass-code"))
    assert len(kept) == 1
    with open(kept[0], "rb") as stream:
        texts = marshal.loads(stream.read()[len(importlib.util.MAGIC_NUMBER):])
    assert len(texts) == 3 and all("y" in text for text in texts if "__init__" in text)


def test_a_cache_that_cannot_be_written_leaves_the_classes_as_they_are(tmp_path):
    blocked = tmp_path / "a-file"
    blocked.write_text("")  # a cache directory below a file: no directory can be made there
    first, second = (_run(COUNT_COMPILES, blocked / "cache").split() for _ in range(2))
    assert first[2] == second[2] == "True" and int(second[0]) == int(first[0]) > 20
    assert blocked.read_text() == "" and not list(tmp_path.rglob("*.dataclass-code*"))
