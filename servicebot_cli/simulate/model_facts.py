"""What the simulator reads from the Pinocchio model, worked out while the rest is loaded.

The simulator needs three things of the shared model: that it builds (the validation every
command's loading does, here with the planar base the simulator uses), the joint space of
that model, and where each link sits on the base in the neutral configuration (the sensors'
mounts). Importing Pinocchio and building the model take about 60 ms, a seventh of a default
run from a cold process. With a second core, a forked process
(:mod:`~servicebot_cli.common.forked`) works them out while the parent reads the scenario,
the controllers and the robot's shape; only arrays come back. Without one, they are worked
out in-process when first asked for.

That process then imports the modules the run's pose work will use, and the simulator hands
it that work (:meth:`FactsAhead.take_over`): it has Pinocchio and Coal loaded already, which
a process forked for the pose work would spend its first 35 ms importing while the
simulator waits for its first piece.
"""

from __future__ import annotations

import contextlib
import io
import pickle
import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from types import BuiltinFunctionType, FunctionType, TracebackType
from typing import TYPE_CHECKING, Any, TypeVar

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import DescriptionError, ServicebotError
from servicebot_cli.common.forked import Worker, WorkerEnded, prepare_quietly, second_core
from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.description.model import new_data

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]
HANDOVER_BYTES = 4 << 20
"""Work that pickles to more than this is left to a newly forked worker, which shares it."""
J = TypeVar("J")
R = TypeVar("R")


@dataclass(frozen=True)
class ModelFacts:
    """The model's facts the simulator uses.

    Attributes:
        joint_space: Movable joints of the planar-base model (one Pinocchio configuration).
        placements: Each link's ``transform_link_to_base`` (4, 4) in the neutral
            configuration, with the base at the origin.
    """

    joint_space: JointSpace
    placements: dict[str, FloatArray]


def model_facts(robot: RobotDescription) -> ModelFacts:
    """Build ``robot``'s planar-base model and read the facts from it.

    Raises:
        DescriptionError: Pinocchio cannot build the description.
    """
    import pinocchio as pin

    model = robot.model_with_base("planar")  # refused as the fixed-base one of loading is
    space = JointSpace.of(model, robot.movable_joints)
    try:
        data = new_data(model, robot.display)  # refused beyond what fits in memory
    except MemoryError:  # its tables grow steeply: 10.8 GB for a chain of 550 joints
        raise DescriptionError(
            f"{robot.display}: too large to simulate: Pinocchio's data for its {len(space.names)}"
            " joints does not fit in this machine's memory") from None
    pin.framesForwardKinematics(model, data, space.neutral())
    # Pinocchio's data.oMf[i] is transform_frame_to_world; the base sits at the origin.
    placements = {frame.name: np.array(data.oMf[i].homogeneous)
                  for i, frame in enumerate(model.frames) if frame.type == pin.BODY}
    return ModelFacts(space, placements)


class FactsAhead:
    """:func:`model_facts` of a robot, begun now in a forked process when that saves time.

    Forked (``fork`` None) only when Pinocchio is not imported yet (else building is quick)
    and a second core is free. :meth:`result` gives the facts (or raises the description's
    error, each time it is asked); :meth:`close` stops the process whatever happened.

    Once the facts are sent, the process imports ``then_import`` (the modules of the work to
    come), and can be handed that work (:meth:`take_over`).
    """

    def __init__(self, robot: RobotDescription, *, fork: bool | None = None,
                 then_import: tuple[str, ...] = ()) -> None:
        forked = ("pinocchio" not in sys.modules and second_core()) if fork is None else fork
        self._facts: ModelFacts | None = None
        self._error: Exception | None = None
        self._handed_over = False
        # the packages the process has: those here at the fork, and those it imports then
        self._packages = {name.partition(".")[0] for name in (*sys.modules, *then_import)}
        try:
            self._worker: Worker[Any, Any] = Worker(_Process(robot), forked=forked,
                                                    name="model-building")
        except OSError:  # no process to be had: in-process, when asked
            self._worker = Worker(_Process(robot), forked=False)
        self._worker.submit(None)
        if self._worker.pid is not None and then_import:  # while the caller reads on
            self._worker.submit(_Imports(then_import))
            self._worker.drop_result()

    def result(self) -> ModelFacts:
        """The facts, waited for the first time.

        Raises:
            DescriptionError: Pinocchio cannot build the description.
            WorkerEnded: The process was killed from outside.
        """
        if self._facts is None:
            if self._error is not None:
                raise self._error
            try:
                self._facts = self._worker.result()
            except Exception as exc:  # the same error each time it is asked for
                self._error = exc
                raise
            finally:  # Ctrl-C or a signal while waiting: the process is killed, not waited for
                if self._facts is None:
                    self._worker.close()
        return self._facts

    def take_over(self, function: Callable[[J], R], prepare: Callable[[], object] | None,
                  name: str) -> Worker[J, R] | None:
        """The forked process, doing ``function``'s jobs from now on, once the facts are in.

        ``function`` (with all it holds) is pickled across, so it must not be used here
        while the worker lives; ``prepare`` is done there before the first job. None when
        that is no gain, and the caller forks its own worker, which shares this process's
        memory as it is: no such process (not forked, failed, taken over already), work
        that does not pickle, or that pickles to more than :data:`HANDOVER_BYTES` (a world of
        meshes) or names a package the process has not imported (trimesh, for a mesh
        obstacle: most of a second to import there). The process is then stopped.

        Raises:
            DescriptionError: Pinocchio cannot build the description.
        """
        self.result()
        worker = self._worker
        if worker.pid is None or self._handed_over:
            return None
        self._handed_over = True
        pickled = _pickled(_Handover(function, prepare))
        if pickled is None or len(pickled[0]) > HANDOVER_BYTES or pickled[1] - self._packages:
            worker.close()
            return None
        data = pickled[0]
        try:
            worker.submit_pickled(data)
        except WorkerEnded:  # killed meanwhile: the caller forks its own
            worker.close()
            return None
        worker.drop_result()
        worker.name = name
        return worker

    def close(self) -> None:
        """Stop the process if it still runs; it ends by itself once its work is done."""
        if not self._handed_over:
            self._worker.no_more_jobs()
        self._worker.close(finished=self._facts is not None or self._error is not None)

    def __enter__(self) -> FactsAhead:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 traceback: TracebackType | None) -> None:
        self.close()


@contextlib.contextmanager
def description_first(ahead: FactsAhead) -> Iterator[None]:
    """A user's error raised inside comes after the description's own, if it has one.

    Loading builds the model before anything else is read; so the model's error is the one
    reported when both are wrong, whichever step finds its own error first. Anything else
    that stops the model's process (it was killed, no memory) leaves the step's error first.
    """
    try:
        yield
    except ServicebotError:
        try:
            ahead.result()
        except DescriptionError:
            raise
        except Exception:  # noqa: BLE001,S110 -- not the description's error: the step's first
            pass
        raise


def _pickled(work: object) -> tuple[bytes, set[str]] | None:
    """``work`` pickled, and the packages of the classes and functions it names.

    None when it does not pickle.
    """
    stream = io.BytesIO()
    pickler = _NamingPickler(stream)
    try:
        pickler.dump(work)
    except Exception:  # noqa: BLE001 -- whatever pickling it raised: it stays here
        return None
    return stream.getvalue(), {module.partition(".")[0] for module in pickler.modules}


class _NamingPickler(pickle.Pickler):
    """A pickler that notes the module of each object's class (of each class or function)."""

    def __init__(self, stream: io.BytesIO) -> None:
        super().__init__(stream, protocol=pickle.HIGHEST_PROTOCOL)
        self.modules: set[str] = set()

    def reducer_override(self, obj: object) -> Any:
        named = obj if isinstance(obj, (type, FunctionType, BuiltinFunctionType)) else type(obj)
        self.modules.add(getattr(named, "__module__", None) or "builtins")
        return NotImplemented  # pickled as usual


@dataclass(frozen=True)
class _Handover:
    """The work the process does from its next job on."""

    function: Callable[[Any], Any]
    prepare: Callable[[], object] | None


@dataclass(frozen=True)
class _Imports:
    """Modules the work to be handed over will use, imported once the facts are sent."""

    modules: tuple[str, ...]


class _Process:
    """What the forked process does: the facts (job None), then the work handed over."""

    def __init__(self, robot: RobotDescription) -> None:
        self.robot = robot
        self.work: Callable[[Any], Any] | None = None

    def __call__(self, job: Any) -> Any:
        if job is None:
            return model_facts(self.robot)
        if isinstance(job, _Imports):
            import importlib

            for name in job.modules:
                with contextlib.suppress(ImportError):  # the handover meets it, and says so
                    importlib.import_module(name)
            return None
        if isinstance(job, _Handover):
            self.work = job.function
            prepare_quietly(job.prepare)
            return None
        assert self.work is not None  # handed over before its first job
        return self.work(job)
