"""Common-subexpression elimination and ordering of one kernel's assignments.

sympy.cse runs over the staged intermediates and the outputs together, so a subexpression shared
between stages is computed once. The result is ordered topologically (ties broken by the order in
which cse and the spec produced the nodes, never by hashes) and the temporaries are renamed
_tmp0, _tmp1, ... in emission order, which makes the output byte-stable.
"""

import heapq
from dataclasses import dataclass
from typing import Dict, List, Tuple

import sympy

from .spec import Kernel


@dataclass
class Program:
    """Straight-line code: `temporaries` in order, then `outputs[(array, index)] = expr`."""

    kernel: Kernel
    temporaries: List[Tuple[sympy.Symbol, sympy.Expr]]
    outputs: List[Tuple[str, int, sympy.Expr]]


def _topological_order(nodes: List[Tuple[sympy.Symbol, sympy.Expr]]) -> List[int]:
    """Indices of @p nodes so that every node comes after the nodes it reads; among the ready
    ones, the earliest in the input list goes first (deterministic)."""
    index_of = {symbol: i for i, (symbol, _) in enumerate(nodes)}
    readers: List[List[int]] = [[] for _ in nodes]
    pending = [0] * len(nodes)
    for i, (_, expr) in enumerate(nodes):
        deps = sorted({index_of[s] for s in expr.free_symbols if s in index_of})
        pending[i] = len(deps)
        for d in deps:
            readers[d].append(i)
    ready = [i for i in range(len(nodes)) if pending[i] == 0]
    heapq.heapify(ready)
    order = []
    while ready:
        i = heapq.heappop(ready)
        order.append(i)
        for r in readers[i]:
            pending[r] -= 1
            if pending[r] == 0:
                heapq.heappush(ready, r)
    if len(order) != len(nodes):
        raise ValueError("cyclic intermediates")
    return order


def build_program(kernel: Kernel) -> Program:
    let_symbols = [s for s, _ in kernel.lets]
    flat_outputs = [(array.name, i, e) for array, exprs in kernel.outputs for i, e in enumerate(exprs)]
    exprs = [e for _, e in kernel.lets] + [e for _, _, e in flat_outputs]

    replacements, reduced = sympy.cse(exprs, symbols=sympy.numbered_symbols("_cse", real=True))
    nodes = list(replacements) + list(zip(let_symbols, reduced[: len(let_symbols)]))
    output_exprs = reduced[len(let_symbols):]

    # A node that is only a copy of another symbol is substituted away.
    aliases: Dict[sympy.Symbol, sympy.Expr] = {}
    kept = []
    for symbol, expr in nodes:
        if expr.is_Symbol or expr.is_Number:
            aliases[symbol] = expr
        else:
            kept.append((symbol, expr))
    if aliases:
        # Aliases may chain (a -> b -> c): resolve to a fixed point.
        changed = True
        while changed:
            changed = False
            for s, e in aliases.items():
                r = e.xreplace(aliases)
                if r != e:
                    aliases[s] = r
                    changed = True
        kept = [(s, e.xreplace(aliases)) for s, e in kept]
        output_exprs = [e.xreplace(aliases) for e in output_exprs]

    # Drop nodes that no output needs (a stage may compute more than the outputs use).
    needed = set()
    by_symbol = dict(kept)
    stack = [s for e in output_exprs for s in e.free_symbols if s in by_symbol]
    while stack:
        s = stack.pop()
        if s in needed:
            continue
        needed.add(s)
        stack.extend(d for d in by_symbol[s].free_symbols if d in by_symbol)
    kept = [(s, e) for s, e in kept if s in needed]

    order = _topological_order(kept)
    rename = {kept[i][0]: sympy.Symbol(f"_tmp{k}", real=True) for k, i in enumerate(order)}
    temporaries = [(rename[kept[i][0]], kept[i][1].xreplace(rename)) for i in order]
    outputs = [(name, i, e.xreplace(rename)) for (name, i, _), e in zip(flat_outputs, output_exprs)]
    return Program(kernel, temporaries, outputs)


@dataclass
class OpCount:
    adds: int = 0
    muls: int = 0
    divs: int = 0
    sqrts: int = 0

    def __iadd__(self, other: "OpCount") -> "OpCount":
        self.adds += other.adds
        self.muls += other.muls
        self.divs += other.divs
        self.sqrts += other.sqrts
        return self

    @property
    def total(self) -> int:
        return self.adds + self.muls + self.divs + self.sqrts


def count_ops(expr: sympy.Expr) -> OpCount:
    """Floating-point operations of @p expr as printer.py prints it (a sign change is free: it
    folds into an addition or a constant)."""
    c = OpCount()
    if expr.is_Atom:
        return c
    if expr.is_Add:
        c.adds += len(expr.args) - 1
    elif expr.is_Mul:
        factors = [a for a in expr.args if a not in (sympy.S.NegativeOne,)]
        divisors = [a for a in factors if a.is_Pow and a.exp.is_Rational and a.exp < 0]
        c.muls += max(len(factors) - 1 - len(divisors), 0)
        c.divs += len(divisors)
        for d in divisors:
            c += count_ops(1 / d) if d.exp != -1 else count_ops(d.base)
        for a in factors:
            if a not in divisors:
                c += count_ops(a)
        return c
    elif expr.is_Pow:
        if expr.exp.is_Integer and expr.exp > 0:
            c.muls += int(expr.exp) - 1
        elif expr.exp.is_Integer and expr.exp < 0:
            c.divs += 1
            c.muls += int(-expr.exp) - 1
        elif abs(expr.exp) == sympy.S.Half:
            c.sqrts += 1
            c.divs += 1 if expr.exp < 0 else 0
        else:
            raise ValueError(f"unsupported power {expr}")
        c += count_ops(expr.base)
        return c
    else:
        raise ValueError(f"unsupported node {expr.func}")
    for a in expr.args:
        c += count_ops(a)
    return c


def program_op_count(program: Program) -> OpCount:
    total = OpCount()
    for _, e in program.temporaries:
        total += count_ops(e)
    for _, _, e in program.outputs:
        total += count_ops(e)
    return total
