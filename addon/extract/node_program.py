"""Node chains into a Principled BSDF's inputs (docs/addon.md, "Node chains"): RGB, Value, Mix (and
3.4's Mix RGB), Math, Map Range, ColorRamp, Invert, Gamma, Hue/Saturation/Value, Separate and
Combine (RGB, Color, XYZ), Clamp, up to four images (Image Texture) on one UV map, one colour
attribute (Color Attribute, or an Attribute node naming one) and a Normal Map, with Blender's
implicit conversions between colours, vectors and floats. The one description of the ops is
shaders/material_data.json (EL_OP, EL_MIX, EL_MATH); `apply` here and material_program.glsl
implement it the same way, which a test pins (test_node_program). A chain without an image or
the attribute is folded here into its value; one with either becomes the node program the
surface, band and corner programs run per pixel (EL_BASE_TEXTURE).
"""
import functools
import math
from dataclasses import dataclass, field

from ..bridge import shader_specs
from . import material_inputs
from .material_inputs import describe

OP = shader_specs.enum("material_data.json", "EL_OP")
MIX = shader_specs.enum("material_data.json", "EL_MIX")
MATH = shader_specs.enum("material_data.json", "EL_MATH")
_LIMITS = shader_specs.defines(shader_specs.load("material_data.json"))
MAX_CODE, MAX_CONST, MAX_IMAGES = _LIMITS["EL_MAT_CODE"], _LIMITS["EL_MAT_CONST"], _LIMITS["EL_MAT_IMAGES"]
MAX_STOPS = 8
LUMINANCE = (0.2126, 0.7152, 0.0722)  # a colour read as a float (EEVEE's convert_rgba_to_float)
# Principled inputs a chain with an image may feed (the node program's outputs); the others'
# chains are folded, and one with an image there is said. Normal: through a Normal Map.
PER_PIXEL = ("Base Color", "Metallic", "Roughness")
NORMAL = "Normal"
FLAT_NORMAL = (0.5, 0.5, 1.0)  # a Normal Map's colour that leaves the normal as it is


class Unsupported(Exception):
    """A node EdgeLight cannot evaluate: its description and why."""


@dataclass(frozen=True)
class Program:
    """A material's node program. `code`: ((op, a, b, c, sub, s1, s2, s3), ...); operands below
    MAX_CONST index `consts`, from it the result of instruction (operand - MAX_CONST).
    `outputs`: {input: operand} of the PER_PIXEL inputs, and NORMAL's when a Normal Map feeds it
    (empty: no program). `normal_uv`: the UV map a Normal Map's tangents follow ("": the render
    one), or None. `images`: the
    material_inputs.ImageInputs its IMAGE ops read (sub // 2 indexes them), all on one UV map.
    `attribute`: the colour attribute its ATTRIBUTE ops read ("": the mesh's render colour
    attribute), or None."""
    code: tuple = ()
    consts: tuple = ()
    outputs: dict = field(default_factory=dict)
    images: tuple = ()
    attribute: str = None
    normal_uv: str = None

    @functools.cached_property
    def packed(self):
        """(code, args, consts, images) as the float runs of its MaterialData members
        (passes/material_data.py), made once: a draw per instance and sample asks for them."""
        return (tuple(float(v) for ins in self.code for v in ins[:4]),
                tuple(float(v) for ins in self.code for v in ins[4:]),
                tuple(float(v) for c in self.consts for v in c),
                tuple(v for i in self.images
                      for v in (float(i.closest), float(material_inputs.EXTENSIONS[i.extension]), 0.0, 0.0)))

    @property
    def image(self):
        """The first image (the one whose UV map the mesh gives, and whose alpha may cut), or None."""
        return self.images[0] if self.images else None


# ---- the ops, as material_program.glsl computes them (vec4 values; a float is (f, f, f, 1)) ----

def _f(x):
    return (x, x, x, 1.0)


def _gray(v, how):
    return sum(c * w for c, w in zip(v[:3], LUMINANCE)) if how == 0 else (v[0] + v[1] + v[2]) / 3.0


def _pow(a, b):
    """EEVEE's math_power / compatible_pow."""
    def compatible(x, y):
        if y == 0.0:
            return 1.0
        if x < 0.0:
            p = math.pow(-x, y)
            return p if math.fmod(-y, 2.0) == 0.0 else -p
        return 0.0 if x == 0.0 else math.pow(x, y)
    if a >= 0.0:
        return compatible(a, b)
    frac = math.fmod(abs(b), 1.0)
    return compatible(a, math.floor(b + 0.5)) if frac > 0.999 or frac < 0.001 else 0.0


_MATH_FN = {
    "ADD": lambda a, b, c: a + b, "SUBTRACT": lambda a, b, c: a - b, "MULTIPLY": lambda a, b, c: a * b,
    "DIVIDE": lambda a, b, c: a / b if b != 0.0 else 0.0, "MULTIPLY_ADD": lambda a, b, c: a * b + c,
    "POWER": lambda a, b, c: _pow(a, b), "SQRT": lambda a, b, c: math.sqrt(a) if a > 0.0 else 0.0,
    "ABSOLUTE": lambda a, b, c: abs(a), "MINIMUM": lambda a, b, c: min(a, b), "MAXIMUM": lambda a, b, c: max(a, b),
    "LESS_THAN": lambda a, b, c: 1.0 if a < b else 0.0, "GREATER_THAN": lambda a, b, c: 1.0 if a > b else 0.0,
    "ROUND": lambda a, b, c: math.floor(a + 0.5), "FLOOR": lambda a, b, c: math.floor(a),
    "CEIL": lambda a, b, c: math.ceil(a), "FRACT": lambda a, b, c: a - math.floor(a),
    "SINE": lambda a, b, c: math.sin(a), "COSINE": lambda a, b, c: math.cos(a),
    "EXPONENT": lambda a, b, c: math.exp(min(a, 88.0)), "SIGN": lambda a, b, c: math.copysign(1.0, a) if a != 0.0 else 0.0,
    "TRUNC": lambda a, b, c: float(math.trunc(a)),
}
_MATH_BY_VALUE = {v: _MATH_FN[k] for k, v in MATH.items()}


def _blend(blend, a, b, t):
    """EEVEE's mix_* of two colours' rgb at factor t (alpha is the first's)."""
    s = 1.0 - t
    out = []
    for x, y in zip(a[:3], b[:3]):
        if blend == MIX["DARKEN"]:
            v = x + t * (min(x, y) - x)
        elif blend == MIX["MULTIPLY"]:
            v = x + t * (x * y - x)
        elif blend == MIX["LIGHTEN"]:
            v = x + t * (max(x, y) - x)
        elif blend == MIX["SCREEN"]:
            v = 1.0 - (s + t * (1.0 - y)) * (1.0 - x)
        elif blend == MIX["ADD"]:
            v = x + t * y
        elif blend == MIX["SUBTRACT"]:
            v = x - t * y
        elif blend == MIX["DIVIDE"]:
            v = s * x + t * x / y if y != 0.0 else x
        elif blend == MIX["DIFFERENCE"]:
            v = x + t * (abs(x - y) - x)
        elif blend == MIX["OVERLAY"]:
            v = x * (s + 2.0 * t * y) if x < 0.5 else 1.0 - (s + 2.0 * t * (1.0 - y)) * (1.0 - x)
        elif blend == MIX["LINEAR_LIGHT"]:
            v = x + t * (2.0 * (y - 0.5))
        else:
            v = x + t * (y - x)
        out.append(v)
    return (*out, a[3])


def _rgb_to_hsv(r, g, b):
    """EEVEE's rgb_to_hsv."""
    cmax, cmin = max(r, g, b), min(r, g, b)
    delta = cmax - cmin
    s = delta / cmax if cmax != 0.0 else 0.0
    h = 0.0
    if s != 0.0:
        cr, cg, cb = ((cmax - x) / delta for x in (r, g, b))
        h = (cb - cg if r == cmax else (2.0 + cr - cb if g == cmax else 4.0 + cg - cr)) / 6.0
        h += 1.0 if h < 0.0 else 0.0
    return h, s, cmax


def _hsv_to_rgb(h, s, v):
    """EEVEE's hsv_to_rgb."""
    if s == 0.0:
        return v, v, v
    h = (0.0 if h == 1.0 else h) * 6.0
    i = math.floor(h)
    f = h - i
    p, q, t = v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f))
    return ((v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q))[min(max(int(i), 0), 5)]


# A ColorRamp's interpolations the RAMP instruction draws (its sub), as Blender's colour band.
RAMP_INTERPOLATIONS = {'CONSTANT': 0, 'LINEAR': 1, 'EASE': 2}


def _ramp(fac, how, positions, colours):
    """A ColorRamp (RGB) at `fac`: the first stop's colour before it, the last's after; between,
    the left stop's (how 0: Constant) or the two blended by t (1: Linear) or by t^2 (3 - 2t)
    (2: Ease, BKE_colorband_evaluate's), t the fraction of the way from the left stop."""
    if fac <= positions[0]:
        return colours[0]
    for k in range(1, len(positions)):
        if fac < positions[k]:
            if how == 0:
                return colours[k - 1]
            span = positions[k] - positions[k - 1]
            t = (fac - positions[k - 1]) / span if span > 0.0 else 0.0
            if how == 2:
                t = t * t * (3.0 - 2.0 * t)
            return tuple(p + t * (q - p) for p, q in zip(colours[k - 1], colours[k]))
    return colours[-1]


def _clamp01(v):
    return tuple(min(max(c, 0.0), 1.0) for c in v[:3]) + (v[3],)


def apply(op, sub, settings, a, b, c, texels=(), ramp=None, color=(0.0, 0.0, 0.0, 0.0)):
    """One instruction's value from its operands' (vec4 tuples); `ramp`: (positions, colours);
    `texels` and `color`: the images' and the colour attribute's values."""
    if op == OP["IMAGE"]:
        texel = texels[sub // 2] if sub // 2 < len(texels) else (0.0, 0.0, 0.0, 0.0)
        return _f(texel[3]) if sub % 2 == 1 else tuple(texel)
    if op == OP["ATTRIBUTE"]:
        if sub == 1:
            return _f(color[3])
        return _f(sum(color[:3]) / 3.0) if sub == 2 else (*color[:3], 1.0)
    if op == OP["MIX"]:
        t = min(max(c[0], 0.0), 1.0) if settings[0] else c[0]
        out = _blend(sub, a, b, t)
        return _clamp01(out) if settings[1] else out
    if op == OP["MATH"]:
        try:
            v = _MATH_BY_VALUE[sub](a[0], b[0], c[0])
        except (OverflowError, ValueError):  # the GPU's inf or NaN: not a value a material can use
            v = math.nan
        return _f(min(max(v, 0.0), 1.0) if settings[0] and not math.isnan(v) else v)
    if op == OP["RAMP"]:
        return _ramp(a[0], sub, *ramp)
    if op == OP["INVERT"]:
        t = b[0]
        return (*(x + t * (1.0 - 2.0 * x) for x in a[:3]), a[3])
    if op == OP["SEPARATE"]:
        return _f(a[sub])
    if op == OP["COMBINE"]:
        return (a[0], b[0], c[0], 1.0)
    if op == OP["NORMAL_MAP"]:
        return (a[0], a[1], a[2], b[0])
    if op == OP["HUE_SAT"]:
        h, s, v = _rgb_to_hsv(*a[:3])
        turned = _hsv_to_rgb((h + b[0] + 0.5) % 1.0, min(max(s * b[1], 0.0), 1.0), v * b[2])
        return (*(x + c[0] * (y - x) for x, y in zip(a[:3], turned)), a[3])
    if op == OP["GAMMA"]:
        return (*((_pow(x, b[0]) if x > 0.0 else x) for x in a[:3]), a[3])
    if op == OP["GRAY"]:
        return _f(_gray(a, sub))
    if op == OP["CLAMP"]:
        lo, hi = (b[0], c[0]) if sub == 0 else (min(b[0], c[0]), max(b[0], c[0]))
        return _f(min(max(a[0], lo), hi))
    raise ValueError(f"op {op}")


def run(program, texels, color=(0.0, 0.0, 0.0, 0.0)):
    """{input: vec4} of a program's outputs at its images' texels (one per image; one texel
    alone for a single image) and a colour attribute value: what material_program.glsl
    computes."""
    if len(texels) and not hasattr(texels[0], "__len__"):
        texels = (tuple(texels),)
    regs = []

    def value(ref):
        return program.consts[ref] if ref < MAX_CONST else regs[ref - MAX_CONST]
    for op, a, b, c, sub, s1, s2, s3 in program.code:
        ramp = None
        if op == OP["RAMP"]:
            n, first, pos = int(s1), int(s2), int(s3)
            ramp = ([program.consts[pos + k // 4][k % 4] for k in range(n)], [program.consts[first + k] for k in range(n)])
        regs.append(apply(op, sub, (s1, s2, s3), value(a), value(b), value(c), texels, ramp, color))
    return {name: value(ref) for name, ref in program.outputs.items()}


# ---- reading the tree ----

def _socket(node, identifier):
    return next(s for s in node.inputs if s.identifier == identifier)


def _default(socket):
    v = socket.default_value
    if socket.type == 'VALUE' or isinstance(v, (int, float)):
        return _f(float(v))
    v = tuple(float(x) for x in v)
    return v + (1.0,) * (4 - len(v)) if len(v) < 4 else v[:4]


class _Compiler:
    """Values of sockets: ('const', vec4) or ('ref', operand); instructions appended as met."""

    def __init__(self):
        self.code, self.consts, self.images, self.attribute, self.memo = [], [], [], None, {}
        self.normal_uv = None

    def const_ref(self, v):
        v = tuple(float(x) for x in v)
        if v in self.consts:
            return self.consts.index(v)
        return self._alloc([v])

    def _alloc(self, values):
        if len(self.consts) + len(values) > MAX_CONST:
            raise Unsupported(f"more than {MAX_CONST} constants in its chains")
        self.consts.extend(values)
        return len(self.consts) - len(values)

    def ref(self, val):
        return self.const_ref(val[1]) if val[0] == 'const' else val[1]

    def emit(self, op, sub=0, settings=(0.0, 0.0, 0.0), a=('const', _f(0.0)), b=('const', _f(0.0)),
             c=('const', _f(0.0)), ramp=None):
        """An instruction, or its value when every operand is a constant (folded by `apply`)."""
        if op not in {OP["IMAGE"], OP["ATTRIBUTE"], OP["NORMAL_MAP"]} and all(v[0] == 'const' for v in (a, b, c)):
            return ('const', apply(op, sub, settings, a[1], b[1], c[1], ramp=ramp))
        if len(self.code) >= MAX_CODE:
            raise Unsupported(f"more than {MAX_CODE} nodes drawn per pixel")
        s1, s2, s3 = settings
        if ramp is not None:
            positions, colours = ramp
            s1 = float(len(positions))
            s2 = float(self._alloc([tuple(c_) for c_ in colours]))
            padded = list(positions) + [0.0] * (-len(positions) % 4)
            s3 = float(self._alloc([tuple(padded[i:i + 4]) for i in range(0, len(padded), 4)]))
        self.code.append((op, self.ref(a), self.ref(b), self.ref(c), sub, s1, s2, s3))
        return ('ref', MAX_CONST + len(self.code) - 1)

    def input(self, socket):
        """The value of an input socket: its link's, converted to its type, or its own."""
        node, out = material_inputs.feeding(socket)
        if node is None:
            return ('const', _default(socket))
        val = self.output(node, out)
        if socket.type == 'VALUE' and out.type in {'RGBA', 'VECTOR'}:
            val = self.emit(OP["GRAY"], 0 if out.type == 'RGBA' else 1, a=val)
        return val

    def output(self, node, out):
        key = (node.as_pointer(), out.identifier)
        if key not in self.memo:
            if node.mute:
                raise Unsupported(f"{describe(node)} is muted")
            self.memo[key] = self._node(node, out)
        return self.memo[key]

    def _node(self, node, out):
        t = node.type
        if t in {'RGB', 'VALUE'}:
            return ('const', _default(out))
        if t == 'TEX_IMAGE':
            return self._image(node, out)
        if t in {'VERTEX_COLOR', 'ATTRIBUTE'}:
            return self._attribute(node, out)
        if t == 'MIX_RGB':
            self._blend_known(node.blend_type, node)
            return self.emit(OP["MIX"], MIX[node.blend_type], (1.0, float(node.use_clamp), 0.0),
                             self.input(node.inputs["Color1"]), self.input(node.inputs["Color2"]),
                             self.input(node.inputs["Fac"]))
        if t == 'MIX':
            return self._mix(node)
        if t == 'MATH':
            if node.operation not in MATH:
                raise Unsupported(f"{describe(node)}: its operation {node.operation}")
            i = node.inputs
            return self.emit(OP["MATH"], MATH[node.operation], (float(node.use_clamp), 0.0, 0.0),
                             self.input(i[0]), self.input(i[1]), self.input(i[2]) if len(i) > 2 else ('const', _f(0.0)))
        if t == 'VALTORGB':
            return self._ramp(node, out)
        if t == 'INVERT':
            return self.emit(OP["INVERT"], 0, a=self.input(node.inputs["Color"]), b=self.input(node.inputs["Fac"]))
        if t in {'SEPRGB', 'SEPXYZ', 'SEPARATE_COLOR'}:
            if getattr(node, "mode", 'RGB') != 'RGB':
                raise Unsupported(f"{describe(node)}: its mode {node.mode}")
            channel = [o.identifier for o in node.outputs].index(out.identifier)
            return self.emit(OP["SEPARATE"], channel, a=self.input(node.inputs[0]))
        if t in {'COMBRGB', 'COMBXYZ', 'COMBINE_COLOR'}:
            if getattr(node, "mode", 'RGB') != 'RGB':
                raise Unsupported(f"{describe(node)}: its mode {node.mode}")
            i = node.inputs
            return self.emit(OP["COMBINE"], 0, a=self.input(i[0]), b=self.input(i[1]), c=self.input(i[2]))
        if t == 'HUE_SAT':
            i = node.inputs
            hsv = self.emit(OP["COMBINE"], a=self.input(i["Hue"]), b=self.input(i["Saturation"]), c=self.input(i["Value"]))
            return self.emit(OP["HUE_SAT"], a=self.input(i["Color"]), b=hsv, c=self.input(i["Fac"]))
        if t == 'GAMMA':
            return self.emit(OP["GAMMA"], a=self.input(node.inputs["Color"]), b=self.input(node.inputs["Gamma"]))
        if t == 'MAP_RANGE':
            return self._map_range(node)
        if t == 'CLAMP':
            return self.emit(OP["CLAMP"], 0 if node.clamp_type == 'MINMAX' else 1, a=self.input(node.inputs["Value"]),
                             b=self.input(node.inputs["Min"]), c=self.input(node.inputs["Max"]))
        raise Unsupported(describe(node))

    @staticmethod
    def _blend_known(blend, node):
        if blend not in MIX:
            raise Unsupported(f"{describe(node)}: its blend {blend.title().replace('_', ' ')}")

    def _mix(self, node):
        kind = node.data_type
        if kind == 'VECTOR' and node.factor_mode != 'UNIFORM':
            raise Unsupported(f"{describe(node)}: a non-uniform factor")
        if kind not in {'FLOAT', 'VECTOR', 'RGBA'}:
            raise Unsupported(f"{describe(node)}: its type {kind}")
        suffix = {"FLOAT": "Float", "VECTOR": "Vector", "RGBA": "Color"}[kind]
        blend = node.blend_type if kind == 'RGBA' else 'MIX'
        self._blend_known(blend, node)
        clamp_result = float(kind == 'RGBA' and node.clamp_result)
        return self.emit(OP["MIX"], MIX[blend], (float(node.clamp_factor), clamp_result, 0.0),
                         self.input(_socket(node, "A_" + suffix)), self.input(_socket(node, "B_" + suffix)),
                         self.input(_socket(node, "Factor_Float")))

    def _map_range(self, node):
        """A Map Range (float) in Math instructions, as EEVEE's map_range_*: a factor t =
        (value - from_min) / (from_max - from_min), then to_min + t x (to_max - to_min). Linear
        takes t as it is; Stepped floor(t (steps + 1)) / steps; Smooth Step and Smoother Step
        t clamped to [0, 1] through t^2 (3 - 2t) or t^3 (t (6t - 15) + 10), which is EEVEE's
        value for either order of the from values. Linear and Stepped are clamped between the
        two `to` values when the node clamps (the only modes whose Clamp Blender shows)."""
        kind = node.interpolation_type
        if node.data_type != 'FLOAT' or kind not in {'LINEAR', 'STEPPED', 'SMOOTHSTEP', 'SMOOTHERSTEP'}:
            what = kind if node.data_type == 'FLOAT' else node.data_type
            raise Unsupported(f"{describe(node)}: its {what.title().replace('_', ' ')} mapping")

        def socket(name):
            return self.input(next(s for s in node.inputs if s.name == name and s.enabled))

        def math(operation, a, b=('const', _f(0.0)), c=('const', _f(0.0))):
            return self.emit(OP["MATH"], MATH[operation], a=a, b=b, c=c)

        def const(x):
            return ('const', _f(x))
        value, from_min, from_max = socket("Value"), socket("From Min"), socket("From Max")
        to_min, to_max = socket("To Min"), socket("To Max")
        t = math("DIVIDE", math("SUBTRACT", value, from_min), math("SUBTRACT", from_max, from_min))
        if kind == 'STEPPED':
            steps = socket("Steps")
            t = math("DIVIDE", math("FLOOR", math("MULTIPLY", t, math("ADD", steps, const(1.0)))), steps)
        elif kind in {'SMOOTHSTEP', 'SMOOTHERSTEP'}:
            t = self.emit(OP["CLAMP"], 0, a=t, b=const(0.0), c=const(1.0))
            if kind == 'SMOOTHSTEP':
                t = math("MULTIPLY", math("MULTIPLY", t, t), math("MULTIPLY_ADD", t, const(-2.0), const(3.0)))
            else:
                inner = math("MULTIPLY_ADD", math("MULTIPLY_ADD", t, const(6.0), const(-15.0)), t, const(10.0))
                t = math("MULTIPLY", math("MULTIPLY", math("MULTIPLY", t, t), t), inner)
        out = math("MULTIPLY_ADD", t, math("SUBTRACT", to_max, to_min), to_min)
        if node.clamp and kind in {'LINEAR', 'STEPPED'}:
            return self.emit(OP["CLAMP"], 1, a=out, b=to_min, c=to_max)
        return out

    def _ramp(self, node, out):
        """A ColorRamp's Color; its Alpha the Color's alpha (one RAMP instruction for both)."""
        if out.name == "Alpha":
            return self.emit(OP["SEPARATE"], 3, a=self.output(node, node.outputs["Color"]))
        ramp = node.color_ramp
        if ramp.color_mode != 'RGB' or ramp.interpolation not in RAMP_INTERPOLATIONS:
            what = ramp.interpolation if ramp.color_mode == 'RGB' else ramp.color_mode
            raise Unsupported(f"{describe(node)}: its {what.title()} interpolation")
        stops = sorted(((float(e.position), tuple(float(x) for x in e.color)) for e in ramp.elements),
                       key=lambda s: s[0])
        if len(stops) > MAX_STOPS:
            raise Unsupported(f"{describe(node)}: more than {MAX_STOPS} stops")
        return self.emit(OP["RAMP"], RAMP_INTERPOLATIONS[ramp.interpolation], a=self.input(node.inputs["Fac"]),
                         ramp=([p for p, _ in stops], [c for _, c in stops]))

    def _image(self, node, out):
        source = material_inputs.image_node_input(node)
        if source is None:
            raise Unsupported(f"{describe(node)}: {material_inputs.image_node_problem(node)}")
        if source not in self.images:
            if self.images and source.uv_map != self.images[0].uv_map:
                raise Unsupported(f"{describe(node)}: another UV map than its first image's "
                                  f"('{self.images[0].image.name}')")
            if len(self.images) >= MAX_IMAGES:
                raise Unsupported(f"{describe(node)}: more than {MAX_IMAGES} images")
            self.images.append(source)
        return self.emit(OP["IMAGE"], 2 * self.images.index(source) + (1 if out.name == "Alpha" else 0))

    def normal(self, socket):
        """The Principled BSDF's Normal: a Normal Map in tangent space (through reroutes), its
        Color and Strength chains in a NORMAL_MAP instruction; None where it leaves the normal
        as it is (unlinked, or a constant flat colour)."""
        node, out = material_inputs.feeding(socket)
        if node is None:
            return None
        if node.type != 'NORMAL_MAP':
            raise Unsupported(describe(node))
        if node.mute:
            raise Unsupported(f"{describe(node)} is muted")
        if node.space != 'TANGENT':
            raise Unsupported(f"{describe(node)}: its {node.space.title().replace('_', ' ')} space")
        color, strength = self.input(node.inputs["Color"]), self.input(node.inputs["Strength"])
        if color[0] == 'const' and tuple(color[1][:3]) == FLAT_NORMAL:
            return None
        self.normal_uv = node.uv_map  # its tangents' own, whatever its image's (scene_sync.tangent_corners)
        return self.emit(OP["NORMAL_MAP"], a=color, b=strength)

    def _attribute(self, node, out):
        """A Color Attribute node, or an Attribute node of the geometry (its name must be a
        colour attribute of the mesh: scene_sync says where it is not). Outputs: Color and
        Vector, Alpha, Fac (the colour's mean)."""
        if node.type == 'ATTRIBUTE':
            if node.attribute_type != 'GEOMETRY' or not node.attribute_name:
                raise Unsupported(f"{describe(node)}: its {node.attribute_type.title().replace('_', ' ')} attribute")
            name = node.attribute_name
        else:
            name = node.layer_name
        if self.attribute is not None and name != self.attribute:
            raise Unsupported(f"{describe(node)}: a second colour attribute ('{self.attribute or 'the render one'}' is drawn)")
        self.attribute = name
        # Fac is Factor from 5.0: a float output other than Alpha.
        return self.emit(OP["ATTRIBUTE"], 1 if out.name == "Alpha" else (2 if out.type == 'VALUE' else 0))


@dataclass(frozen=True)
class Chains:
    """What a Principled BSDF's linked inputs come to: `values` {input: vec4} of the chains
    folded here; `program` the node program of those drawn per pixel (its outputs empty: none);
    `unread` [(short, long)] of the chains EdgeLight cannot draw (their sockets' values drawn)."""
    values: dict
    program: Program
    unread: list


def read(node, names):
    """The chains into the Principled BSDF `node`'s inputs `names` (those present and linked)."""
    comp, values, outputs, unread = _Compiler(), {}, {}, []
    for name in names:
        socket = node.inputs.get(name)
        if socket is None or not socket.is_linked:
            continue
        trial = _Compiler()
        trial.code, trial.consts, trial.memo = list(comp.code), list(comp.consts), dict(comp.memo)
        trial.images, trial.attribute, trial.normal_uv = list(comp.images), comp.attribute, comp.normal_uv
        try:
            val = trial.normal(socket) if name == NORMAL else trial.input(socket)
            if val is None:
                continue  # a Normal Map that leaves the normal as it is
            if val[0] == 'ref' and name not in PER_PIXEL + (NORMAL,):
                first = describe(socket.links[0].from_node)
                raise Unsupported(f"{first}: per pixel, drawn only into Base Color, Metallic and Roughness")
        except Unsupported as e:
            unread.append((name, str(e)))
            continue
        comp = trial
        if val[0] == 'const':
            values[name] = val[1]
        else:
            outputs[name] = val[1]
    if not outputs:
        return Chains(values, Program(), unread)
    try:
        for name in PER_PIXEL:  # the program gives all three; those not drawn per pixel as constants
            if name not in outputs:
                outputs[name] = comp.const_ref(values[name] if name in values else _default(node.inputs[name]))
    except Unsupported as e:  # no room left for them: no program, its chains said
        firsts = [(name, describe(node.inputs[name].links[0].from_node)) for name in outputs]
        return Chains(values, Program(), unread + [(name, f"{first}: {e}") for name, first in firsts])
    return Chains(values, Program(tuple(comp.code), tuple(comp.consts), outputs, tuple(comp.images), comp.attribute,
                                  comp.normal_uv), unread)
