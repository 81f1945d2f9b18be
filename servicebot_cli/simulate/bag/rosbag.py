"""A rosbag2 directory with MCAP storage, as ``ros2 bag record -s mcap`` makes it.

``PATH/PATH_0.mcap`` holds the messages (profile ``ros2``, ``ros2msg`` schemas, CDR payloads,
zstd chunks) and ``PATH/metadata.yaml`` describes them for ``ros2 bag play`` and ``ros2 bag
info``. Foxglove opens the ``.mcap`` file directly. Each topic's ``offered_qos_profiles``
(:mod:`~servicebot_cli.simulate.bag.qos`) is in both, as rosbag2's MCAP storage keeps it in
the channel's metadata. The directory is built under a temporary name beside ``PATH`` and
renamed into place at the end, so an interrupted run leaves no bag.

Messages are written as the run's pieces come: each piece's messages wait until no later
piece can bring one stamped before them, then go to the file in time order (equal stamps in
the order of :func:`~servicebot_cli.simulate.bag.ros_messages.publishers`).
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path

import numpy as np
import numpy.typing as npt

from servicebot_cli import __version__
from servicebot_cli.common.files import OutputError, atomic_directory
from servicebot_cli.simulate.bag.byte_rows import ByteRows, Payloads
from servicebot_cli.simulate.bag.cdr import stamps_ns
from servicebot_cli.simulate.bag.mcap_file import Channel, McapWriter
from servicebot_cli.simulate.bag.msgdefs import MESSAGE_DEFINITIONS
from servicebot_cli.simulate.bag.qos import offered_qos_profiles
from servicebot_cli.simulate.bag.ros_messages import Publisher, Topic, topics
from servicebot_cli.simulate.simulator import SimResult

IntArray = npt.NDArray[np.int64]


class BagWriter:
    """Writes a run's messages, piece by piece, as a rosbag2 MCAP directory at ``path``.

    The directory is begun on the stack ``stack``; it is renamed into place when the stack
    closes after :meth:`finish`, and removed if it closes on an error.

    Raises:
        OutputError: ``path`` exists, or its parent is missing or not writable.
    """

    def __init__(self, path: str | os.PathLike[str], publishers: list[Publisher],
                 stack: contextlib.ExitStack) -> None:
        target = Path(path)
        if os.path.exists(target):
            raise OutputError(f"{target}: already exists; remove it or give another --bag "
                              "path (ros2 bag record refuses too)")
        self.publishers, self.topics = publishers, topics(publishers)
        self.directory = stack.enter_context(atomic_directory(target))
        self.file_name = f"{target.name}_0.mcap"
        handle = stack.enter_context((self.directory / self.file_name).open("wb"))
        self.channel = np.array([[t.name for t in self.topics].index(p.topic)
                                 for p in publishers])
        self.mcap = McapWriter(handle, [_channel(t) for t in self.topics], profile="ros2",
                               library=f"servicebot {__version__}")
        stack.callback(self.mcap.close)  # before the file closes
        self.sequences = np.zeros(len(self.topics), dtype=np.int64)
        self.start_ns: int | None = None
        self.end_ns = 0
        # messages waiting for their turn, in the order they came: blocks of one publisher's
        # messages (its index, their stamps [ns] in time order, their payloads as rows)
        self.waiting: list[tuple[int, IntArray, Payloads]] = []

    def add(self, piece: SimResult) -> None:
        """Take a piece's messages; write those no later piece can precede."""
        for index, publisher in enumerate(self.publishers):
            times = publisher.times(piece)
            if len(times):
                self.waiting.append((index, stamps_ns(times),
                                     _as_payloads(publisher.serialize(piece))))
        if piece.last:
            self._write(None)
            return
        # A later piece's messages are stamped at or after its first tick's start, less
        # a nanosecond's rounding and odometry's one tick of lag: a tick more is safe.
        self._write(int(stamps_ns(np.array([(piece.first_tick + piece.plan.ticks - 1)
                                            * piece.plan.dt_s]))[0]))

    def _write(self, before_ns: int | None) -> None:
        """Write the waiting messages stamped before ``before_ns`` (None: all), in time order.

        Equal stamps go in the order of the publishers, then in the order they came.
        """
        ready, kept = [], []
        for publisher, times, rows in self.waiting:  # each block's ready messages lead it
            count = len(times) if before_ns is None else int(np.searchsorted(times, before_ns))
            ready.append((publisher, times[:count], rows.part(0, count)))
            if count < len(times):
                kept.append((publisher, times[count:], rows.part(count, len(times))))
        self.waiting = kept
        counts = [len(times) for _, times, _ in ready]
        if not sum(counts):
            return
        stamp = np.concatenate([times for _, times, _ in ready])
        source = np.repeat([publisher for publisher, _, _ in ready], counts)
        order = np.lexsort((np.arange(len(stamp)), source, stamp))
        blocks: list[ByteRows] = []
        block = []
        for _, _, rows in ready:
            block.append(rows.block + len(blocks))
            blocks += rows.blocks
        payloads = Payloads(blocks, np.concatenate(block)[order],
                            np.concatenate([rows.row for _, _, rows in ready])[order])
        channels, stamps = self.channel[source[order]], stamp[order]
        sequences = np.empty(len(stamps), dtype=np.int64)
        for channel in np.flatnonzero(np.bincount(channels)).tolist():
            mine = np.flatnonzero(channels == channel)
            sequences[mine] = self.sequences[channel] + np.arange(len(mine))
            self.sequences[channel] += len(mine)
        self.mcap.add(channels, sequences, stamps, payloads)
        self.start_ns = int(stamps[0]) if self.start_ns is None else self.start_ns
        self.end_ns = max(self.end_ns, int(stamps.max()))

    def finish(self, summary: object = None) -> None:
        """Write what waits, the file's summary and ``metadata.yaml`` (``summary`` unused)."""
        self._write(None)
        self.mcap.finish()
        counts = [int(n) for n in self.sequences]
        (self.directory / "metadata.yaml").write_text(
            _metadata(self.file_name, self.topics, counts, self.start_ns or 0, self.end_ns),
            encoding="utf-8")


def _as_payloads(rows: ByteRows | Payloads) -> Payloads:
    """Messages of one size as :class:`Payloads` of one block."""
    if isinstance(rows, Payloads):
        return rows
    return Payloads([rows], np.zeros(len(rows), dtype=np.int64),
                    np.arange(len(rows), dtype=np.int64))


def _channel(topic: Topic) -> Channel:
    return Channel(topic=topic.name, message_encoding="cdr", schema_name=topic.type,
                   schema_encoding="ros2msg",
                   schema_data=MESSAGE_DEFINITIONS[topic.type].encode(),
                   metadata={"offered_qos_profiles": offered_qos_profiles(topic.offered_qos)})


def _metadata(file_name: str, topics: list[Topic], counts: list[int], start: int,
              end: int) -> str:
    total = sum(counts)
    lines = ["rosbag2_bagfile_information:", "  version: 5", "  storage_identifier: mcap",
             "  duration:", f"    nanoseconds: {end - start}", "  starting_time:",
             f"    nanoseconds_since_epoch: {start}", f"  message_count: {total}",
             "  topics_with_message_count:"]
    for topic, count in zip(topics, counts, strict=True):
        lines += ["    - topic_metadata:", f"        name: {topic.name}",
                  f"        type: {topic.type}", "        serialization_format: cdr",
                  "        offered_qos_profiles: "
                  + _quoted(offered_qos_profiles(topic.offered_qos)),
                  f"      message_count: {count}"]
    lines += ['  compression_format: ""', '  compression_mode: ""', "  relative_file_paths:",
              f"    - {file_name}", "  files:", f"    - path: {file_name}",
              "      starting_time:", f"        nanoseconds_since_epoch: {start}",
              "      duration:", f"        nanoseconds: {end - start}",
              f"      message_count: {total}"]
    return "\n".join(lines) + "\n"


def _quoted(text: str) -> str:
    """A YAML double-quoted scalar."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
