#include "silhouette.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace el {

float ViewPoint::facing(const glm::vec3& n, const glm::vec3& p) const {
    return orthographic ? glm::dot(n, to_viewer) : glm::dot(n, eye - p);
}

void compute_facing(const MeshData& mesh, const ViewPoint& view, std::vector<uint8_t>& facing) {
    const Geometry& g = mesh.geom;
    const size_t padded = g.plane_x.size();  // a multiple of 64
    facing.resize(padded);
    // facing = dot(n, eye) - plane offset (perspective) or dot(n, to_viewer) (orthographic):
    // reads only the face's own plane, 16 bytes, sequentially. One byte per face (not a bit) so
    // the edge pass reads it without shifts or masks.
    const glm::vec3 e = view.orthographic ? view.to_viewer : view.eye;
    const float ds = view.orthographic ? 0.0f : 1.0f;
    const float *px = g.plane_x.data(), *py = g.plane_y.data(), *pz = g.plane_z.data(), *pd = g.plane_d.data();
    uint8_t* out = facing.data();
#if defined(__SSE2__)
    const __m128 ex = _mm_set1_ps(e.x), ey = _mm_set1_ps(e.y), ez = _mm_set1_ps(e.z), dsv = _mm_set1_ps(ds);
    const __m128 zero = _mm_setzero_ps();
    const __m128i one = _mm_set1_epi8(1);
    auto four = [&](size_t i) {
        __m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(px + i), ex), _mm_mul_ps(_mm_loadu_ps(py + i), ey)),
                              _mm_mul_ps(_mm_loadu_ps(pz + i), ez));
        d = _mm_sub_ps(d, _mm_mul_ps(_mm_loadu_ps(pd + i), dsv));
        return _mm_castps_si128(_mm_cmpgt_ps(d, zero));  // 4 x (0 or -1)
    };
    for (size_t i = 0; i < padded; i += 16) {
        const __m128i lo = _mm_packs_epi32(four(i), four(i + 4)), hi = _mm_packs_epi32(four(i + 8), four(i + 12));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), _mm_and_si128(_mm_packs_epi16(lo, hi), one));
    }
#else
    for (size_t i = 0; i < padded; ++i) out[i] = px[i] * e.x + py[i] * e.y + pz[i] * e.z - pd[i] * ds > 0.0f;
#endif
}

uint64_t count_flips(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    if (a.size() != b.size()) return UINT64_MAX;
    uint64_t flips = 0;
    for (size_t i = 0; i < a.size(); ++i) flips += a[i] ^ b[i];
    return flips;
}

void collect_silhouettes(const MeshData& mesh, const std::vector<uint8_t>& facing, std::vector<uint32_t>& out) {
    const Classification& cls = mesh.cls;
    const size_t n = cls.silhouette_candidates.size();
    out.resize(n);  // reused across views: grows once, then no allocation
    const uint64_t* faces = cls.candidate_faces.data();
    const uint8_t* fb = facing.data();
    uint32_t* o = out.data();
    size_t count = 0;
    // Branch-free: always write the candidate's position, advance on a silhouette. Positions are
    // mapped to edge indices afterwards, for the few hits only.
    for (size_t i = 0; i < n; ++i) {
        const uint64_t f = faces[i];
        o[count] = uint32_t(i);
        count += fb[uint32_t(f)] ^ fb[f >> 32];
    }
    const uint32_t* edges = cls.silhouette_candidates.data();
    for (size_t k = 0; k < count; ++k) o[k] = edges[o[k]];
    out.resize(count);
}

}  // namespace el
