"""Strokes (vector_lines.Stroke) -> an SVG 1.1 document: one Inkscape layer (<g>) per line type
and visibility, with the type's colour, opacity and width; polylines in pixel coordinates."""
import xml.etree.ElementTree as ET

import numpy as np

SVG_NS = "http://www.w3.org/2000/svg"
INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"
ET.register_namespace("", SVG_NS)
ET.register_namespace("inkscape", INKSCAPE_NS)

LABELS = {"silhouette": "Silhouettes", "border": "Borders", "crease": "Creases", "contour": "Contours",
          "material": "Material Boundaries", "marked": "Marked Edges", "wire": "Wire"}


def srgb_hex(rgb):
    """Scene-linear colour -> #rrggbb (sRGB, as the Standard view transform shows it)."""
    c = np.clip(np.asarray(rgb, np.float64), 0.0, 1.0)
    s = np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1.0 / 2.4) - 0.055)
    return "#" + "".join(f"{int(round(v * 255.0)):02x}" for v in s)


def _num(v):
    return f"{v:.2f}".rstrip("0").rstrip(".")


def _points(p):
    return " ".join(f"{_num(x)},{_num(y)}" for x, y in p.tolist())


def _q(tag):
    return f"{{{SVG_NS}}}{tag}"


def document(strokes, settings, width, height, title="EdgeLight lines", view=None):
    """ElementTree root of the SVG for `strokes` (type -> [Stroke]) of LineSettings `settings`,
    drawn over width x height pixels; `view` (x, y, w, h; y down), the part of them shown, when
    not all (a render region drawn with a margin).

    Layers paint in reverse draw order, hidden ones first: in the line pass the type drawn
    first wins a tie and visible strokes sit over hidden ones, so those end on top here. The
    opacity is the layer's (group opacity), so a chain's overlapping caps do not stack, as
    the line pass keeps each pixel's most opaque stroke."""
    x, y, w, h = view or (0, 0, width, height)
    root = ET.Element(_q("svg"), {"version": "1.1", "width": str(w), "height": str(h), "viewBox": f"{x} {y} {w} {h}"})
    ET.SubElement(root, _q("title")).text = title
    styles = dict(settings.styles)
    for hidden in (True, False):
        for kind in reversed([k for k, _ in settings.styles]):
            groups = [g for g in strokes.get(kind, ()) if g.hidden == hidden and g.polylines]
            if not groups:
                continue
            style = styles[kind]
            name = kind + ("-hidden" if hidden else "")
            opacity = style.opacity * (settings.hidden_opacity if hidden else 1.0)
            layer = ET.SubElement(root, _q("g"), {
                "id": name, f"{{{INKSCAPE_NS}}}groupmode": "layer",
                f"{{{INKSCAPE_NS}}}label": LABELS.get(kind, kind) + (" (hidden)" if hidden else ""),
                "fill": "none", "stroke": srgb_hex(style.color), "opacity": _num(opacity),
                "stroke-linecap": "round", "stroke-linejoin": "round"})
            widths = {g.width for g in groups}
            if len(widths) == 1:
                layer.set("stroke-width", _num(groups[0].width))
            for g in groups:
                attrs = {} if len(widths) == 1 else {"stroke-width": _num(g.width)}
                for p in g.polylines:
                    ET.SubElement(layer, _q("polyline"), dict(attrs, points=_points(p)))
    return root


def write(path, root):
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)
