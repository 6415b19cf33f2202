"""One module per generated family; each exposes family() -> spec.Family."""

import importlib

FAMILY_MODULES = ["line_rows", "point_rows", "beta_constraints", "beta_n4", "rig_rows"]


def all_families():
    return [importlib.import_module(f"{__name__}.{m}").family() for m in FAMILY_MODULES]
