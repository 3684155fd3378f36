"""``[material]``: the sheet's calibration (``"auto"`` from E, nu and the thickness, or
``"manual"`` stiffnesses), or a named preset; with ``density``, the sheet's mass."""

from __future__ import annotations

from kresling.model import ManualProperties, SheetMaterial
from kresling.model.material_presets import MATERIAL_PRESETS
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_keys.mass import SheetMass, read_sheet_mass
from kresling.simulate.problem_table import (boolean, number, quantities, quantity, stiffnesses,
                                             string)

__all__ = ["KEY", "MATERIAL_KEY_OF_FIELD"]

#: The problem file's key of each field of the material (the model's messages name fields).
MATERIAL_KEY_OF_FIELD = {"youngs_modulus": "E", "poisson_ratio": "nu", "thickness": "thickness",
                         "length_scale": "length_scale", "bar_modulus": "bar_modulus",
                         "bar_area": "bar_area", "fold_stiffness": "fold_stiffness",
                         "bend_stiffness": "bend_stiffness", "face_stiffness": "face_stiffness"}


def read_material(t, context) -> dict:
    """The material (None for a preset: made with the pattern, whose size it scales with),
    MERLIN2's compatibility, the preset's name and the sheet's mass."""
    if t.has("preset"):
        name = t.get("preset", string, choices=tuple(MATERIAL_PRESETS))
        for key in ("calibration", "merlin2_compat"):
            if t.has(key):
                t.fail(key, f"does not go with preset = {name!r} (the preset is a manual "
                            "calibration of its own)")
        sheet_mass = read_sheet_mass(t, None)
        t.finish()
        return {"material": None, "merlin2_compat": False, "preset": name,
                "sheet_mass": sheet_mass}
    calibration = t.get("calibration", string, required=True, choices=("auto", "manual"))
    compat = t.get("merlin2_compat", boolean, False)
    if calibration == "auto":
        E = t.get("E", quantity, required=True, allowed="Young's modulus [N/mm^2]")
        nu = t.get("nu", number, required=True, allowed="Poisson's ratio in (-1, 0.5]")
        if not -1 < nu <= 0.5:
            t.fail("nu", f"= {nu!r} is invalid: must be in (-1, 0.5]")
        thickness = t.get("thickness", quantity, required=True, allowed="the thickness [mm]")
        length_scale = t.get("length_scale", quantity, None)
        material = SheetMaterial(E, nu, thickness, length_scale)
    else:
        material = ManualProperties(
            bar_modulus=t.get("bar_modulus", quantity, required=True,
                              allowed="the bars' modulus C0 [N/mm^2]"),
            bar_area=t.get("bar_area", quantities, required=True,
                           allowed="the bars' area [mm^2] (a number or one per bar)"),
            fold_stiffness=t.get("fold_stiffness", stiffnesses, None),
            bend_stiffness=t.get("bend_stiffness", stiffnesses, None),
            face_stiffness=t.get("face_stiffness", quantity, None))
    sheet_mass = read_sheet_mass(t, material)
    t.finish()
    return {"material": material, "merlin2_compat": compat, "preset": None,
            "sheet_mass": sheet_mass}


def _default(context):
    """A method that folds needs no [material]: it takes its own preset (Origami
    Simulator's for a fold, which folds what that simulator folds)."""
    preset = getattr(context.method, "default_preset", None)
    return {"preset": preset} if preset else None


def _required(context) -> bool:
    """A structure of ``[[bar]]`` members alone has no panels to calibrate (the pattern
    key refuses panels without a material)."""
    return _default(context) is None and "bar" not in context.given


KEY = ProblemKey("material", rank=10, read=read_material, default=_default,
                 required=_required, allowed="a table with the calibration (or a preset)",
                 absent={"material": None, "merlin2_compat": False, "preset": None,
                         "sheet_mass": SheetMass()})
