/*
 * EdgeLight native core: the one public header (C99-compatible).
 *
 * Conventions
 *  - Every function that can fail returns an el_status; on failure el_last_error() (thread-local)
 *    says what was wrong. Nothing here aborts the host process.
 *  - Arrays cross the boundary as caller-owned pointer + count. Getters copy into caller buffers
 *    whose capacity is given in elements of the array's record (an edge, a segment, ...).
 *  - Positions are float32 xyz, triangles uint32 triples, matrices float32 4x4 row-major with
 *    column vectors (p' = M * [x y z 1]^T, translation in elements 3, 7, 11) — numpy's layout of
 *    Blender's Matrix.
 *  - Handles are opaque; each *_create has a *_destroy. A view keeps its mesh's data alive, so
 *    handles may be destroyed in any order. A handle is not safe for concurrent use; distinct
 *    handles are.
 */
#ifndef EDGELIGHT_EDGELIGHT_H
#define EDGELIGHT_EDGELIGHT_H

#include <stdint.h>

#if defined(_WIN32)
#  define EL_API __declspec(dllexport)
#else
#  define EL_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Bumped on every change of a signature, struct layout or enum value below. */
#define EL_ABI_VERSION 12u

typedef enum el_status {
    EL_OK = 0,
    EL_ERR_NULL_POINTER = 1,      /* a required pointer was NULL */
    EL_ERR_INVALID_COUNT = 2,     /* zero or inconsistent count */
    EL_ERR_INDEX_OUT_OF_RANGE = 3,/* an index refers past its array */
    EL_ERR_NON_FINITE = 4,        /* NaN or Inf in an input */
    EL_ERR_OVERFLOW = 5,          /* a count whose derived sizes would overflow */
    EL_ERR_INVALID_ARGUMENT = 6,  /* a value outside its domain, or inconsistent inputs */
    EL_ERR_BUFFER_TOO_SMALL = 7,  /* caller's capacity below what is needed */
    EL_ERR_OUT_OF_MEMORY = 8,
    EL_ERR_INTERNAL = 9           /* a bug: please report the message */
} el_status;

EL_API uint32_t el_abi_version(void);
/* Message for the last failed call on this thread ("" after success). Valid until the next call. */
EL_API const char* el_last_error(void);
EL_API const char* el_status_name(el_status status);

/* ------------------------------------------------------------------------------------------ */
/* Mesh: topology and static classification                                                     */
/* ------------------------------------------------------------------------------------------ */

typedef struct el_mesh el_mesh;

/* triangle_edges entry for a triangle side that is no real edge (diagonal inside an n-gon). */
#define EL_NO_EDGE 0xFFFFFFFFu

/* Host marks, per edge (el_mesh_desc.edge_marks). They are copied into the edge flags. */
#define EL_MARK_SHARP     (1u << 16)
#define EL_MARK_SEAM      (1u << 17)
#define EL_MARK_FREESTYLE (1u << 18)
#define EL_MARK_BEVEL     (1u << 19) /* set by the library too where edge_bevel_weights > 0 */
#define EL_MARK_ALL       (EL_MARK_SHARP | EL_MARK_SEAM | EL_MARK_FREESTYLE | EL_MARK_BEVEL)

/* Static edge flags (el_mesh_get_edge_flags). */
#define EL_EDGE_LOOSE              (1u << 0)  /* no face (host edges only) */
#define EL_EDGE_BORDER             (1u << 1)  /* exactly one face */
#define EL_EDGE_MANIFOLD           (1u << 2)  /* exactly two faces */
#define EL_EDGE_NON_MANIFOLD       (1u << 3)  /* three or more faces */
#define EL_EDGE_CREASE             (1u << 4)  /* manifold, angle between normals > threshold */
#define EL_EDGE_CONVEX             (1u << 5)  /* manifold, bends away from the outside */
#define EL_EDGE_CONCAVE            (1u << 6)  /* manifold, bends towards the outside */
#define EL_EDGE_DEGENERATE         (1u << 7)  /* zero length, or next to a zero-area face */
#define EL_EDGE_MATERIAL_BOUNDARY  (1u << 8)  /* faces with different triangle_materials */
#define EL_EDGE_FLIPPED_WINDING    (1u << 9)  /* manifold, both faces run the edge the same way
                                                 even after orientation (non-orientable surface):
                                                 never convex, concave, crease or silhouette */

/* The largest |coordinate| a position may have: past it single-precision squares of distances
 * overflow (the shaders compute in single precision); el_mesh_create refuses it as
 * EL_ERR_NON_FINITE. */
#define EL_MAX_COORDINATE 1e15

/* Everything the library needs to know about one mesh. Optional arrays may be NULL. */
typedef struct el_mesh_desc {
    const float* positions;          /* 3 * vertex_count, each coordinate within EL_MAX_COORDINATE */
    uint32_t vertex_count;
    const uint32_t* triangles;       /* 3 * triangle_count, may be 0 triangles if edges given */
    uint32_t triangle_count;
    /* Optional host topology (Blender has it): unique edges and triangle -> edge map. Side s of
     * triangle t runs from corner s to corner (s+1)%3 and maps to triangle_edges[3t+s], which is
     * an edge index or EL_NO_EDGE. Both or neither. */
    const uint32_t* edges;           /* 2 * edge_count */
    uint32_t edge_count;
    const uint32_t* triangle_edges;  /* 3 * triangle_count */
    /* Optional, only with host edges: EL_MARK_* bits per edge, and bevel weights in [0, 1]. */
    const uint32_t* edge_marks;      /* edge_count */
    const float* edge_bevel_weights; /* edge_count */
    /* Optional: material slot per triangle (for material boundaries). */
    const uint32_t* triangle_materials; /* triangle_count */
    /* Optional: unit vertex normals (3 * vertex_count) for smooth contours; if NULL the library
     * computes angle-weighted ones. */
    const float* vertex_normals;
    /* Optional: per triangle, the unit normal of the face it was cut from (3 * triangle_count),
     * e.g. its polygon's normal in a triangulated n-gon. Classification and facing then use it
     * instead of the triangle's own normal, which a sliver of a near-planar polygon gets wrong,
     * and a zero-area triangle of a proper polygon (collinear corners along its side) is not
     * degenerate. Given in the input winding (the library negates it where it reorients); a
     * zero entry marks a face with no normal (degenerate). */
    const float* triangle_normals;
} el_mesh_desc;

/* Validates every input, builds edges and edge->face adjacency (or takes the host's), face
 * normals, dihedral angles and convexity. Classifies creases at 30 degrees until
 * el_mesh_classify is called.
 *
 * Orientation: the input winding of each triangle does not matter. Each connected component
 * (faces joined through manifold edges) gets one consistent winding: a closed component (every
 * triangle side on a manifold edge) the one with outward normals (positive signed volume), an
 * open one the winding of the larger part of its input area (a tie keeps its lowest-indexed
 * triangle as given). Face normals, edge normals N1/N2, angles, convexity, creases, facing,
 * silhouettes and computed vertex normals all follow that winding;
 * el_mesh_get_triangle_flips says which triangles it reverses. The caller's triangles are not
 * changed. */
EL_API el_status el_mesh_create(const el_mesh_desc* desc, el_mesh** out_mesh);
EL_API void el_mesh_destroy(el_mesh* mesh);

/* Crease threshold in degrees, in Blender's Auto Smooth / Smooth by Angle convention: an edge is
 * a crease when the angle between its two face normals exceeds the threshold. Freestyle's crease
 * angle is 180 minus this. Costs O(edges); nothing else is recomputed. */
EL_API el_status el_mesh_classify(el_mesh* mesh, float crease_angle_deg);

typedef struct el_mesh_info {
    uint32_t vertex_count;
    uint32_t triangle_count;
    uint32_t edge_count;
    uint32_t loose_edges;
    uint32_t border_edges;
    uint32_t manifold_edges;
    uint32_t non_manifold_edges;
    uint32_t crease_edges;
    uint32_t convex_edges;
    uint32_t concave_edges;
    uint32_t marked_edges;            /* any EL_MARK_* bit */
    uint32_t material_boundary_edges;
    uint32_t flipped_winding_edges;   /* manifold edges whose two faces ran them the same way in
                                         the input (before orientation); the edges still flagged
                                         EL_EDGE_FLIPPED_WINDING are a subset (non-orientable) */
    uint32_t reoriented_triangles;    /* triangles whose winding the library reversed */
    uint32_t degenerate_triangles;
    uint32_t degenerate_edges;
    uint32_t host_edges;              /* 1 if the host supplied edges */
    float crease_angle_deg;
} el_mesh_info;

EL_API el_status el_mesh_get_info(const el_mesh* mesh, el_mesh_info* out_info);
/* 2 vertex indices per edge. */
EL_API el_status el_mesh_get_edges(const el_mesh* mesh, uint32_t* out, uint32_t capacity_edges);
/* EL_EDGE_* | EL_MARK_* per edge. */
EL_API el_status el_mesh_get_edge_flags(const el_mesh* mesh, uint32_t* out, uint32_t capacity_edges);
/* Number of faces per edge. */
EL_API el_status el_mesh_get_edge_face_counts(const el_mesh* mesh, uint32_t* out, uint32_t capacity_edges);
/* 6 floats per edge: N1 xyz, N2 xyz (object space, unit). N1 is the normal of the face that runs
 * the edge from its first to its second vertex in the oriented winding (if any). Border edges: N2 = N1. Loose edges and
 * edges whose faces are all degenerate: zero vectors. */
EL_API el_status el_mesh_get_edge_normals(const el_mesh* mesh, float* out, uint32_t capacity_edges);
/* Angle between the two face normals in degrees (0 flat, 90 cube edge); 0 for non-manifold. */
EL_API el_status el_mesh_get_edge_angles(const el_mesh* mesh, float* out, uint32_t capacity_edges);
/* 3 floats per triangle, unit, or zero for a degenerate triangle; in the oriented winding, so
 * the negation of the input winding's normal for the triangles el_mesh_get_triangle_flips marks. */
EL_API el_status el_mesh_get_face_normals(const el_mesh* mesh, float* out, uint32_t capacity_triangles);
/* 1 per degenerate triangle, else 0. */
EL_API el_status el_mesh_get_degenerate_triangles(const el_mesh* mesh, uint8_t* out, uint32_t capacity_triangles);
/* 1 per triangle whose winding the library reversed to orient its component (see el_mesh_create),
 * else 0. */
EL_API el_status el_mesh_get_triangle_flips(const el_mesh* mesh, uint8_t* out, uint32_t capacity_triangles);
/* Faces of one edge: writes up to capacity triangle indices and the total count. */
EL_API el_status el_mesh_get_edge_faces(const el_mesh* mesh, uint32_t edge, uint32_t* out,
                                        uint32_t capacity, uint32_t* out_count);
/* Indices of edges whose flags contain all bits of `all_of` and any bit of `any_of` (0 = no
 * constraint). Pass out = NULL to get only the count. */
EL_API el_status el_mesh_select_edges(const el_mesh* mesh, uint32_t all_of, uint32_t any_of,
                                      uint32_t* out, uint32_t capacity, uint32_t* out_count);

/* ------------------------------------------------------------------------------------------ */
/* Chains: lines linked end to end, for tapering and styling along their length                 */
/* ------------------------------------------------------------------------------------------ */

/* Items (edges, contour segments) are linked where exactly two of them meet. An end where one
 * item ends is free (a line may taper there); where three or more meet, chains stop at a
 * junction without tapering. */
#define EL_CHAIN_CLOSED     (1u << 0) /* a loop: no ends */
#define EL_CHAIN_START_FREE (1u << 1) /* the chain's start is a free end */
#define EL_CHAIN_END_FREE   (1u << 2) /* the chain's end is a free end */

typedef struct el_chain_link {
    uint32_t chain;  /* index into the chains array */
    float s0;        /* arc length from the chain's start to the item's first endpoint */
    float s1;        /* ... and to its second endpoint (object-space units) */
} el_chain_link;

typedef struct el_chain {
    uint32_t item_count;
    float length;    /* object-space arc length */
    uint32_t flags;  /* EL_CHAIN_* */
} el_chain;

/* Chains the given edges (distinct edge indices) by their shared vertices. out_links gets one
 * record per input edge (edge_count of them), out_chains up to capacity_chains records; at most
 * edge_count chains exist. */
EL_API el_status el_mesh_chain_edges(const el_mesh* mesh, const uint32_t* edges, uint32_t edge_count,
                                     el_chain_link* out_links, el_chain* out_chains,
                                     uint32_t capacity_chains, uint32_t* out_chain_count);

/* Line nodes: chains of line segments as the add-on's line pass draws them at the screen's
 * resolution (docs/lines.md). The segments are put in chain order (by chain, then arc length,
 * from `links` as el_mesh_chain_edges or el_view_chain_contours wrote them; `links` NULL: each
 * segment a chain of its own) and each run of segments that continue one another is cut into
 * groups of up to EL_LINE_GROUP; each group is a binary tree of chords over its segments (halved
 * recursively, the segments its leaves, at most three levels above them). One record per
 * segment, in chain order, EL_LINE_NODE_FLOATS floats:
 *   [0..3]   a.xyz, taper at a: the segment's first point along the chain and that end's taper
 *            value (taper: two values per segment, at p0 and p1)
 *   [4..7]   b.xyz, taper at b: its last point
 *   [8..10]  the error of its parent chord, grandparent, great-grandparent (-1: none): no point
 *            of the segments a chord stands for lies farther from it (errors never shrink
 *            towards the root)
 *   [11]     sum over those three levels l = 0, 1, 2 of count_l * 16^l: count_l the segments
 *            of that chord when this segment is its first, else 0
 *   [12..15] the group's bounding sphere (centre, radius)
 *   [16..19] the bounding sphere of the segment's whole chain, with EL_LINE_NODES_CHAIN_SPHERES
 *            (radius -1 without)
 * A chord of count segments starting at place i runs from a of record i to b of record
 * i + count - 1. Distances are in the input's units. out_order[i] (count values) is the input
 * segment at place i; out_nodes takes count records (capacity_nodes counts records). count must
 * be below 2^24 (places are exact as floats). */
#define EL_LINE_GROUP 8u
#define EL_LINE_NODE_FLOATS 20u
#define EL_LINE_NODES_CHAIN_SPHERES (1u << 0)
EL_API el_status el_line_nodes(const float* p0, const float* p1, const float* taper, const el_chain_link* links,
                               uint32_t count, uint32_t flags, float* out_nodes, uint32_t capacity_nodes,
                               uint32_t* out_order);

/* ------------------------------------------------------------------------------------------ */
/* View: silhouettes and smooth contours, cached per view                                       */
/* ------------------------------------------------------------------------------------------ */

typedef struct el_view el_view;

typedef enum el_projection {
    EL_PERSPECTIVE = 0,
    EL_ORTHOGRAPHIC = 1
} el_projection;

typedef struct el_camera {
    int32_t projection;        /* el_projection */
    float eye[3];              /* world space, perspective */
    float view_dir[3];         /* world space, orthographic: direction the camera looks along */
    float object_to_world[16]; /* row-major, column vectors; must be invertible */
} el_camera;

/* What el_view_update computes. */
#define EL_VIEW_SILHOUETTES (1u << 0)
#define EL_VIEW_CONTOURS    (1u << 1)

typedef struct el_view_stats {
    uint64_t updates;          /* calls of el_view_update */
    uint64_t cache_hits;       /* calls that found the same camera and did nothing */
    uint64_t facing_passes;    /* per-face facing recomputations */
    uint64_t faces_flipped;    /* faces whose facing changed, summed over updates */
    uint64_t silhouette_rebuilds; /* edge lists rebuilt because a face flipped */
    uint64_t contour_passes;   /* contour recomputations */
    uint32_t silhouette_edges; /* current */
    uint32_t contour_segments; /* current */
} el_view_stats;

EL_API el_status el_view_create(const el_mesh* mesh, el_view** out_view);
EL_API void el_view_destroy(el_view* view);
/* Recomputes what `what` asks for if the camera (or `what`) changed; an identical camera costs a
 * comparison. *out_changed (optional) is 1 when the outputs changed, so the host re-uploads only
 * then. */
EL_API el_status el_view_update(el_view* view, const el_camera* camera, uint32_t what,
                                uint32_t* out_changed);
/* Manifold edges whose two faces face differently (front/back); ascending edge indices. */
EL_API el_status el_view_get_silhouettes(const el_view* view, uint32_t* out, uint32_t capacity,
                                         uint32_t* out_count);
/* Per-face facing bit for the current camera (1 = front-facing), in the oriented winding. */
EL_API el_status el_view_get_facing(const el_view* view, uint8_t* out, uint32_t capacity_triangles);
/* Smooth contour segments (zero set of n.v, Hertzmann & Zorin): 6 floats per segment, two
 * object-space endpoints; out_triangles (optional) gets the triangle of each segment. */
EL_API el_status el_view_get_contours(const el_view* view, float* out_points,
                                      uint32_t* out_triangles, uint32_t capacity_segments,
                                      uint32_t* out_count);
/* Chains the current contour segments through the triangle sides they share (one link per
 * segment, in el_view_get_contours order). */
EL_API el_status el_view_chain_contours(const el_view* view, el_chain_link* out_links,
                                        uint32_t capacity_links, el_chain* out_chains,
                                        uint32_t capacity_chains, uint32_t* out_chain_count);
EL_API el_status el_view_get_stats(const el_view* view, el_view_stats* out_stats);

/* ------------------------------------------------------------------------------------------ */
/* Silhouettes on the rounded outline (docs/lines.md, "Silhouettes of rounded edges")           */
/* ------------------------------------------------------------------------------------------ */

/* A mesh's convex rounded edges and corner patches, as the surface pass's outline textures hold
 * them (shaders/outline_layout.json is the one description; a test pins these to it). An edge
 * record is EL_OUTLINE_EDGE_TEXELS vec4s, object space:
 *   (N1, radius), (N2, 0), (p0, cut at p0), (p1, cut at p1), (turn of N1, -), (turn of N2, -)
 * at t along the edge a side's normal is normalize(N + (t - 1/2) turn); a cut is nonzero where a
 * concave fillet fills the corner at that end (the end does not move); "-" is not read here (the
 * surface pass's concave-end flags). A corner record is
 * EL_OUTLINE_CORNER_TEXELS vec4s: (ball centre, radius), (vertex position, 0), and the three
 * sectors' normals. */
#define EL_OUTLINE_EDGE_TEXELS 6u
#define EL_OUTLINE_CORNER_TEXELS 5u
/* A corner's arc is cut into at most this many chords (el_outline_lines). */
#define EL_OUTLINE_ARC_MAX_PIECES 8u

typedef struct el_outline el_outline;

typedef struct el_outline_desc {
    const float* edges;              /* edge_count records of 4 * EL_OUTLINE_EDGE_TEXELS floats */
    const uint32_t* edge_vertices;   /* 2 per edge record: the mesh vertices of its p0 and p1 */
    uint32_t edge_count;
    const float* corners;            /* corner_count records of 4 * EL_OUTLINE_CORNER_TEXELS floats */
    const uint32_t* corner_vertices; /* 1 per corner record: the mesh vertex it rounds */
    uint32_t corner_count;
} el_outline_desc;

/* The camera an instance is seen with: its transform and the frame's camera, world space. */
typedef struct el_outline_view {
    int32_t projection;        /* el_projection */
    float eye[3];              /* perspective */
    float view_dir[3];         /* orthographic: the direction the camera looks along */
    float object_to_world[16]; /* row-major, column vectors (el_camera's layout) */
    float world_to_view[16];
    float view_to_clip[16];
    float width;               /* the image, pixels */
    float height;
} el_outline_view;

/* Line segments of one type, object space, with what the line pass draws them with. Input:
 * count segments; vertices[2 i], [2 i + 1] the mesh vertices of segment i's p0 and p1. faces and
 * links are each optional (NULL); each is given out where it is given in. */
typedef struct el_outline_segments {
    const uint32_t* vertices;
    const float* p0;              /* 3 per segment */
    const float* p1;
    const float* n1;              /* 3 per segment: the faces' normals */
    const float* n2;
    const float* taper;           /* 2 per segment: at p0, at p1 */
    const float* faces;           /* 2 per segment: the surface ids of its faces */
    const el_chain_link* links;   /* its chain and arc lengths */
    uint32_t count;
} el_outline_segments;

typedef struct el_outline_out {
    float* p0;                    /* 3 per segment */
    float* p1;
    float* n1;
    float* n2;
    float* taper;                 /* 2 per segment */
    float* faces;                 /* 2 per segment; required where the input has faces */
    el_chain_link* links;         /* required where the input has links */
    uint32_t capacity;            /* segments; (2 + EL_OUTLINE_ARC_MAX_PIECES) * count always suffices */
} el_outline_out;

EL_API el_status el_outline_create(const el_outline_desc* desc, el_outline** out_outline);
EL_API void el_outline_destroy(el_outline* outline);
/* The silhouette segments `in` (along mesh edges) with those on convex rounded edges moved onto
 * their fillets' outline as `view` sees them, their corners joined (where a corner patch's ball
 * rounds them, on its circle, with an arc of it appended in chords), and an unmoved silhouette
 * they run on into ending at the fillet's foot, joined to them by an appended segment. Writes
 * the first in->count segments in input order, then the appended ones; *out_count is the total
 * (also on EL_ERR_BUFFER_TOO_SMALL, so the caller can retry). */
EL_API el_status el_outline_lines(const el_outline* outline, const el_outline_view* view,
                                  const el_outline_segments* in, el_outline_out* out, uint32_t* out_count);
/* Per triangle, the rounded edges (or corner patches) whose strip (or zone) may cross it, where
 * the mesh's faces are wider than every strip and zone: the items at its corners (an item's
 * vertices: item_verts, verts_per_item each, -1 for none) lying flat with it (|N_t . N| >=
 * cos_max for one of the item's normals_per_item normals) or, with EL_OUTLINE_FANS_OWN_SIDES
 * (items are edges, verts_per_item 2), running along its own side. out: per triangle `per`
 * floats, item number + 1 (0: none), its own sides first, then the others in the order its
 * corners and their items come. Triangles in the caller's order (the surface batch's):
 * tri_verts 3 and tri_normals 3 floats per triangle. The surface pass's outline lists
 * (shaders/outline_layout.json). */
#define EL_OUTLINE_FANS_OWN_SIDES (1u << 0)
EL_API el_status el_outline_fans(const uint32_t* tri_verts, const float* tri_normals, uint32_t triangle_count,
                                 const int32_t* item_verts, uint32_t verts_per_item, const float* item_normals,
                                 uint32_t normals_per_item, uint32_t item_count, uint32_t flags, float cos_max,
                                 uint32_t per, float* out);
/* The fillet's outline point (rounded_outline.glsl's el_fillet_outline), for count convex fillets
 * of radius 1 between faces of unit normals na, nb seen along v (unit, towards the eye): out_p
 * the unit direction from the axis to the outline point, turned towards the sharp edge (0 where
 * no silhouette), out_c where the sharp edge lies from the axis, out_silhouette 1 where one face
 * faces the eye and the other does not. 3 floats per vector. */
EL_API el_status el_fillet_outline(const float* na, const float* nb, const float* v, uint32_t count,
                                   float* out_p, float* out_c, uint8_t* out_silhouette);

/* ------------------------------------------------------------------------------------------ */
/* Rounded edges: what the edge pass shades a band with                                         */
/* ------------------------------------------------------------------------------------------ */

/* Corner patches (docs/highlight_math.md, "Corner patches"): the vertices where exactly three
 * chosen edges meet, all convex or all concave, no other `stop` edge there (NULL: the chosen),
 * whose fan falls into three sectors (each two edges' facing sides turning by under 40 degrees),
 * not too near one plane, the ball's centre within 4 radii. Per corner, vertices ascending:
 * out_vertex, out_edges (its three edges, ascending), out_normals (9: the sectors' unit normals,
 * AB, BC, CA), out_radius (the smallest of its edges'), out_centre (3: the ball's, r under the
 * three faces, or over them for concave edges), out_fold (+1 convex, -1 concave). edge_normals:
 * 6 floats an edge (N1, N2, oriented alike); convex, chosen, stop: one byte an edge; radius: a
 * chosen edge's (finite; the others' are not read). capacity: corners the outputs hold
 * (vertex_count always suffices); *out_count is set also on EL_ERR_BUFFER_TOO_SMALL. */
EL_API el_status el_corner_patches(const float* positions, uint32_t vertex_count, const uint32_t* edges,
                                   const float* edge_normals, const uint8_t* convex, const uint8_t* chosen,
                                   const float* radius, const uint8_t* stop, uint32_t edge_count, uint32_t capacity,
                                   uint32_t* out_vertex, uint32_t* out_edges, float* out_normals, float* out_radius,
                                   float* out_centre, float* out_fold, uint32_t* out_count);

/* A mesh's polygons, as the host has them (Blender's): each one's loops, a loop's vertex and the
 * edge from it to the next loop's, each loop triangle's polygon, each polygon's unit normal in
 * the host's winding (zero: no area). */
typedef struct el_polygons {
    const uint32_t* start;      /* per polygon: its first loop */
    const uint32_t* total;      /* per polygon: its loop count (at least 1) */
    uint32_t polygon_count;
    const uint32_t* loop_vert;  /* per loop */
    const uint32_t* loop_edge;  /* per loop: an index into the edges of the call */
    uint32_t loop_count;
    const uint32_t* tri_poly;   /* per triangle */
    uint32_t triangle_count;
    const float* normal;        /* 3 per polygon */
} el_polygons;

/* Where each selected rounded edge's band ends on its two faces (docs/highlight_math.md, "Band
 * ends"): 4 angles a selected edge, (at its first vertex on N1's face, on N2's, at its second on
 * N1's, on N2's), the cut's angle from the edge towards the face's inside: pi/2 square, a mitre
 * (half the face's corner) where the face's next side there is rounded too, leaning past the
 * vertex (up to 3 pi/4) at a joint of one chain of rounded edges, the corner itself where it is
 * sharper than square, never under 0.02. faces: 2 per selected edge, its triangles (-1 none).
 * With smooth (a byte an edge) and edge_polys (2 per edge, its first two polygons, -1 none), a
 * face is its smooth patch: the side at the vertex is the first round the fan not smooth, and a
 * band whose fan comes back to its own edge ends square. */
EL_API el_status el_band_ends(const el_polygons* polys, const float* positions, uint32_t vertex_count,
                              const uint32_t* edges, const float* edge_normals, const uint8_t* rounded,
                              const uint8_t* smooth, const int32_t* edge_polys, uint32_t edge_count,
                              const uint32_t* selected, const int32_t* faces, uint32_t count, float* out);

/* Which edges each material slot rounds (a material's Rounded Edges settings). el_slot_rules.rules: */
#define EL_RULE_ANGLE (1u << 0) /* edges folded past angle_deg */
#define EL_RULE_SHARP (1u << 1) /* edges marked sharp */
#define EL_RULE_BEVEL (1u << 2) /* edges with a bevel weight: alone, the weight scales the radius */

typedef struct el_slot_rules {
    uint32_t enabled;  /* the material rounds edges at all */
    float radius;      /* object space */
    float K;           /* the highlight's strength: 0 rounds nothing */
    uint32_t rules;    /* EL_RULE_* */
    float angle_deg;
} el_slot_rules;

/* The rule, per edge of a mesh: an edge is rounded where it is manifold, not degenerate, has a
 * second face, both faces' slots round edges (enabled, radius and K above 0) and either slot's
 * rules pick it; it takes the smaller radius of the slots that pick it. flags (EL_EDGE_*),
 * angles (degrees), face_a / face_b (each edge's first two triangles, -1 none), sharp (a byte),
 * bevel (the weight) per edge; tri_slot per triangle (below slot_count). Out per edge (any
 * NULL but chosen and radius is not written): chosen (a byte), radius (the rounding radius,
 * inf where no slot picks it), slot_a / slot_b (its faces' slots, 0 without a face), pick_a /
 * pick_b (whether that slot's rules pick it), rad_a / rad_b (the radius that slot asks). */
EL_API el_status el_edge_rules(const uint32_t* flags, const float* angles, const int32_t* face_a, const int32_t* face_b,
                               const uint8_t* sharp, const float* bevel, uint32_t edge_count, const uint32_t* tri_slot,
                               uint32_t triangle_count, const el_slot_rules* slots, uint32_t slot_count,
                               uint8_t* out_chosen, float* out_radius, uint32_t* out_slot_a, uint32_t* out_slot_b,
                               uint8_t* out_pick_a, uint8_t* out_pick_b, float* out_rad_a, float* out_rad_b);

/* A lower bound of how wide each of `count` edges' faces are across it (the radius clamp's first
 * look, before any walk): per edge and side, the farthest from the edge's line of three corners
 * of that side's polygon (its first loop's, and a third and two thirds of the way round), 0
 * where the side has none. edges: 2 vertices per edge; edge_polys: 2 polygons per edge (-1:
 * none); polys: start, total and loop_vert are read. out: 2 doubles per edge. */
EL_API el_status el_width_bounds(const el_polygons* polys, const float* positions, uint32_t vertex_count,
                                 const uint32_t* edges, const int32_t* edge_polys, uint32_t count, double* out);

/* The two normals each selected rounded edge's arc runs between at each of its ends, as the
 * mesh gives them (edge_normals: N1, N2, 6 floats an edge, the faces' own), each turned to the
 * normal its side is shaded with there: the corner normal (corner_normals, 9 floats a triangle,
 * its corners in tri_verts order) of that side's triangle (edge_faces: the edge's first two
 * triangles, -1 none) at that end, signed as the library's normal, where it lies within
 * max_turn_deg of it. An edge keeps its faces' normals at both ends where a corner normal at
 * either end is missing or turned too far, or where taking them would turn the arc round (the
 * fold's sign about the edge). out: 12 floats a selected edge, (N1, N2) at its first vertex,
 * then at its second. */
EL_API el_status el_shading_normals(const float* positions, uint32_t vertex_count, const uint32_t* edges,
                                    const float* edge_normals, const int32_t* edge_faces, uint32_t edge_count,
                                    const uint32_t* tri_verts, const float* corner_normals, uint32_t triangle_count,
                                    const uint32_t* selected, uint32_t count, float max_turn_deg, float* out);

/* ------------------------------------------------------------------------------------------ */
/* View lines of many instances of one mesh, in one call                                        */
/* ------------------------------------------------------------------------------------------ */

/* The taper value of a segment end with no free end on its chain (el_view_lines_desc). */
#define EL_NO_TAPER 1.0e9f
/* el_view_lines_desc.flags */
#define EL_VIEW_LINES_TAPER (1u << 0) /* taper values from the chains (else EL_NO_TAPER) */

typedef struct el_view_lines el_view_lines;

typedef struct el_view_lines_desc {
    const el_mesh* mesh;
    const el_outline* outline;     /* NULL: silhouettes stay on the sharp edges */
    const float* edge_faces;       /* 2 per mesh edge, what a segment along it carries as faces; NULL: none */
    const el_outline_view* views;  /* one per instance: its transform and the camera */
    uint32_t view_count;
    uint32_t flags;                /* EL_VIEW_LINES_* */
} el_view_lines_desc;

/* Each instance's silhouettes (el_view_update's, in ascending edge order) as line segments:
 * object-space ends, the edge's two face normals, per end its taper value (the distance to its
 * chain's nearest free end over the chain's length, or EL_NO_TAPER), its faces (edge_faces) and
 * its chain record (chains of the instance's own silhouettes, el_mesh_chain_edges'), moved onto
 * the rounded outline with an outline (el_outline_lines). Instances run in parallel. An
 * instance whose own transform the view refuses (singular, say) gets no segments, its status in
 * el_view_lines_get_offsets' out_status and its message from el_view_lines_get_message; the call
 * fails for bad arguments, with an outline also for any view whose camera is unusable (its
 * projection, size or matrices). */
EL_API el_status el_view_lines_create(const el_view_lines_desc* desc, el_view_lines** out_lines);
EL_API void el_view_lines_destroy(el_view_lines* lines);
/* out_offsets: view_count + 1 values, instance i's segments are [offsets[i], offsets[i + 1]);
 * out_status (optional): view_count el_status values. */
EL_API el_status el_view_lines_get_offsets(const el_view_lines* lines, uint32_t* out_offsets, uint32_t capacity,
                                           int32_t* out_status);
/* What went wrong with instance `view`'s lines ("" where nothing did), valid while `lines` is. */
EL_API el_status el_view_lines_get_message(const el_view_lines* lines, uint32_t view, const char** out_message);
/* All segments, instance after instance, into out (its capacity: offsets[view_count] at least;
 * faces and links required where the desc had edge_faces, and always). */
EL_API el_status el_view_lines_copy(const el_view_lines* lines, el_outline_out* out);

/* ------------------------------------------------------------------------------------------ */
/* Highlight math (docs/highlight_math.md)                                                      */
/* ------------------------------------------------------------------------------------------ */

typedef struct el_highlight_table el_highlight_table;

typedef enum el_table_layout {
    /* The paper's table: F(phi, m) at phi_count values of phi uniform on [0, pi/2] and the
     * integers m = 1, 2, ..., m_count. Lookups between integer m interpolate linearly. */
    EL_TABLE_PAPER = 0,
    /* EdgeLight's: x = phi / phi_end(m) uniform on [0, 1] with phi_end(m) = min(pi/2, c/sqrt(m)),
     * t = ln(m) / ln(m_max) uniform on [0, 1]; stores sqrt(m) * F. Covers any real m in
     * [1, m_max]. */
    EL_TABLE_WARPED = 1,
    /* EdgeLight's default: the grid and stored sqrt(m) * F of WARPED, but with a smooth
     * phi_end(m) = ((2/pi)^6 + m^3/c^6)^(-1/6) and 4 x 4-point (bicubic Lagrange) interpolation:
     * 16 texel reads instead of 4, and a table 8 times smaller than the paper's for a smaller
     * error over m in [1, m_max] (docs/highlight_math.md, "Table study"). phi_count and m_count
     * >= 4. */
    EL_TABLE_BICUBIC = 2
} el_table_layout;

typedef struct el_table_desc {
    int32_t layout;     /* el_table_layout */
    uint32_t phi_count; /* samples along phi (texture width), >= 2 */
    uint32_t m_count;   /* samples along the exponent (texture height), >= 2 */
    float m_max;        /* WARPED, BICUBIC: largest exponent covered, in (1, 1e6]; PAPER: ignored (= m_count) */
} el_table_desc;

/* The recommended table (docs/highlight_math.md, "Table study"). */
#define EL_TABLE_DEFAULT_DESC {EL_TABLE_BICUBIC, 96u, 128u, 10001.0f}

typedef struct el_table_info {
    int32_t layout;
    uint32_t phi_count;
    uint32_t m_count;
    float m_max;
    float warp_c;       /* WARPED: c in phi_end(m) = min(pi/2, c/sqrt(m)); BICUBIC: c of its phi_end */
} el_table_info;

EL_API el_status el_highlight_table_create(const el_table_desc* desc, el_highlight_table** out);
EL_API void el_highlight_table_destroy(el_highlight_table* table);
EL_API el_status el_highlight_table_get_info(const el_highlight_table* table, el_table_info* out);
/* Row-major float32, m_count rows of phi_count texels: upload as an R32F texture of width
 * phi_count and height m_count. */
EL_API el_status el_highlight_table_copy(const el_highlight_table* table, float* out,
                                         uint64_t capacity_floats);
/* F(phi, m) = integral_0^phi cos^m(theta) dtheta through the table, float32, phi in
 * [-pi/2, pi/2] (F is odd), m in the table's range. */
EL_API el_status el_highlight_table_lookup(const el_highlight_table* table, float phi, float m,
                                           float* out);

/* Exact F(phi, m) in double (regularized incomplete beta), phi in [-pi/2, pi/2] (float32 pi/2
 * accepted), 0 <= m <= 1e9. */
EL_API el_status el_cos_power_integral(double phi, double m, double* out);
/* Closed-form part: integral_a^b cos^n(t) sin(t) dt = (cos^(n+1) a - cos^(n+1) b) / (n + 1),
 * a, b in [-pi/2, pi/2]. */
EL_API el_status el_cos_power_sin_integral(double a, double b, double n, double* out);
/* Blend weight W = K * r_e / (d * r_max), clamped to [0, 1]. */
EL_API el_status el_highlight_weight(float K, float r_e, float d, float r_max, float* out_w);

/* One pixel's rounded edge: a cylinder of radius r_e around the edge line through `point` with
 * direction `edge_dir`, its normals sweeping from n1 to n2 about the edge. Directions need not be
 * unit. Light and half vectors are taken at `point`. */
typedef struct el_highlight_input {
    float point[3];     /* a point on the edge (world) */
    float edge_dir[3];  /* edge direction */
    float n1[3];        /* normal of the first face (rejected within 0.057 degrees of edge_dir) */
    float n2[3];        /* normal of the second face */
    float eye[3];       /* perspective: eye position */
    float view_dir[3];  /* orthographic: direction the camera looks along */
    int32_t projection; /* el_projection */
    float light[3];     /* direction towards the light (sun), or light position (point) */
    int32_t light_is_point;
    float shininess;    /* Blinn exponent n >= 1 (real) */
    float radius;       /* r_e, world units */
    float K;            /* blend gain: W = K r_e / (d r_max); K = focal length in pixels gives
                           true pixel coverage (docs/highlight_math.md) */
    float ortho_scale;  /* orthographic: d used in W (world size that K pixels span) */
} el_highlight_input;

typedef struct el_highlight_result {
    float specular;     /* I_s specular factor: mean of max(N.H,0)^n over the visible arc,
                           weighted by projected width (in [0, 1]) */
    float diffuse;      /* the same with max(N.L,0) */
    float weight;       /* W, clamped to [0, 1]; 0 when nothing of the arc is visible. Fades to 0
                           as the view comes within ~1.1 degrees of the edge axis (from 0 at
                           |E x V| = 0.01 to full at 0.02) */
    float r_max;        /* 1 / |P.(Na - Nb)| over the visible arc; 0 when the visible width is
                           0 (nothing visible, or a flat edge facing the eye) */
    float visible_fraction; /* visible projected width / full projected width */
} el_highlight_result;

/* Float32 evaluation through the table: the same steps as shaders' edge_highlight pass. */
EL_API el_status el_highlight_eval(const el_highlight_table* table, const el_highlight_input* in,
                                   el_highlight_result* out);
/* count must be > 0. */
EL_API el_status el_highlight_eval_batch(const el_highlight_table* table,
                                         const el_highlight_input* in, uint32_t count,
                                         el_highlight_result* out);
/* Double-precision reference: adaptive quadrature of the full arc integral in 3-D, no table, no
 * closed form. For tests and benchmarks. */
EL_API el_status el_highlight_reference(const el_highlight_input* in, el_highlight_result* out);

#ifdef __cplusplus
}
#endif

#endif /* EDGELIGHT_EDGELIGHT_H */
