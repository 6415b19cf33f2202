"""Symbolic derivation of tripose's coefficient kernels and their C++ emission.

Pipeline (one pass per kernel): a problem spec (specs/) builds sympy expressions for the outputs,
possibly in stages of named intermediates; cse.py eliminates common subexpressions and orders the
assignments; printer.py prints C++; render.py fills the templates (templates/).
"""
