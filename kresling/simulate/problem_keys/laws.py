"""``[laws]``: the constitutive law of the bars and of each hinge family (fold, bend and the
crease families of a pattern), with its linear range and stiffness."""

from __future__ import annotations

from kresling.laws import BAR_LAWS, SPRING_LAWS
from kresling.model import CreaseLaws, HingeLaw, SheetMaterial
from kresling.model.material_presets import PRESET_LIMITS_DEG
from kresling.model.pattern_model import FOLD_FAMILIES
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import limits, quantity, string

__all__ = ["KEY", "LAW_LIMITS_DEG"]

#: The hinges' enhanced linear limits [deg] when ``[laws]`` gives none (with a preset
#: material, the preset's).
LAW_LIMITS_DEG = (45.0, 315.0)


def read_laws(t, context) -> dict:
    default_limits = PRESET_LIMITS_DEG if context.preset else LAW_LIMITS_DEG
    laws = sorted(SPRING_LAWS)
    bar = t.get("bar", string, "ogden", choices=tuple(sorted(BAR_LAWS)))
    fold = HingeLaw(t.get("fold", string, "enhanced_linear", choices=laws),
                    t.get("fold_limits_deg", limits, default_limits),
                    t.get("fold_stiffness", quantity, None))
    bend_default = ("super_linear_bend" if isinstance(context.material, SheetMaterial)
                    else "enhanced_linear")
    bend = HingeLaw(t.get("bend", string, bend_default, choices=laws),
                    t.get("bend_limits_deg", limits, default_limits),
                    t.get("bend_stiffness", quantity, None))
    families = {}
    for family in FOLD_FAMILIES:
        if not t.has(family):
            continue
        sub = t.table(family)
        families[family] = HingeLaw(sub.get("law", string, fold.law, choices=laws),
                                    sub.get("limits_deg", limits, fold.limits_deg),
                                    sub.get("stiffness", quantity, fold.stiffness))
        sub.finish()
    t.finish()
    return {"laws": CreaseLaws(bar=bar, fold=fold, bend=bend, families=families)}


KEY = ProblemKey("laws", rank=30, read=read_laws, default={})
