"""Runs a kernel's straight-line program in Python (for tests and measurements).

The program is the one the C++ printer emits (same temporaries, same order), printed as Python,
so tests exercise the spec and the common-subexpression elimination together. Inputs may be
floats (double precision, like the C++ kernel) or mpmath numbers (a high-precision reference).
"""

import math
from typing import Callable, Dict

import numpy as np
import sympy
from sympy.printing.pycode import PythonCodePrinter

from .cse import Program, build_program
from .spec import Kernel


class _Printer(PythonCodePrinter):
    def _print_Pow(self, expr, rational=False):
        if expr.exp == sympy.S.Half:
            return f"sqrt({self._print(expr.base)})"
        if expr.exp == -sympy.S.Half:
            return f"(1/sqrt({self._print(expr.base)}))"
        return super()._print_Pow(expr, rational)


def compile_program(program: Program, sqrt=math.sqrt) -> Callable[..., Dict[str, list]]:
    """f(**inputs) -> {output name: list of values}; inputs are sequences indexed like the C arrays."""
    kernel = program.kernel
    printer = _Printer()
    names = [a.name for a, _ in kernel.inputs]
    lines = [f"def _kernel({', '.join(names)}):"]
    for array, _ in kernel.outputs:
        lines.append(f"    {array.name} = [None] * {array.size}")
    for symbol, expr in program.temporaries:
        lines.append(f"    {symbol.name} = {printer.doprint(expr)}")
    for name, i, expr in program.outputs:
        lines.append(f"    {name}[{i}] = {printer.doprint(expr)}")
    lines.append("    return {" + ", ".join(f"'{a.name}': {a.name}" for a, _ in kernel.outputs) + "}")
    namespace = {"sqrt": sqrt}
    exec("\n".join(lines), namespace)
    kernel_fn = namespace["_kernel"]

    def run(**inputs):
        return kernel_fn(**{n: list(inputs[n]) for n in names})

    return run


def numeric_kernel(kernel: Kernel) -> Callable[..., Dict[str, np.ndarray]]:
    """Double-precision evaluation: f(**inputs) -> {output name: float64 array}."""
    run = compile_program(build_program(kernel))

    def f(**inputs):
        out = run(**{k: [float(x) for x in np.ravel(v)] for k, v in inputs.items()})
        return {k: np.array([float(x) for x in v]) for k, v in out.items()}

    return f
