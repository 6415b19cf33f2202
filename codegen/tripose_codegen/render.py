"""Fills the templates (templates/*.in, string.Template) with a family's printed kernels."""

import textwrap
from pathlib import Path
from string import Template
from typing import Dict

from .cse import Program, build_program, count_ops, program_op_count
from .printer import CONTINUATION_INDENT, LINE_LIMIT, print_expr, wrap_statement
from .spec import Family

TEMPLATE_DIR = Path(__file__).resolve().parent / "templates"
TEMPLATE_DIR_IN_REPO = "codegen/tripose_codegen/templates"
COMMAND = "python3 codegen/generate.py"

LICENCE = """\
// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html."""


def _template(name: str) -> Template:
    return Template((TEMPLATE_DIR / name).read_text().rstrip("\n") + ("\n" if name.endswith((".hpp.in", ".cpp.in")) else ""))


def _banner(family: Family, template: str) -> str:
    return "\n".join([
        "//",
        "// GENERATED FILE: do not edit by hand.",
        f"// Produced by `{COMMAND}` from the problem spec",
        f"//   {family.spec_module}",
        f"// through the template {TEMPLATE_DIR_IN_REPO}/{template}.",
        "// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file",
        "// is up to date.",
    ])


def _comment_block(text: str, prefix: str = "") -> str:
    lines = textwrap.dedent(text).strip("\n").splitlines()
    return "\n".join((prefix + line).rstrip() for line in lines)


def _signature(program: Program) -> str:
    """The parameter list, wrapped after a comma when `void name(...);` would pass LINE_LIMIT."""
    kernel = program.kernel
    params = [f"const double* {a.name}" for a, _ in kernel.inputs]
    params += [f"double* {a.name}" for a, _ in kernel.outputs]
    lines = []
    line = f"void {kernel.name}("
    start = len(line)
    for i, p in enumerate(params):
        piece = p + (", " if i + 1 < len(params) else ");")
        if len(line) + len(piece.rstrip()) > LINE_LIMIT and len(line) > start:
            lines.append(line.rstrip())
            line = " " * CONTINUATION_INDENT
        line += piece
    lines.append(line)
    return "\n".join(lines)[len(f"void {kernel.name}("):-2]


def _op_count_comment(program: Program) -> str:
    c = program_op_count(program)
    parts = [f"{c.muls} mul", f"{c.adds} add", f"{c.divs} div"]
    if c.sqrts:
        parts.append(f"{c.sqrts} sqrt")
    return f"Operation count: {', '.join(parts)} (total {c.total})."


def _body(program: Program) -> str:
    lines = []
    for symbol, expr in program.temporaries:
        lines.append(wrap_statement(f"const double {symbol.name} = {print_expr(expr)};", 4))
    for name, i, expr in program.outputs:
        lines.append(wrap_statement(f"{name}[{i}] = {print_expr(expr)};", 4))
    return "\n".join(lines)


def _declaration(program: Program) -> str:
    kernel = program.kernel
    params = []
    for array, _ in kernel.inputs:
        params.append(f"@param {array.name} input, {array.size} doubles: {array.doc}")
    for array, _ in kernel.outputs:
        params.append(f"@param {array.name} output, {array.size} doubles: {array.doc}")
    return _template("declaration.in").substitute(
        doc=_comment_block(kernel.doc).replace("\n", "\n"),
        params="\n".join(params),
        name=kernel.name,
        signature=_signature(program),
    )


def render_family(family: Family) -> Dict[str, str]:
    """Returns {file name: contents} for the family's header and source."""
    programs = [build_program(k) for k in family.kernels]
    guard = f"OPENCV_TRIPOSE_GENERATED_{family.stem.upper()}_HPP"
    header = _template("header.hpp.in").substitute(
        licence=LICENCE,
        banner=_banner(family, "header.hpp.in"),
        guard=guard,
        family_doc=_comment_block(family.title + "\n\n" + textwrap.dedent(family.doc).strip("\n")),
        declarations="\n\n".join(_declaration(p) for p in programs),
    )
    definitions = "\n\n".join(
        _template("definition.in").substitute(
            name=p.kernel.name,
            signature=_signature(p),
            op_count=_op_count_comment(p),
            body=_body(p),
        )
        for p in programs)
    source = _template("source.cpp.in").substitute(
        licence=LICENCE,
        banner=_banner(family, "source.cpp.in"),
        stem=family.stem,
        includes="\n#include <cmath>" if "std::sqrt" in definitions else "",
        definitions=definitions,
    )
    return {f"{family.stem}.hpp": header, f"{family.stem}.cpp": source}
