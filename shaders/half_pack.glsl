/* Two floats as IEEE half floats in one uint, and back: packHalf2x16 / unpackHalf2x16 with one
 * rounding on every GPU (to nearest, ties to even) and within GLSL 3.30, which has neither
 * (they are GLSL 4.20; Blender 3.4 runs on OpenGL 3.3). A half's 5-bit exponent and 10-bit
 * mantissa from a float's 8 and 23; past the largest half: infinity; NaN stays NaN. */
uint el_half_bits(float v)
{
  uint x = floatBitsToUint(v);
  uint sign = (x >> 16) & 0x8000u;
  uint e = (x >> 23) & 0xffu;
  uint m = x & 0x7fffffu;
  if (e == 255u) {
    return sign | 0x7c00u | (m != 0u ? 0x200u : 0u);
  }
  int he = int(e) - 112; /* 127 - 15 */
  if (he >= 31) {
    return sign | 0x7c00u;
  }
  if (he <= 0) { /* a subnormal half (or zero): the implicit bit shifted in */
    if (he < -10) {
      return sign;
    }
    m |= 0x800000u;
    uint shift = uint(14 - he);
    uint hm = m >> shift;
    uint rest = m & ((1u << shift) - 1u), half_ulp = 1u << (shift - 1u);
    if (rest > half_ulp || (rest == half_ulp && (hm & 1u) != 0u)) {
      hm += 1u;
    }
    return sign | hm;
  }
  uint h = sign | (uint(he) << 10) | (m >> 13);
  uint rest = m & 0x1fffu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u) != 0u)) {
    h += 1u; /* a carry into the exponent is still the right half */
  }
  return h;
}

float el_half_value(uint h)
{
  uint sign = (h & 0x8000u) << 16;
  uint e = (h >> 10) & 0x1fu;
  uint m = h & 0x3ffu;
  if (e == 0u) {
    float v = float(m) * 5.9604644775390625e-8; /* 2^-24 */
    return sign != 0u ? -v : v;
  }
  if (e == 31u) {
    return uintBitsToFloat(sign | 0x7f800000u | (m << 13));
  }
  return uintBitsToFloat(sign | ((e + 112u) << 23) | (m << 13));
}

uint el_pack_half2(vec2 v)
{
  return el_half_bits(v.x) | (el_half_bits(v.y) << 16);
}

vec2 el_unpack_half2(uint p)
{
  return vec2(el_half_value(p & 0xffffu), el_half_value(p >> 16));
}
