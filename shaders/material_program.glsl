/* The node program (shaders/material_data.json, addon/extract/node_program.py): what a material's node
 * chains compute from its image and its colour attribute, run per pixel by the surface, band and corner programs. The
 * ops are EEVEE's node library's (mix_*, math_*, the colour band), in the add-on's own words in
 * node_program.apply, which a test holds this to. Operands below EL_MAT_CONST are the block's
 * constants, from it the results of earlier instructions. */
#ifdef EL_BASE_TEXTURE
vec4 el_mat_reg[EL_MAT_CODE];
vec4 el_mat_texels[EL_MAT_IMAGES]; /* each image's texel at the point, sampled once (el_material_at) */

vec4 el_mat_operand(float ref)
{
  int i = int(ref + 0.5);
  return i < EL_MAT_CONST ? material.consts[clamp(i, 0, EL_MAT_CONST - 1)] : el_mat_reg[clamp(i - EL_MAT_CONST, 0, EL_MAT_CODE - 1)];
}

vec4 el_mat_float(float f)
{
  return vec4(f, f, f, 1.0);
}

/* Image i's texel at uv, filtered and extended as its node sets (material.images[i]), as
 * el_base_texel does by the variant's defines for the image whose alpha cuts (textures.glsl). */
vec4 el_mat_fetch(int i, ivec2 p, ivec2 size, int extend)
{
  if (extend == EL_EXTEND_REPEAT) {
    p -= size * ivec2(floor(vec2(p) / vec2(size)));
  }
  p = clamp(p, ivec2(0), size - 1);
  switch (i) {
    case 1: return texelFetch(base_tex1, p, 0);
    case 2: return texelFetch(base_tex2, p, 0);
    case 3: return texelFetch(base_tex3, p, 0);
  }
  return texelFetch(base_tex, p, 0);
}

vec4 el_mat_texel(int i, vec2 uv)
{
  vec4 how = material.images[i];
  int extend = int(how.y + 0.5);
  if (extend == EL_EXTEND_CLIP && (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))) {
    return vec4(0.0);
  }
  ivec2 size = i == 1 ? textureSize(base_tex1, 0) : (i == 2 ? textureSize(base_tex2, 0) : (i == 3 ? textureSize(base_tex3, 0) : textureSize(base_tex, 0)));
  vec2 p = uv * vec2(size);
  if (how.x > 0.5) {
    return el_mat_fetch(i, ivec2(floor(p)), size, extend);
  }
  p -= 0.5;
  ivec2 b = ivec2(floor(p));
  vec2 f = p - floor(p);
  vec4 lo = mix(el_mat_fetch(i, b, size, extend), el_mat_fetch(i, b + ivec2(1, 0), size, extend), f.x);
  vec4 hi = mix(el_mat_fetch(i, b + ivec2(0, 1), size, extend), el_mat_fetch(i, b + ivec2(1, 1), size, extend), f.x);
  return mix(lo, hi, f.y);
}

float el_mat_pow(float a, float b)
{
  /* EEVEE's math_power over compatible_pow: a negative base only to a whole power. */
  if (a < 0.0) {
    float f = mod(abs(b), 1.0);
    if (!(f > 0.999 || f < 0.001)) {
      return 0.0;
    }
    b = floor(b + 0.5);
  }
  if (b == 0.0) {
    return 1.0;
  }
  if (a < 0.0) {
    float p = pow(-a, b);
    return mod(-b, 2.0) == 0.0 ? p : -p;
  }
  return a == 0.0 ? 0.0 : pow(a, b);
}

float el_mat_math(int op, float a, float b, float c)
{
  switch (op) {
    case EL_MATH_ADD: return a + b;
    case EL_MATH_SUBTRACT: return a - b;
    case EL_MATH_MULTIPLY: return a * b;
    case EL_MATH_DIVIDE: return b != 0.0 ? a / b : 0.0;
    case EL_MATH_MULTIPLY_ADD: return a * b + c;
    case EL_MATH_POWER: return el_mat_pow(a, b);
    case EL_MATH_SQRT: return a > 0.0 ? sqrt(a) : 0.0;
    case EL_MATH_ABSOLUTE: return abs(a);
    case EL_MATH_MINIMUM: return min(a, b);
    case EL_MATH_MAXIMUM: return max(a, b);
    case EL_MATH_LESS_THAN: return a < b ? 1.0 : 0.0;
    case EL_MATH_GREATER_THAN: return a > b ? 1.0 : 0.0;
    case EL_MATH_ROUND: return floor(a + 0.5);
    case EL_MATH_FLOOR: return floor(a);
    case EL_MATH_CEIL: return ceil(a);
    case EL_MATH_FRACT: return a - floor(a);
    case EL_MATH_SINE: return sin(a);
    case EL_MATH_COSINE: return cos(a);
    case EL_MATH_EXPONENT: return exp(min(a, 88.0));
    case EL_MATH_SIGN: return sign(a);
    case EL_MATH_TRUNC: return trunc(a);
  }
  return 0.0;
}

vec3 el_mat_blend(int blend, vec3 a, vec3 b, float t)
{
  float s = 1.0 - t;
  switch (blend) {
    case EL_MIX_DARKEN: return a + t * (min(a, b) - a);
    case EL_MIX_MULTIPLY: return a + t * (a * b - a);
    case EL_MIX_LIGHTEN: return a + t * (max(a, b) - a);
    case EL_MIX_SCREEN: return 1.0 - (s + t * (1.0 - b)) * (1.0 - a);
    case EL_MIX_ADD: return a + t * b;
    case EL_MIX_SUBTRACT: return a - t * b;
    case EL_MIX_DIVIDE: {
      vec3 q = a;
      for (int k = 0; k < 3; k++) {
        if (b[k] != 0.0) {
          q[k] = s * a[k] + t * a[k] / b[k];
        }
      }
      return q;
    }
    case EL_MIX_DIFFERENCE: return a + t * (abs(a - b) - a);
    case EL_MIX_OVERLAY: {
      vec3 lo = a * (s + 2.0 * t * b), hi = 1.0 - (s + 2.0 * t * (1.0 - b)) * (1.0 - a);
      return mix(hi, lo, vec3(lessThan(a, vec3(0.5))));
    }
    case EL_MIX_LINEAR_LIGHT: return a + t * (2.0 * (b - 0.5));
  }
  return a + t * (b - a);
}

/* EEVEE's rgb_to_hsv and hsv_to_rgb (its colour utilities), for a Hue/Saturation/Value. */
vec3 el_rgb_to_hsv(vec3 rgb)
{
  float cmax = max(rgb.r, max(rgb.g, rgb.b)), cmin = min(rgb.r, min(rgb.g, rgb.b));
  float cdelta = cmax - cmin;
  float s = cmax != 0.0 ? cdelta / cmax : 0.0;
  float h = 0.0;
  if (s != 0.0) {
    vec3 c = (vec3(cmax) - rgb) / cdelta;
    h = rgb.r == cmax ? c.b - c.g : (rgb.g == cmax ? 2.0 + c.r - c.b : 4.0 + c.g - c.r);
    h /= 6.0;
    h += h < 0.0 ? 1.0 : 0.0;
  }
  return vec3(h, s, cmax);
}

vec3 el_hsv_to_rgb(vec3 hsv)
{
  float h = hsv.x, s = hsv.y, v = hsv.z;
  if (s == 0.0) {
    return vec3(v);
  }
  h = (h == 1.0 ? 0.0 : h) * 6.0;
  float i = floor(h), f = h - i;
  float p = v * (1.0 - s), q = v * (1.0 - s * f), t = v * (1.0 - s * (1.0 - f));
  if (i == 0.0) {
    return vec3(v, t, p);
  }
  if (i == 1.0) {
    return vec3(q, v, p);
  }
  if (i == 2.0) {
    return vec3(p, v, t);
  }
  if (i == 3.0) {
    return vec3(p, q, v);
  }
  return i == 4.0 ? vec3(t, p, v) : vec3(v, p, q);
}

/* A ColorRamp: `count` stops, their colours from operand `first`, positions four to a constant
 * from operand `pos`; between two stops the left one's colour (how 0: Constant) or the two
 * blended by t (1: Linear) or by t^2 (3 - 2t) (2: Ease). */
vec4 el_mat_ramp(float fac, int how, int count, int first, int pos)
{
  if (fac <= el_mat_operand(float(pos)).x) {
    return el_mat_operand(float(first));
  }
  for (int k = 1; k < count; k++) {
    float p1 = el_mat_operand(float(pos + k / 4))[k % 4];
    if (fac < p1) {
      float p0 = el_mat_operand(float(pos + (k - 1) / 4))[(k - 1) % 4];
      vec4 c0 = el_mat_operand(float(first + k - 1));
      if (how == 0) {
        return c0;
      }
      float t = p1 - p0 > 0.0 ? (fac - p0) / (p1 - p0) : 0.0;
      if (how == 2) {
        t = t * t * (3.0 - 2.0 * t);
      }
      return c0 + t * (el_mat_operand(float(first + k)) - c0);
    }
  }
  return el_mat_operand(float(first + count - 1));
}

vec4 el_mat_op(int op, int sub, vec3 s, vec4 a, vec4 b, vec4 c, vec4 col)
{
  switch (op) {
    case EL_OP_IMAGE: {
      vec4 texel = el_mat_texels[clamp(sub / 2, 0, EL_MAT_IMAGES - 1)];
      return (sub & 1) == 1 ? el_mat_float(texel.a) : texel;
    }
    case EL_OP_ATTRIBUTE: {
      if (sub == 1) {
        return el_mat_float(col.a);
      }
      return sub == 2 ? el_mat_float((col.r + col.g + col.b) / 3.0) : vec4(col.rgb, 1.0);
    }
    case EL_OP_MIX: {
      float t = s.x > 0.5 ? clamp(c.x, 0.0, 1.0) : c.x;
      vec3 rgb = el_mat_blend(sub, a.rgb, b.rgb, t);
      return vec4(s.y > 0.5 ? clamp(rgb, 0.0, 1.0) : rgb, a.a);
    }
    case EL_OP_MATH: {
      float v = el_mat_math(sub, a.x, b.x, c.x);
      return el_mat_float(s.x > 0.5 ? clamp(v, 0.0, 1.0) : v);
    }
    case EL_OP_RAMP: return el_mat_ramp(a.x, sub, int(s.x + 0.5), int(s.y + 0.5), int(s.z + 0.5));
    case EL_OP_INVERT: return vec4(a.rgb + b.x * (1.0 - 2.0 * a.rgb), a.a);
    case EL_OP_SEPARATE: return el_mat_float(a[clamp(sub, 0, 3)]);
    case EL_OP_COMBINE: return vec4(a.x, b.x, c.x, 1.0);
    case EL_OP_NORMAL_MAP: return vec4(a.rgb, b.x);
    case EL_OP_HUE_SAT: {
      vec3 hsv = el_rgb_to_hsv(a.rgb);
      hsv = vec3(fract(hsv.x + b.x + 0.5), clamp(hsv.y * b.y, 0.0, 1.0), hsv.z * b.z);
      return vec4(mix(a.rgb, el_hsv_to_rgb(hsv), c.x), a.a);
    }
    case EL_OP_GAMMA: {
      vec4 g = a; /* EEVEE's node_gamma: channels above zero only */
      for (int k = 0; k < 3; k++) {
        if (a[k] > 0.0) {
          g[k] = el_mat_pow(a[k], b.x);
        }
      }
      return g;
    }
    case EL_OP_GRAY: return el_mat_float(sub == 0 ? dot(a.rgb, vec3(0.2126, 0.7152, 0.0722)) : (a.r + a.g + a.b) / 3.0);
    case EL_OP_CLAMP: {
      float lo = sub == 0 ? b.x : min(b.x, c.x), hi = sub == 0 ? c.x : max(b.x, c.x);
      return el_mat_float(min(max(a.x, lo), hi));
    }
  }
  return vec4(0.0);
}

/* The Principled inputs at a point of the image's UV and of colour attribute `col`, as the
 * surface reads them: albedo, F0 and the Blinn exponent (materials.shading_of's split of base colour, metallic and roughness). */
struct ElMaterial {
  vec3 albedo;
  vec3 f0;
  float n;
  vec4 normal_map; /* a Normal Map's colour (rgb) and strength (a); a < 0: none */
};

ElMaterial el_material_at(vec2 uv, vec4 col)
{
  int images = int(material.program.w + 0.5);
  for (int k = 0; k < EL_MAT_IMAGES; k++) {
    el_mat_texels[k] = k < images ? el_mat_texel(k, uv) : vec4(0.0);
  }
  int count = min(int(material.program.x + 0.5), EL_MAT_CODE);
  for (int i = 0; i < count; i++) {
    vec4 c = material.code[i], p = material.args[i];
    el_mat_reg[i] = el_mat_op(int(c.x + 0.5), int(p.x + 0.5), p.yzw, el_mat_operand(c.y), el_mat_operand(c.z),
                              el_mat_operand(c.w), col);
  }
  vec3 base = max(el_mat_operand(material.outputs.x).rgb, 0.0); /* no negative albedo, as Cycles' Principled */
  float metallic = clamp(el_mat_operand(material.outputs.y).x, 0.0, 1.0);
  float roughness = clamp(el_mat_operand(material.outputs.z).x, 0.0, 1.0);
  ElMaterial m;
  m.albedo = base * (1.0 - metallic);
  m.f0 = vec3(material.program.y * (1.0 - metallic)) + base * metallic;
  float alpha = max(roughness, 1e-3) * max(roughness, 1e-3);
  m.n = material.program.z >= 0.0 ? material.program.z : clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 10000.0);
  m.normal_map = material.outputs.w >= 0.0 ? el_mat_operand(material.outputs.w) : vec4(0.0, 0.0, 0.0, -1.0);
  return m;
}

/* EEVEE's node_normal_map and its strength's mix: the colour as a tangent-space normal (2c - 1)
 * on the frame (T, sign N x T, N) of the corner-interpolated tangent `tangent` (xyz, w the
 * bitangent's sign), the frame turned round with a face seen from behind; the mesh's normal N
 * where there is no tangent. */
vec3 el_normal_map(vec3 N, bool front, vec4 tangent, vec4 normal_map)
{
  if (!(dot(tangent.xyz, tangent.xyz) > 1e-12)) {
    return N;
  }
  tangent *= front ? 1.0 : -1.0;
  vec3 T = normalize(tangent.xyz);
  vec3 B = tangent.w * cross(N, T);
  vec3 c = 2.0 * normal_map.rgb - 1.0;
  vec3 mapped = normalize(c.x * T + c.y * B + c.z * N);
  return normalize(mix(N, mapped, max(normal_map.a, 0.0)));
}
#endif
