"""SVG cut files at true scale, one Inkscape/Illustrator layer per cut pass, and PNG previews.

Width, height and viewBox are in millimetres, so 1 user unit is 1 mm in every program that
honours the units (Inkscape, Illustrator, cutting-plotter software). Each cut pass is a
top-level group with ``inkscape:groupmode="layer"`` and ``inkscape:label``, the form
Inkscape reads as a layer; Illustrator makes a layer of each top-level group, named by its
``id``. Every path is a stroke with no fill, coloured per layer.
"""

from __future__ import annotations

import logging
import xml.etree.ElementTree as ET
from pathlib import Path

from kresling.fabrication.layers import CutSheet

__all__ = ["svg_document", "write_svg", "render_png", "MARGIN"]

logger = logging.getLogger(__name__)

SVG_NS = "http://www.w3.org/2000/svg"
INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"
ET.register_namespace("", SVG_NS)
ET.register_namespace("inkscape", INKSCAPE_NS)

#: Blank border around the pattern on an SVG or PNG page [mm]: the page is the pattern's
#: extent plus twice this, each way (a DXF file has no page, only the pattern).
MARGIN = 5.0


def svg_document(sheet: CutSheet, *, margin: float = MARGIN, stroke_width: float = 0.1) -> str:
    """The SVG text of a cut sheet.

    Parameters
    ----------
    sheet : CutSheet
    margin : float, default 5.0
        Empty border round the paths [mm].
    stroke_width : float, default 0.1
        Line width [mm]; cutters follow the path whatever its width (0.1 mm is a hairline
        that still shows on screen).

    Returns
    -------
    str
        An SVG 1.1 document of ``size + 2 margin`` by the same in mm, y pointing down as SVG
        requires (the drawing is the sheet as seen from above, not mirrored).
    """
    (x0, y0), (x1, y1) = sheet.bounds()
    width, height = x1 - x0 + 2 * margin, y1 - y0 + 2 * margin
    root = ET.Element(f"{{{SVG_NS}}}svg", {
        "version": "1.1",
        "width": f"{width:.6f}mm",
        "height": f"{height:.6f}mm",
        "viewBox": f"0 0 {width:.6f} {height:.6f}",
    })
    ET.SubElement(root, f"{{{SVG_NS}}}title").text = sheet.title
    ET.SubElement(root, f"{{{SVG_NS}}}desc").text = " | ".join(
        [f"{layer.name}: {layer.description}" for layer in sheet.layers] + list(sheet.notes))

    def place(points):
        return [(x - x0 + margin, y1 - y + margin) for x, y in points]

    for layer in sheet.layers:
        group = ET.SubElement(root, f"{{{SVG_NS}}}g", {
            "id": f"layer-{layer.key}",
            f"{{{INKSCAPE_NS}}}groupmode": "layer",
            f"{{{INKSCAPE_NS}}}label": layer.name,
            "style": (f"fill:none;stroke:{layer.colour};stroke-width:{stroke_width:g};"
                      "stroke-linecap:round;stroke-linejoin:round"),
        })
        for path in layer.paths:
            corners = " L ".join(f"{x:.6f},{y:.6f}" for x, y in place(path.points))
            ET.SubElement(group, f"{{{SVG_NS}}}path", {
                "d": f"M {corners}{' Z' if path.closed else ''}",
                "class": path.role.replace(" ", "-"),
            })
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"


def write_svg(sheet: CutSheet, path, **options) -> Path:
    """Write a cut sheet as SVG (``options`` as :func:`svg_document`); returns the path."""
    path = Path(path)
    path.write_text(svg_document(sheet, **options), encoding="utf-8")
    width, height = sheet.size
    logger.info("wrote %s (%.1f x %.1f mm, %d layers)", path, width, height, len(sheet.layers))
    return path


def render_png(svg_text: str, path, *, dpi: float = 96.0) -> Path:
    """Render SVG text to a PNG file on a white background with cairosvg.

    Parameters
    ----------
    svg_text : str
        E.g. from :func:`svg_document` (a thicker ``stroke_width`` reads better on screen).
    path : str or Path
    dpi : float, default 96
        Pixels per inch: the image is ``width_mm / 25.4 * dpi`` pixels wide.

    Raises
    ------
    ImportError
        If cairosvg (the ``fabrication`` extra) is not installed.
    """
    try:
        import cairosvg  # here, not at the top: an optional extra, needed only for PNG
    except (ImportError, OSError) as error:  # cairocffi raises OSError when libcairo is missing
        raise ImportError("rendering a PNG needs cairosvg and the cairo library: "
                          "pip install 'kresling[fabrication]' (and apt-get install libcairo2)"
                          ) from error
    path = Path(path)
    cairosvg.svg2png(bytestring=svg_text.encode("utf-8"), write_to=str(path), dpi=dpi,
                     background_color="white")
    logger.info("rendered %s at %g dpi", path, dpi)
    return path
