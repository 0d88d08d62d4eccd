#include "chains.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
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
        // than sorting end indices through their keys.
        const size_t n = items.size() * 2;
        std::vector<std::pair<uint64_t, uint32_t>> sorted(n);
        for (size_t e = 0; e < n; ++e) sorted[e] = {items[e / 2].key[e % 2], uint32_t(e)};
        std::sort(sorted.begin(), sorted.end());
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

}  // namespace el
