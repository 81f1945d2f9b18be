"""A rosbag2 directory with MCAP storage, as ``ros2 bag record -s mcap`` makes it.

``PATH/PATH_0.mcap`` holds the messages (profile ``ros2``, ``ros2msg`` schemas, CDR payloads,
zstd chunks) and ``PATH/metadata.yaml`` describes them for ``ros2 bag play`` and ``ros2 bag
info``. Foxglove opens the ``.mcap`` file directly. Each topic's ``offered_qos_profiles``
(:mod:`~servicebot_cli.simulate.bag.qos`) is in both, as rosbag2's MCAP storage keeps it in
the channel's metadata. The directory is built under a temporary name beside ``PATH`` and
renamed into place at the end, so an interrupted run leaves no bag.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from servicebot_cli import __version__
from servicebot_cli.common.files import OutputError, atomic_directory
from servicebot_cli.simulate.bag.mcap_file import Channel, write_mcap
from servicebot_cli.simulate.bag.msgdefs import MESSAGE_DEFINITIONS
from servicebot_cli.simulate.bag.qos import offered_qos_profiles
from servicebot_cli.simulate.bag.ros_messages import Stream


def write_bag(path: str | os.PathLike[str], streams: Sequence[Stream]) -> None:
    """Write ``streams`` as a rosbag2 MCAP directory at ``path``.

    Raises:
        OutputError: ``path`` exists, its parent is missing, or writing failed.
    """
    target = Path(path)
    if target.exists():
        raise OutputError(f"{target}: already exists; remove it or give another --bag path "
                          "(ros2 bag record refuses too)")
    with atomic_directory(target) as temporary:
        file_name = f"{target.name}_0.mcap"
        _write_mcap(temporary / file_name, streams)
        (temporary / "metadata.yaml").write_text(_metadata(file_name, streams), encoding="utf-8")


def _write_mcap(file: Path, streams: Sequence[Stream]) -> None:
    channels = [Channel(topic=s.topic, message_encoding="cdr", schema_name=s.type,
                        schema_encoding="ros2msg", schema_data=MESSAGE_DEFINITIONS[s.type].encode(),
                        metadata={"offered_qos_profiles": offered_qos_profiles(s.offered_qos)})
                for s in streams]
    stamps = np.concatenate([s.stamps_ns for s in streams])
    which = np.concatenate([np.full(len(s.payloads), i) for i, s in enumerate(streams)])
    index = np.concatenate([np.arange(len(s.payloads)) for s in streams])
    order = np.argsort(stamps, kind="stable")  # one stream's messages stay in their order
    payloads = [p for s in streams for p in s.payloads]
    with file.open("wb") as handle:
        write_mcap(handle, channels, which[order], index[order], stamps[order],
                   [payloads[k] for k in order.tolist()], profile="ros2",
                   library=f"servicebot {__version__}")


def _metadata(file_name: str, streams: Sequence[Stream]) -> str:
    stamps = [s.stamps_ns for s in streams if len(s.stamps_ns)]
    start = int(min(s.min() for s in stamps)) if stamps else 0
    end = int(max(s.max() for s in stamps)) if stamps else 0
    total = sum(len(s.payloads) for s in streams)
    lines = ["rosbag2_bagfile_information:", "  version: 5", "  storage_identifier: mcap",
             "  duration:", f"    nanoseconds: {end - start}", "  starting_time:",
             f"    nanoseconds_since_epoch: {start}", f"  message_count: {total}",
             "  topics_with_message_count:"]
    for s in streams:
        lines += ["    - topic_metadata:", f"        name: {s.topic}", f"        type: {s.type}",
                  "        serialization_format: cdr",
                  f"        offered_qos_profiles: {_quoted(offered_qos_profiles(s.offered_qos))}",
                  f"      message_count: {len(s.payloads)}"]
    lines += ['  compression_format: ""', '  compression_mode: ""', "  relative_file_paths:",
              f"    - {file_name}", "  files:", f"    - path: {file_name}",
              "      starting_time:", f"        nanoseconds_since_epoch: {start}",
              "      duration:", f"        nanoseconds: {end - start}",
              f"      message_count: {total}"]
    return "\n".join(lines) + "\n"


def _quoted(text: str) -> str:
    """A YAML double-quoted scalar."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
