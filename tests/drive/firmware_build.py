"""Builds of firmware/: for this host (a pty instead of a UART) and for an Arduino Uno."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

from tests.conftest import REPO

FIRMWARE = REPO / "firmware"
SKETCH = FIRMWARE / "servicebot_firmware"
PORTABLE = [SKETCH / "controller.cpp", SKETCH / "protocol.cpp"]
ARDUINO_AVR = Path("/usr/share/arduino/hardware/arduino/avr")
AVR_PACKAGES = "gcc-avr avr-libc arduino-core-avr"


def build_host(out_dir: Path) -> Path:
    """The firmware for this machine, with firmware/host/'s simulated motors on a pty."""
    binary = out_dir / "servicebot_firmware_host"
    subprocess.run(["g++", "-std=c++17", "-O2", "-Wall", "-Wextra", "-Werror", "-o", binary,
                    *FIRMWARE.glob("host/*.cpp"), *PORTABLE, "-lutil"],
                   check=True, capture_output=True, text=True)
    return binary


def avr_missing() -> str:
    """Why the Uno build cannot run here, or '' when it can."""
    tools = [t for t in ("avr-gcc", "avr-g++", "avr-size") if shutil.which(t) is None]
    if not (ARDUINO_AVR / "cores" / "arduino" / "Arduino.h").exists():
        tools.append(f"the Arduino core in {ARDUINO_AVR}")
    if tools:
        return (f"needs Debian's {AVR_PACKAGES} (missing: {', '.join(tools)}): "
                f"apt-get install -y {AVR_PACKAGES}")
    return ""


def build_uno(out_dir: Path) -> tuple[int, int]:
    """Compile the sketch and the Arduino core for an ATmega328P; ``(flash, ram)`` bytes.

    Flash is text + data (initialised data is stored in flash too), RAM is data + bss
    (what is used before the stack and the heap).
    """
    core, variant = ARDUINO_AVR / "cores" / "arduino", ARDUINO_AVR / "variants" / "standard"
    flags = ["-mmcu=atmega328p", "-DF_CPU=16000000L", "-DARDUINO=10819", "-DARDUINO_AVR_UNO",
             "-DARDUINO_ARCH_AVR", "-Os", "-ffunction-sections", "-fdata-sections",
             f"-I{core}", f"-I{variant}"]
    cxx = ["-std=gnu++1z", "-fno-exceptions", "-fno-threadsafe-statics", "-fno-rtti"]
    objects = []
    for source in sorted(core.glob("*.c")) + sorted(core.glob("*.cpp")):
        if source.name == "WString.cpp":  # Debian's copy needs a newer compiler; unused here
            continue
        obj = out_dir / f"core_{source.name}.o"
        compiler = ["avr-gcc"] if source.suffix == ".c" else ["avr-g++", *cxx]
        _run([*compiler, *flags, "-c", str(source), "-o", str(obj)])
        objects.append(obj)
    for source in [SKETCH / "servicebot_firmware.ino", *PORTABLE]:
        obj = out_dir / f"{source.stem}.o"
        _run(["avr-g++", *cxx, *flags, "-Wall", "-Wextra", "-Werror", "-x", "c++", "-c",
              str(source), "-o", str(obj)])
        objects.insert(0, obj)
    elf = out_dir / "servicebot_firmware.elf"
    _run(["avr-gcc", "-mmcu=atmega328p", "-Os", "-Wl,--gc-sections", "-o", str(elf),
          *map(str, objects), "-lm"])
    sizes = _run(["avr-size", str(elf)]).splitlines()[1].split()
    text, data, bss = (int(v) for v in sizes[:3])
    return text + data, data + bss


def _run(command: list[str]) -> str:
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode:
        raise AssertionError(f"{' '.join(command)} failed:\n{done.stderr}")
    return done.stdout
