"""DXF cut files through ezdxf: one DXF layer per cut pass, one polyline per path, in mm."""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from kresling.fabrication.layers import CutSheet

__all__ = ["dxf_document", "write_dxf"]

logger = logging.getLogger(__name__)


def _ezdxf():
    try:
        import ezdxf  # here, not at the top: an optional extra, needed only to write DXF
    except ImportError as error:
        raise ImportError("writing DXF needs ezdxf: pip install 'kresling[fabrication]'") from error
    return ezdxf


def dxf_document(sheet: CutSheet):
    """An ezdxf document of a cut sheet.

    The drawing unit is the millimetre (``$INSUNITS`` = 4); the sheet's bounding box starts at
    the origin, y up. Each layer of the sheet is a DXF layer named by its key, with the
    layer's colour as true colour; each path is an ``LWPOLYLINE`` (closed where the path is).

    Parameters
    ----------
    sheet : CutSheet

    Returns
    -------
    ezdxf.document.Drawing

    Raises
    ------
    ImportError
        If ezdxf (the ``fabrication`` extra) is not installed.
    """
    ezdxf = _ezdxf()
    document = ezdxf.new("R2010", setup=False)
    document.units = ezdxf.units.MM
    document.header["$MEASUREMENT"] = 1          # metric
    origin = sheet.bounds()[0]
    model_space = document.modelspace()
    for layer in sheet.layers:
        rgb = tuple(int(layer.colour[k:k + 2], 16) for k in (1, 3, 5))
        dxf_layer = document.layers.add(layer.key)
        dxf_layer.rgb = rgb
        dxf_layer.color = _nearest_aci(rgb)
        dxf_layer.description = layer.name
        for path in layer.paths:
            points = np.asarray(path.points) - origin
            model_space.add_lwpolyline([tuple(p) for p in points], close=path.closed,
                                       dxfattribs={"layer": layer.key})
    return document


def write_dxf(sheet: CutSheet, path) -> Path:
    """Write a cut sheet as DXF (see :func:`dxf_document`); returns the path."""
    path = Path(path)
    dxf_document(sheet).saveas(path)
    logger.info("wrote %s (%d layers)", path, len(sheet.layers))
    return path


def _nearest_aci(rgb) -> int:
    """The AutoCAD colour index nearest to ``rgb`` among the seven primaries (for programs that
    ignore true colour)."""
    primaries = {1: (255, 0, 0), 2: (255, 255, 0), 3: (0, 255, 0), 4: (0, 255, 255),
                 5: (0, 0, 255), 6: (255, 0, 255), 7: (255, 255, 255)}
    return min(primaries, key=lambda k: sum((a - b) ** 2 for a, b in zip(primaries[k], rgb)))
