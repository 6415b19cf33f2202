"""One module per generated family; each exposes family() -> spec.Family."""

import importlib

# The slowest family first: generate.py hands them out in this order to two workers, and
# affine_constraints takes about as long as all the others together.
FAMILY_MODULES = ["affine_constraints", "line_rows", "point_rows", "beta_constraints", "beta_n4",
                  "rig_rows"]


def all_families():
    return [importlib.import_module(f"{__name__}.{m}").family() for m in FAMILY_MODULES]
