"""Problem specs: the symbolic description of one generated kernel.

A kernel has named input arrays (flat, row-major, one sympy Symbol per entry), named output arrays
(one sympy expression per entry) and optionally a list of staged intermediates ("lets"): symbols
with a defining expression, used when a derivation is cheaper to express in steps than as one
expanded formula (e.g. the memoized minors of the N = 4 null vector). Intermediates become
temporaries of the generated code; they are never expanded into the outputs.
"""

from dataclasses import dataclass, field
from typing import List, Sequence, Tuple

import sympy


def join_doc(*pieces: str) -> str:
    """Dedents each piece of a docstring-like text and joins them with blank lines."""
    import textwrap

    return "\n\n".join(textwrap.dedent(p).strip("\n") for p in pieces)


@dataclass
class Array:
    """A flat C array argument: `name[i]` is the entry `symbols[i]` (inputs) or `exprs[i]` (outputs)."""

    name: str
    size: int
    doc: str


@dataclass
class Kernel:
    """One generated C++ function `void name(const double* in..., double* out...)`."""

    name: str
    doc: str  # Header comment: the exact equations and the layouts.
    inputs: List[Tuple[Array, List[sympy.Symbol]]] = field(default_factory=list)
    outputs: List[Tuple[Array, List[sympy.Expr]]] = field(default_factory=list)
    lets: List[Tuple[sympy.Symbol, sympy.Expr]] = field(default_factory=list)

    def input(self, name: str, size: int, doc: str) -> List[sympy.Symbol]:
        symbols = [sympy.Symbol(f"{name}[{i}]", real=True) for i in range(size)]
        self.inputs.append((Array(name, size, doc), symbols))
        return symbols

    def output(self, name: str, exprs: Sequence[sympy.Expr], doc: str) -> None:
        exprs = [sympy.sympify(e) for e in exprs]
        self.outputs.append((Array(name, len(exprs), doc), exprs))

    def let(self, expr: sympy.Expr) -> sympy.Expr:
        """Names @p expr as a staged intermediate and returns its symbol (numbers and symbols pass
        through unchanged: naming them would only add copies)."""
        expr = sympy.sympify(expr)
        if expr.is_Number or expr.is_Symbol:
            return expr
        symbol = sympy.Symbol(f"_let{len(self.lets)}", real=True)
        self.lets.append((symbol, expr))
        return symbol

    def input_symbols(self) -> List[sympy.Symbol]:
        return [s for _, symbols in self.inputs for s in symbols]

    def inlined_outputs(self) -> List[List[sympy.Expr]]:
        """The outputs with every intermediate substituted (for tests on small kernels)."""
        values = {}
        for symbol, expr in self.lets:
            values[symbol] = expr.xreplace(values)
        return [[e.xreplace(values) for e in exprs] for _, exprs in self.outputs]


@dataclass
class Family:
    """Kernels emitted together into src/generated/<stem>.hpp and <stem>.cpp."""

    stem: str
    title: str
    doc: str
    spec_module: str  # Path of the spec file, named in the banner.
    kernels: List[Kernel]
