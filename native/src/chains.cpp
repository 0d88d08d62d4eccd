#include "chains.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <utility>

namespace el {

namespace {

// CSR map from each distinct key to the item ends (2 * item + end) that carry it.
struct KeyIndex {
    std::vector<uint32_t> key_of_end;  // dense key id per item end
    std::vector<uint32_t> offsets;     // per dense key
    std::vector<uint32_t> ends;

    explicit KeyIndex(const std::vector<ChainItem>& items) {
        // Sort (key, end) pairs directly: contiguous and branch-light, several times faster
        // than sorting end indices through their keys; by radix (16 bits a pass, as many passes
        // as the largest key needs: two for vertex indices), stable, so equal keys keep their
        // ends in order, as the comparison sort of the pairs did.
        const size_t n = items.size() * 2;
        std::vector<std::pair<uint64_t, uint32_t>> sorted(n), scratch(n);
        uint64_t largest = 0;
        for (size_t e = 0; e < n; ++e) {
            sorted[e] = {items[e / 2].key[e % 2], uint32_t(e)};
            largest = std::max(largest, sorted[e].first);
        }
        std::vector<uint32_t> count(size_t(1) << 16);
        for (unsigned shift = 0; shift < 64 && (largest >> shift) != 0; shift += 16) {
            std::fill(count.begin(), count.end(), 0u);
            for (const auto& p : sorted) ++count[(p.first >> shift) & 0xFFFF];
            uint32_t sum = 0;
            for (uint32_t& c : count) sum += std::exchange(c, sum);
            for (const auto& p : sorted) scratch[count[(p.first >> shift) & 0xFFFF]++] = p;
            sorted.swap(scratch);
        }
        key_of_end.assign(n, 0);
        ends.resize(n);
        offsets.reserve(n + 1);
        offsets.push_back(0);
        for (size_t i = 0; i < n; ++i) {
            if (i > 0 && sorted[i].first != sorted[i - 1].first) offsets.push_back(uint32_t(i));
            key_of_end[sorted[i].second] = uint32_t(offsets.size() - 1);
            ends[i] = sorted[i].second;
        }
        offsets.push_back(uint32_t(n));
    }
    uint32_t degree(uint32_t k) const { return offsets[k + 1] - offsets[k]; }
    // The other item end at a degree-2 key.
    uint32_t partner(uint32_t end) const {
        const uint32_t k = key_of_end[end];
        return ends[offsets[k]] == end ? ends[offsets[k] + 1] : ends[offsets[k]];
    }
};

}  // namespace

Chains build_chains(const std::vector<ChainItem>& items) {
    Chains out;
    const uint32_t n = uint32_t(items.size());
    out.links.assign(n, el_chain_link{EL_NO_EDGE, 0.0f, 0.0f});
    if (n == 0) return out;
    const KeyIndex idx(items);
    auto links_on = [&](uint32_t end) {
        // An end continues into another item when exactly two ends meet and the other is not
        // this item's own other end (a zero-length item).
        const uint32_t k = idx.key_of_end[end];
        return idx.degree(k) == 2 && idx.partner(end) / 2 != end / 2;
    };
    auto length = [&](uint32_t i) { return glm::distance(items[i].point[0], items[i].point[1]); };

    // Walk one chain from item `start` entering through end `enter` (0 or 1); returns the items
    // in order with the end each was entered by.
    std::vector<std::pair<uint32_t, uint32_t>> walk;
    auto trace = [&](uint32_t start, uint32_t enter) {
        walk.clear();
        uint32_t item = start, in = enter;
        while (true) {
            walk.emplace_back(item, in);
            out.links[item].chain = 0;  // visited marker, overwritten below
            const uint32_t exit_end = 2 * item + (1 - in);
            if (!links_on(exit_end)) break;
            const uint32_t next = idx.partner(exit_end);
            if (next / 2 == start) break;  // closed the loop
            item = next / 2;
            in = next % 2;
        }
    };
    auto emit = [&](bool closed) {
        el_chain c{};
        c.item_count = uint32_t(walk.size());
        float s = 0.0f;
        for (auto [item, in] : walk) {
            el_chain_link& l = out.links[item];
            l.chain = uint32_t(out.chains.size());
            const float len = length(item);
            // s0/s1 belong to the item's own first/second endpoint, whichever way it is walked.
            (in == 0 ? l.s0 : l.s1) = s;
            s += len;
            (in == 0 ? l.s1 : l.s0) = s;
        }
        c.length = s;
        if (closed) {
            c.flags = EL_CHAIN_CLOSED;
        } else {
            const auto [first, first_in] = walk.front();
            const auto [last, last_in] = walk.back();
            if (idx.degree(idx.key_of_end[2 * first + first_in]) == 1) c.flags |= EL_CHAIN_START_FREE;
            if (idx.degree(idx.key_of_end[2 * last + (1 - last_in)]) == 1) c.flags |= EL_CHAIN_END_FREE;
        }
        out.chains.push_back(c);
    };

    // Open chains first, each from an end that does not link backwards.
    for (uint32_t i = 0; i < n; ++i) {
        if (out.links[i].chain != EL_NO_EDGE) continue;
        for (uint32_t end = 0; end < 2; ++end) {
            if (out.links[i].chain != EL_NO_EDGE) break;
            if (!links_on(2 * i + end)) {
                trace(i, end);
                emit(false);
            }
        }
    }
    // What is left are loops.
    for (uint32_t i = 0; i < n; ++i) {
        if (out.links[i].chain != EL_NO_EDGE) continue;
        trace(i, 0);
        emit(true);
    }
    return out;
}

namespace {

using dvec3 = glm::dvec3;

// Distance from p to the segment a -> b.
double distance_to_segment(const dvec3& p, const dvec3& a, const dvec3& b) {
    const dvec3 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    const double t = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + t * ab);
}

// A bounding sphere of points [begin, end): the centre of their box, the largest distance.
struct Sphere {
    dvec3 centre{0.0};
    double radius = -1.0;
};

template <class It>
Sphere sphere_of(It begin, It end) {
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (It it = begin; it != end; ++it) {
        lo = glm::min(lo, *it);
        hi = glm::max(hi, *it);
    }
    Sphere s{0.5 * (lo + hi), 0.0};
    for (It it = begin; it != end; ++it) s.radius = std::max(s.radius, glm::distance(*it, s.centre));
    return s;
}

}  // namespace

LineNodes build_line_nodes(const float* p0, const float* p1, const float* taper, const el_chain_link* links,
                           uint32_t count, bool chain_spheres) {
    LineNodes out;
    const uint32_t n = count;
    out.order.resize(n);
    std::iota(out.order.begin(), out.order.end(), 0u);
    if (links) {
        // By chain (counting sort: chain indices are below the item count where the library
        // numbered them), then by arc length within each chain.
        auto mid = [&](uint32_t i) { return double(links[i].s0) + double(links[i].s1); };
        auto by_arc = [&](uint32_t i, uint32_t j) { return mid(i) != mid(j) ? mid(i) < mid(j) : i < j; };
        uint32_t chains = 0;
        for (uint32_t i = 0; i < n; ++i) chains = std::max(chains, links[i].chain + 1);
        if (chains <= 4 * uint64_t(n) + 64) {
            std::vector<uint32_t> first(size_t(chains) + 1, 0);
            for (uint32_t i = 0; i < n; ++i) ++first[links[i].chain + 1];
            std::partial_sum(first.begin(), first.end(), first.begin());
            std::vector<uint32_t> at(first.begin(), first.end() - 1);
            for (uint32_t i = 0; i < n; ++i) out.order[at[links[i].chain]++] = i;
            for (uint32_t c = 0; c < chains; ++c)
                if (first[c + 1] - first[c] > 1) std::sort(out.order.begin() + first[c], out.order.begin() + first[c + 1], by_arc);
        } else {
            std::sort(out.order.begin(), out.order.end(), [&](uint32_t i, uint32_t j) {
                return links[i].chain != links[j].chain ? links[i].chain < links[j].chain : by_arc(i, j);
            });
        }
    }
    // In chain order: ends oriented along the chain, and whether each continues the one before
    // (the library sums lengths along a chain, so a segment starts at the very value the one
    // before it ended at; a gap, where segments were left out, breaks the run).
    std::vector<dvec3> a(n), b(n);
    std::vector<float> ta(n), tb(n);
    std::vector<uint8_t> linked(n, 0);
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t i = out.order[k];
        const bool flip = links && links[i].s0 > links[i].s1;
        const dvec3 q0(p0[3 * size_t(i)], p0[3 * size_t(i) + 1], p0[3 * size_t(i) + 2]);
        const dvec3 q1(p1[3 * size_t(i)], p1[3 * size_t(i) + 1], p1[3 * size_t(i) + 2]);
        a[k] = flip ? q1 : q0;
        b[k] = flip ? q0 : q1;
        ta[k] = taper[2 * size_t(i) + (flip ? 1 : 0)];
        tb[k] = taper[2 * size_t(i) + (flip ? 0 : 1)];
        if (k > 0 && links) {
            const el_chain_link& prev = links[out.order[k - 1]];
            const el_chain_link& cur = links[i];
            linked[k] = prev.chain == cur.chain && std::min(cur.s0, cur.s1) == std::max(prev.s0, prev.s1);
        }
    }
    // Each segment's chain's sphere (a crease chain smaller than a pixel is not drawn).
    std::vector<Sphere> chain_sphere(n);
    if (chain_spheres) {
        std::vector<dvec3> pts;
        for (uint32_t k = 0; k < n;) {
            uint32_t e = k + 1;
            while (e < n && links && links[out.order[e]].chain == links[out.order[k]].chain) ++e;
            pts.clear();
            for (uint32_t j = k; j < e; ++j) {
                pts.push_back(a[j]);
                pts.push_back(b[j]);
            }
            const Sphere s = sphere_of(pts.begin(), pts.end());
            std::fill(chain_sphere.begin() + k, chain_sphere.begin() + e, s);
            k = e;
        }
    }
    out.nodes.reserve(size_t(n) * EL_LINE_NODE_FLOATS);
    std::array<dvec3, 2 * EL_LINE_GROUP> pts{};
    // The nodes of one group's tree, in pre-order: its range of segments and its error.
    struct Node {
        uint32_t lo, hi;
        int parent;
        double error;
    };
    std::vector<Node> tree;
    std::array<int, EL_LINE_GROUP> leaf_node{};
    uint32_t run_start = 0;
    for (uint32_t g0 = 0; g0 < n;) {
        if (!linked[g0]) run_start = g0;
        uint32_t g1 = g0 + 1;
        while (g1 < n && linked[g1] && (g1 - run_start) % EL_LINE_GROUP != 0) ++g1;
        const uint32_t c = g1 - g0;
        for (uint32_t k = 0; k < c; ++k) {
            pts[2 * k] = a[g0 + k];
            pts[2 * k + 1] = b[g0 + k];
        }
        const Sphere group = sphere_of(pts.begin(), pts.begin() + 2 * c);
        // Ranges halved from the root, then errors from the leaves up (a child comes after its
        // parent, so a backward pass sees every child first).
        tree.clear();
        tree.push_back({0, c, -1, 0.0});
        for (size_t t = 0; t < tree.size(); ++t) {
            const Node nd = tree[t];
            if (nd.hi - nd.lo > 1) {
                const uint32_t mid = (nd.lo + nd.hi) / 2;
                tree.push_back({nd.lo, mid, int(t), 0.0});
                tree.push_back({mid, nd.hi, int(t), 0.0});
            } else {
                leaf_node[nd.lo] = int(t);
            }
        }
        for (size_t t = tree.size(); t-- > 0;) {
            Node& nd = tree[t];
            if (nd.hi - nd.lo > 1) {
                // Every junction inside the chord: the end of one segment and the start of the
                // next (equal for mesh edges; contour points may differ in the last bit).
                const dvec3 ca = a[g0 + nd.lo], cb = b[g0 + nd.hi - 1];
                for (uint32_t k = nd.lo + 1; k < nd.hi; ++k) {
                    nd.error = std::max({nd.error, distance_to_segment(a[g0 + k], ca, cb),
                                         distance_to_segment(b[g0 + k - 1], ca, cb)});
                }
            }
            if (nd.parent >= 0) tree[size_t(nd.parent)].error = std::max(tree[size_t(nd.parent)].error, nd.error);
        }
        // One record per segment: its own ends, then per ancestor (parent first) its error and,
        // where this segment is the ancestor's first, the ancestor's segment count.
        for (uint32_t k = 0; k < c; ++k) {
            const uint32_t i = g0 + k;
            const Sphere& cs = chain_sphere[i];
            float v[EL_LINE_NODE_FLOATS] = {
                float(a[i].x), float(a[i].y), float(a[i].z), ta[i],
                float(b[i].x), float(b[i].y), float(b[i].z), tb[i],
                -1.0f, -1.0f, -1.0f, 0.0f,
                float(group.centre.x), float(group.centre.y), float(group.centre.z), float(group.radius),
                float(cs.centre.x), float(cs.centre.y), float(cs.centre.z), float(cs.radius)};
            uint32_t code = 0;
            int up = tree[size_t(leaf_node[k])].parent;
            for (uint32_t level = 0; level < 3 && up >= 0; ++level, up = tree[size_t(up)].parent) {
                const Node& anc = tree[size_t(up)];
                v[8 + level] = float(anc.error);
                if (anc.lo == k) code += (anc.hi - anc.lo) << (4 * level);
            }
            v[11] = float(code);
            out.nodes.insert(out.nodes.end(), v, v + EL_LINE_NODE_FLOATS);
        }
        g0 = g1;
    }
    return out;
}

}  // namespace el
