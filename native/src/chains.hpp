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

}  // namespace el
