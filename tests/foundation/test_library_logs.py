"""A library's own log records and warnings are collected as lines, never printed."""

from __future__ import annotations

import logging
import warnings

import numpy as np

from servicebot_cli.common.library_logs import captured


def test_a_logged_traceback_becomes_one_line_and_nothing_is_printed(capsys):
    with captured() as said:
        try:
            raise FileNotFoundError("l_finger_normals.png")
        except FileNotFoundError:
            logging.getLogger("trimesh").error("unable to load bumpmap", exc_info=True)
        with np.errstate(over="warn"):
            np.float64(1e308) * 10
        warnings.warn("a library's warning", stacklevel=1)
    assert said == ["unable to load bumpmap: FileNotFoundError: l_finger_normals.png",
                    "overflow encountered in scalar multiply", "a library's warning"]
    out, err = capsys.readouterr()
    assert out == err == ""


def test_loggers_are_put_back():
    logger = logging.getLogger("trimesh")
    before = (logger.propagate, list(logger.handlers))
    with captured():
        pass
    assert (logger.propagate, list(logger.handlers)) == before
