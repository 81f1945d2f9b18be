"""Bounds on what one xacro expansion may compute, so a hostile file ends in one error.

xacro evaluates ``${...}`` as Python and expands macros without limit, so a few lines can
ask for more than any machine has: macros that each call the next twice (xacro's billion
laughs), properties that each double the one before, ``${9**9**9}`` or ``${'a' * 10**10}``.
ROS's own xacro runs them until memory or patience ends. Here:

* :func:`guarded_safe_eval` is xacro's ``safe_eval`` with ``**``, ``*`` and ``<<`` checked
  before Python computes them: a result over :data:`MAX_INT_BITS` bits or
  :data:`MAX_TEXT` items is refused;
* :func:`bounded_eval_text` refuses a text value longer than :data:`MAX_TEXT` characters;
* :class:`MacroBudget` refuses more than :data:`MAX_MACRO_CALLS` macro calls.

Real descriptions stay far below every bound (a 32 MB URDF is refused anyway). Python's
``eval`` cannot be bounded in general (``math.factorial(10**8)``, ``sum(range(10**12))``);
these bounds cover the ways a file grows without end.
"""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Callable, Sized
from typing import Any

MAX_MACRO_CALLS = 20_000
"""Most macro calls one expansion makes; large real robots make a few hundred."""
MAX_TEXT = 10_000_000
"""Longest text (or list) an expression or attribute may produce [characters or items]."""
MAX_INT_BITS = 100_000
"""Largest integer an expression may compute [bits] (about 30,000 decimal digits)."""

_POW = "servicebot_guarded_pow_"
_MUL = "servicebot_guarded_mul_"
_LSHIFT = "servicebot_guarded_lshift_"


class ExpansionTooLarge(Exception):
    """An expression or the expansion went past one of the bounds; the message says which."""


def _int_bits(value: object) -> float:
    """Bits of an integer operand (bools count as 1), or 0 for anything else."""
    if isinstance(value, int):
        return max(1, abs(value).bit_length())
    return 0


def _pow(base: Any, exponent: Any) -> Any:
    if (isinstance(base, int) and isinstance(exponent, int) and exponent > 1
            and abs(base) > 1 and exponent * math.log2(abs(base)) > MAX_INT_BITS):
        raise ExpansionTooLarge(f"{base} ** {exponent} has over {MAX_INT_BITS} bits; "
                                "use a float (e.g. 9.0 ** 9) or a smaller number")
    return operator.pow(base, exponent)


def _mul(left: Any, right: Any) -> Any:
    for items, count in ((left, right), (right, left)):
        if (isinstance(items, (str, bytes, list, tuple)) and isinstance(count, int)
                and len(items) * count > MAX_TEXT):
            raise ExpansionTooLarge(f"repeating {type(items).__name__} of {len(items)} items "
                                    f"{count} times is over {MAX_TEXT} items")
    if _int_bits(left) + _int_bits(right) > MAX_INT_BITS:
        raise ExpansionTooLarge(f"a product of over {MAX_INT_BITS} bits")
    return operator.mul(left, right)


def _lshift(value: Any, shift: Any) -> Any:
    if isinstance(value, int) and isinstance(shift, int) and shift > MAX_INT_BITS:
        raise ExpansionTooLarge(f"{value} << {shift} has over {MAX_INT_BITS} bits")
    return operator.lshift(value, shift)


GUARDS: dict[str, Callable[[Any, Any], Any]] = {_POW: _pow, _MUL: _mul, _LSHIFT: _lshift}
"""The checked operators, by the names expressions call them under (added to xacro's
global symbols while an expansion runs)."""

_GUARDED = {ast.Pow: _POW, ast.Mult: _MUL, ast.LShift: _LSHIFT}


class _Guard(ast.NodeTransformer):
    """``a ** b`` to ``servicebot_guarded_pow_(a, b)``, and the same for ``*`` and ``<<``."""

    def visit_BinOp(self, node: ast.BinOp) -> ast.AST:  # noqa: N802 (ast's visitor names)
        self.generic_visit(node)
        name = _GUARDED.get(type(node.op))
        if name is None:
            return node
        call = ast.Call(func=ast.Name(id=name, ctx=ast.Load()), args=[node.left, node.right],
                        keywords=[])
        return ast.copy_location(call, node)


def guarded_safe_eval(exception: type[Exception]) -> Callable[..., Any]:
    """The ``safe_eval`` of xacro with the guarded operators; ``exception`` is XacroException."""

    def safe_eval(expr: str, globals: dict[str, Any], locals: Any = None) -> Any:  # noqa: A002
        tree = ast.parse(expr.strip(), "<expression>", "eval")
        code = compile(ast.fix_missing_locations(_Guard().visit(tree)), "<expression>", "eval")
        invalid = [n for n in code.co_names if n.startswith("__")]
        if invalid:  # as xacro: no dunder names
            raise exception("Use of invalid name(s): ", ", ".join(invalid))
        globals.update(__builtins__={})  # as xacro: no builtins
        return eval(code, globals, locals)  # noqa: S307 (xacro's own evaluation, guarded)

    return safe_eval


def bounded_eval_text(eval_text: Callable[[str, Any], Any]) -> Callable[[str, Any], Any]:
    """The ``eval_text`` of xacro, refusing a value longer than :data:`MAX_TEXT`."""

    def wrapper(text: str, symbols: Any) -> Any:
        value = eval_text(text, symbols)
        if isinstance(value, (str, bytes, list, tuple)) and len(value) > MAX_TEXT:
            raise ExpansionTooLarge(_too_long(value))
        return value

    return wrapper


def _too_long(value: Sized) -> str:
    return (f"a value of over {MAX_TEXT} characters ({len(value)}); does a property repeat "
            "another that repeats one before it?")


class MacroBudget:
    """Counts macro calls; refuses the call past :data:`MAX_MACRO_CALLS`."""

    def __init__(self) -> None:
        self.calls = 0

    def wrap(self, handle_macro_call: Callable[..., bool]) -> Callable[..., bool]:
        """The ``handle_macro_call`` of xacro, counting the calls it handles."""

        def wrapper(node: Any, *args: Any) -> bool:
            handled = handle_macro_call(node, *args)
            if handled:
                self.calls += 1
                if self.calls > MAX_MACRO_CALLS:
                    raise ExpansionTooLarge(
                        f"over {MAX_MACRO_CALLS} macro calls; does a macro call itself or "
                        "another more than once, over and over? Expansion stopped")
            return handled

        return wrapper
