// Chains: items (mesh edges, contour segments) linked end to end where exactly two items of the
// set meet, so lines can taper at free ends and be styled along their length.
#pragma once

#include <edgelight/edgelight.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace el {

struct ChainItem {
    uint64_t key[2];  // endpoint identities: equal keys are the same point
    glm::vec3 point[2];
};

struct Chains {
    std::vector<el_chain_link> links;  // per item, in input order
    std::vector<el_chain> chains;
};

// Links items whose endpoints share a key of degree 2 (exactly two item ends there). A key of
// degree 1 is a free end; degree 3 or more is a junction, where chains stop without tapering.
// A loop of degree-2 keys is one closed chain. Items whose two ends share a key (zero length)
// are chains of their own.
Chains build_chains(const std::vector<ChainItem>& items);

// The line pass's nodes (el_line_nodes in edgelight.h): segments put in chain order (by chain,
// then arc length; `links` null: each segment a chain of its own), cut into groups of up to
// EL_LINE_GROUP consecutive segments of one chain, each group a binary tree of chords over them,
// halved recursively; one record of EL_LINE_NODE_FLOATS floats per segment, in chain order.
// order[i] is the segment at place i of the chain order.
struct LineNodes {
    std::vector<float> nodes;
    std::vector<uint32_t> order;
};
LineNodes build_line_nodes(const float* p0, const float* p1, const float* taper, const el_chain_link* links,
                           uint32_t count, bool chain_spheres);

}  // namespace el
