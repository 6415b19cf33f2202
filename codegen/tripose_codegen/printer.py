"""C++ printer: sympy's C++11 printer with exact, allocation-free output for our kernels.

Integer powers become products (no std::pow), rationals with a power-of-two denominator become
exact double literals, and long statements are wrapped at + and - so that the emitted code is
already formatted (no formatter in the loop, so the output depends only on sympy's version).
"""

import sympy
from sympy.printing.cxx import CXX11CodePrinter

LINE_LIMIT = 100
CONTINUATION_INDENT = 8


class KernelPrinter(CXX11CodePrinter):
    def _print_Pow(self, expr):
        base, exp = expr.base, expr.exp
        if exp.is_Integer and exp != 0:
            n = abs(int(exp))
            b = self.parenthesize(base, sympy.printing.precedence.PRECEDENCE["Mul"] + 1)
            product = "*".join([b] * n)
            if exp > 0:
                return product if n == 1 else f"({product})"
            return f"1.0/{product}" if n == 1 else f"1.0/({product})"
        if exp == sympy.S.Half:
            return f"std::sqrt({self._print(base)})"
        if exp == -sympy.S.Half:
            return f"1.0/std::sqrt({self._print(base)})"
        raise ValueError(f"unsupported power in a generated kernel: {expr}")

    def _print_Rational(self, expr):
        p, q = int(expr.p), int(expr.q)
        if q & (q - 1) == 0:  # Exact in binary floating point.
            return repr(p / q)
        return f"({p}.0/{q}.0)"

    def _print_Integer(self, expr):
        return str(int(expr))

    def _print_Float(self, expr):
        return repr(float(expr))


_printer = KernelPrinter()


def print_expr(expr: sympy.Expr) -> str:
    return _printer.doprint(expr)


def wrap_statement(text: str, indent: int) -> str:
    """Breaks @p text (one statement, without indentation) before a binary + or - so that lines
    stay within LINE_LIMIT where possible."""
    lines = []
    first = True
    while True:
        prefix = " " * (indent if first else indent + CONTINUATION_INDENT)
        room = LINE_LIMIT - len(prefix)
        if len(text) <= room:
            lines.append(prefix + text)
            break
        cut = max(text.rfind(" + ", 0, room), text.rfind(" - ", 0, room))
        if cut <= 0:
            cut = min((i for i in (text.find(" + ", room), text.find(" - ", room)) if i > 0), default=-1)
        if cut <= 0:
            lines.append(prefix + text)
            break
        lines.append(prefix + text[:cut])
        text = text[cut + 1:]
        first = False
    return "\n".join(lines)
