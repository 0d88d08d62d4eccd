/* Ink line pass: one screen-space quad per drawn chord (no wide GL lines, no geometry shader),
 * reaching half a pixel (and a little) past its round-capped stroke on every side.
 *
 * Lines at the screen's resolution (passes/line_pass.py, docs/lines.md): a chain's segments come
 * in groups of up to 8, each group a binary tree of chords over them. Each segment's record
 * (line_nodes, 5 texels, in chain order) holds its ends, its ancestors' error bounds and, for
 * the chords it is the first segment of, their segment counts. Per view this shader finds the
 * coarsest chord on the segment's path whose projected bound stays within line_lod.x pixels
 * (bounds grow towards the root and share the group's sphere, so every segment under that chord
 * finds the same one) and draws it from its first segment; the others draw nothing. It skips
 * crease chains whose whole projection fits in a disc of line_lod.y pixels, and, when hidden
 * lines are not drawn, every chord whose fragments the visibility rule (line.frag.glsl) would
 * all discard. A quad not drawn puts its corners outside the clip volume: no fragment runs.
 *
 * `node` is 4 * segment + corner; corner bit 1 picks the end (0: a, 1: b), bit 0 the side.
 * Record texels: (a, taper at a), (b, taper at b), (errors of the parent, grandparent and
 * great-grandparent chords, -1 none; sum of count_l * 16^l, count_l the segments of level l's
 * chord when this segment is its first, else 0), the group's bounding sphere, the chain's
 * bounding sphere; a chord of count segments from segment n ends at b of segment n + count - 1.
 * line_faces holds each segment's two faces (surface ids) in chain order. Widths are pixels, or
 * scene units with a pixel floor (line_style.y = 1); taper is the distance from each end to the
 * chain's nearest free end as a fraction of the chain's length (large: no free end), and
 * line_style.w the fraction over which the stroke tapers to nothing. line_lod.z bounds the model matrix's stretch (its
 * largest singular value); line_lod.w = 1 allows culling hidden chords (0: the tests'
 * reference). A negative line_lod.x draws every segment. */
const int EL_NODE_TEXELS = 5;
const int EL_NODES_PER_ROW = 819; /* 4095 texels: a record never straddles two rows */
const int EL_FACES_PER_ROW = 4096;

float el_line_half_width(float depth, float taper_t)
{
  float w = line_style.x;
  if (line_style.y > 0.5) {
    float px_per_unit = frame.eye.w > 0.5 ? frame.camera.x / max(depth, 1e-20) : frame.camera.x;
    w = max(w * px_per_unit, line_style.z);
  }
  float f = line_style.w > 0.0 ? clamp(taper_t / line_style.w, 0.0, 1.0) : 1.0;
  return 0.5 * w * f;
}

vec4 el_node_texel(int node, int k)
{
  return texelFetch(line_nodes, ivec2((node % EL_NODES_PER_ROW) * EL_NODE_TEXELS + k, node / EL_NODES_PER_ROW), 0);
}

/* Pixels per object-space unit that any displacement inside `sphere` (object space) moves on
 * screen, at most; 1e30 when the sphere reaches the eye's plane. Under perspective a point p
 * and a point q, both in the sphere, project |p - q| * f * sqrt(1 + T^2) / z_min apart at most
 * (f the focal length in pixels, z_min the sphere's nearest view depth, T the largest
 * tan(angle off the view axis) in the sphere); docs/lines.md derives it. */
float el_px_per_unit(vec4 sphere)
{
  float f = max(abs(frame.projection[0][0]) * frame.viewport.x, abs(frame.projection[1][1]) * frame.viewport.y) * 0.5;
  float stretch = line_lod.z;
  if (frame.eye.w < 0.5) {
    return f * stretch;
  }
  vec4 c = frame.view * (model * vec4(sphere.xyz, 1.0));
  float r = sphere.w * stretch;
  float z_min = -c.z - r;
  if (!(z_min > 1e-6 * max(r, 1e-6))) {
    return 1e30;
  }
  float tan_max = (length(c.xy) + r) / z_min;
  return f * stretch * sqrt(1.0 + tan_max * tan_max) / z_min;
}

/* ---- Hidden nodes, culled before they are rasterised (hidden lines Off) ------------------- */
/* Slack of the walk below in pixels: the fragment's closest point is rounded. */
const float EL_WALK_SLACK = 1.0 / 256.0;
/* Nodes whose walk crosses more pixel columns (or rows) than this are drawn untested. */
const int EL_WALK_MAX = 48;

/* Centre cells of column u of the walk: rows x..y, and the nearest and farthest view depth (z,
 * w) of the segment's part over the column, for a segment a -> b with a.x <= b.x (walk
 * coordinates). Empty: x > y. */
vec4 el_walk_column(float u, vec2 a, vec2 b, float za, float zb, bool persp)
{
  if (u + 1.0 + EL_WALK_SLACK < a.x || u - EL_WALK_SLACK > b.x) {
    return vec4(1.0, 0.0, 0.0, 0.0);
  }
  float du = b.x - a.x;
  float s0 = 0.0, s1 = 1.0;
  if (du > 0.0) {
    s0 = clamp((u - EL_WALK_SLACK - a.x) / du, 0.0, 1.0);
    s1 = clamp((u + 1.0 + EL_WALK_SLACK - a.x) / du, 0.0, 1.0);
  }
  float v0 = a.y + s0 * (b.y - a.y), v1 = a.y + s1 * (b.y - a.y);
  float z0 = persp ? 1.0 / mix(1.0 / za, 1.0 / zb, s0) : mix(za, zb, s0);
  float z1 = persp ? 1.0 / mix(1.0 / za, 1.0 / zb, s1) : mix(za, zb, s1);
  return vec4(floor(min(v0, v1) - EL_WALK_SLACK), floor(max(v0, v1) + EL_WALK_SLACK), min(z0, z1), max(z0, z1));
}

bool el_own_face(vec2 id, vec4 f0, vec4 f1, vec4 f2, vec4 f3)
{
  vec4 y = vec4(id.y);
  return id.x == line_vis.z && id.y > 0.0 &&
         (any(equal(y, f0)) || any(equal(y, f1)) || any(equal(y, f2)) || any(equal(y, f3)));
}

/* Whether the fragment shader's visibility rule could accept any centre point of the screen
 * segment sa -> sb (view depths za, zb; faces f0..f3): the rule's conservative copy over every
 * pixel whose 3x3 window a centre point can use (and every centre cell, for depth). False: every
 * fragment of the node would be discarded as hidden. */
bool el_line_may_show(vec2 sa, vec2 sb, float za, float zb, float reach, vec4 f0, vec4 f1, vec4 f2, vec4 f3)
{
  bool persp = frame.eye.w > 0.5;
  /* Only centre points within `reach` of the image can colour a pixel of it (Liang-Barsky). */
  vec2 lo_px = vec2(-reach), hi_px = frame.viewport.xy + reach;
  vec2 d = sb - sa;
  float t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 2; k++) {
    if (abs(d[k]) < 1e-12) {
      if (sa[k] < lo_px[k] || sa[k] > hi_px[k]) {
        return false;
      }
    }
    else {
      float ta = (lo_px[k] - sa[k]) / d[k], tb = (hi_px[k] - sa[k]) / d[k];
      t0 = max(t0, min(ta, tb));
      t1 = min(t1, max(ta, tb));
    }
  }
  if (t0 > t1) {
    return false;
  }
  vec2 a = sa + t0 * d, b = sa + t1 * d;
  float z0 = persp ? 1.0 / mix(1.0 / za, 1.0 / zb, t0) : mix(za, zb, t0);
  float z1 = persp ? 1.0 / mix(1.0 / za, 1.0 / zb, t1) : mix(za, zb, t1);
  /* Walk along the major axis (x in walk coordinates), a before b. */
  bool swap = abs(d.y) > abs(d.x);
  if (swap) {
    a = a.yx;
    b = b.yx;
  }
  if (b.x < a.x) {
    vec2 t = a;
    a = b;
    b = t;
    float tz = z0;
    z0 = z1;
    z1 = tz;
  }
  float u0 = floor(a.x - EL_WALK_SLACK) - 1.0, u1 = floor(b.x + EL_WALK_SLACK) + 1.0;
  if (u1 - u0 > float(EL_WALK_MAX)) {
    return true;
  }
  ivec2 size = textureSize(surface_depth, 0) - 1;
  bool outline = line_vis.w > 0.5;
  float world_per_px = 1.0 / frame.camera.x;
  vec4 prev = vec4(1.0, 0.0, 0.0, 0.0);
  vec4 cur = el_walk_column(u0, a, b, z0, z1, persp);
  for (int i = 0; i <= EL_WALK_MAX; i++) {
    float u = u0 + float(i);
    if (u > u1) {
      break;
    }
    vec4 next = el_walk_column(u + 1.0, a, b, z0, z1, persp);
    /* Rows that a centre cell of columns u-1..u+1 reaches with its 3x3 window, and the depths
     * of the segment over those columns. */
    float lo = 1e30, hi = -1e30, z_near = 1e30, z_far = 0.0;
    if (prev.x <= prev.y) {
      lo = min(lo, prev.x - 1.0);
      hi = max(hi, prev.y + 1.0);
      z_near = min(z_near, prev.z);
      z_far = max(z_far, prev.w);
    }
    if (cur.x <= cur.y) {
      lo = min(lo, cur.x - 1.0);
      hi = max(hi, cur.y + 1.0);
      z_near = min(z_near, cur.z);
      z_far = max(z_far, cur.w);
    }
    if (next.x <= next.y) {
      lo = min(lo, next.x - 1.0);
      hi = max(hi, next.y + 1.0);
      z_near = min(z_near, next.z);
      z_far = max(z_far, next.w);
    }
    for (float v = lo; v <= hi; v += 1.0) {
      ivec2 px = clamp(ivec2(swap ? vec2(v, u) : vec2(u, v)), ivec2(0), size);
      if (el_own_face(texelFetch(surface_id, px, 0).rg, f0, f1, f2, f3)) {
        return true;
      }
      /* Depth: for outline types any pixel of a window can be the one compared; for the others
       * only a centre cell. */
      bool centre = v >= cur.x && v <= cur.y;
      if (outline || centre) {
        float zn = outline ? z_near : cur.z, zf = outline ? z_far : cur.w;
        float inv = texelFetch(surface_depth, px, 0).r;
        float bias = 0.5 * (persp ? zf : 1.0) * world_per_px + line_vis.y * zf;
        if (inv <= 0.0 || zn <= (1.0 / inv) * (1.0 + 1e-5) + bias * 1.001) {
          return true;
        }
      }
    }
    prev = cur;
    cur = next;
  }
  return false;
}

/* The faces (surface ids) of segments first + k and first + k + 1 of a node of `count`
 * segments; 0 past its last. */
vec4 el_face_pair(int first, int count, int k)
{
  int i = first + min(k, count - 1), j = first + min(k + 1, count - 1);
  vec2 x = texelFetch(line_faces, ivec2(i % EL_FACES_PER_ROW, i / EL_FACES_PER_ROW), 0).rg;
  vec2 y = texelFetch(line_faces, ivec2(j % EL_FACES_PER_ROW, j / EL_FACES_PER_ROW), 0).rg;
  return vec4(k < count ? x : vec2(0.0), k + 1 < count ? y : vec2(0.0));
}

void el_cull()
{
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
}

void main()
{
  int n = node >> 2;
  float end = float((node >> 1) & 1), side = float(node & 1) * 2.0 - 1.0;
  vec4 tree = el_node_texel(n, 2);
  /* The coarsest chord within the tolerance on this segment's path: level 0 is the segment. */
  int level = 0;
  if (tree.x >= 0.0 && line_lod.x >= 0.0) {
    float px_per_unit = el_px_per_unit(el_node_texel(n, 3));
    level = tree.x * px_per_unit > line_lod.x ? 0 : (tree.y < 0.0 || tree.y * px_per_unit > line_lod.x ? 1 : (tree.z < 0.0 || tree.z * px_per_unit > line_lod.x ? 2 : 3));
  }
  int count = level == 0 ? 1 : (int(tree.w) >> (4 * (level - 1))) & 15;
  if (count == 0) {
    el_cull(); /* another segment draws this chord */
    return;
  }
  /* A crease chain whose whole projection fits in a disc of line_lod.y pixels. */
  if (line_lod.y > 0.0) {
    vec4 chain = el_node_texel(n, 4);
    if (2.0 * chain.w * el_px_per_unit(chain) <= line_lod.y) {
      el_cull();
      return;
    }
  }
  vec4 ea = el_node_texel(n, 0), eb = el_node_texel(n + count - 1, 1);
  vec3 w0 = (model * vec4(ea.xyz, 1.0)).xyz;
  vec3 w1 = (model * vec4(eb.xyz, 1.0)).xyz;
  vec4 v0 = frame.view * vec4(w0, 1.0);
  vec4 v1 = frame.view * vec4(w1, 1.0);
  vec4 c0 = frame.projection * v0;
  vec4 c1 = frame.projection * v1;
  float z0 = -v0.z, z1 = -v1.z;
  /* Clip the segment to the part in front of the eye (perspective w > 0). */
  const float eps = 1e-6;
  if (c0.w < eps && c1.w < eps) {
    el_cull();
    return;
  }
  float t0 = 0.0, t1 = 1.0;
  if (c0.w < eps) {
    t0 = (eps - c0.w) / (c1.w - c0.w);
  }
  else if (c1.w < eps) {
    t1 = (eps - c0.w) / (c1.w - c0.w);
  }
  vec4 a = mix(c0, c1, t0), b = mix(c0, c1, t1);
  float za = mix(z0, z1, t0), zb = mix(z0, z1, t1);
  float taper_a = mix(ea.w, eb.w, t0), taper_b = mix(ea.w, eb.w, t1);

  vec2 sa = (a.xy / a.w * 0.5 + 0.5) * frame.viewport.xy;
  vec2 sb = (b.xy / b.w * 0.5 + 0.5) * frame.viewport.xy;
  float ra = el_line_half_width(za, taper_a), rb = el_line_half_width(zb, taper_b);
  /* Every pixel centre the stroke covers lies within max(r) + 1/2 of the centre line. */
  float reach = max(ra, rb) + 0.5 + 1.0 / 64.0;

  /* The chord's faces: those of every segment it stands for (this one and the next count - 1). */
  vec4 f0 = el_face_pair(n, count, 0), f1 = count > 2 ? el_face_pair(n, count, 2) : vec4(0.0);
  vec4 f2 = count > 4 ? el_face_pair(n, count, 4) : vec4(0.0);
  vec4 f3 = count > 6 ? el_face_pair(n, count, 6) : vec4(0.0);
  if (line_vis.x <= 0.0 && line_lod.w > 0.5 && !el_line_may_show(sa, sb, za, zb, reach, f0, f1, f2, f3)) {
    el_cull();
    return;
  }
  line_ends = vec4(sa, sb);
  line_radius = vec2(ra, rb);
  line_depth = vec2(za, zb);
  line_faces0 = f0;
  line_faces1 = f1;
  line_faces2 = f2;
  line_faces3 = f3;

  vec2 along = sb - sa;
  float len = length(along);
  vec2 dir = len > 1e-6 ? along / len : vec2(1.0, 0.0);
  vec2 across = vec2(-dir.y, dir.x);
  vec2 s = (end < 0.5 ? sa - dir * reach : sb + dir * reach) + across * side * reach;
  gl_Position = vec4(s / frame.viewport.xy * 2.0 - 1.0, 0.0, 1.0);
}
