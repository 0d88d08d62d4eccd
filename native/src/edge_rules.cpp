#include "edge_rules.hpp"

#include <algorithm>
#include <limits>

namespace el {

namespace {

struct Pick {
    bool enabled, picked;
    float radius;
};

// What slot `s` says of edge `e`: whether it rounds edges at all, whether its rules pick this
// one, and the radius it asks (its own; times the bevel weight where the weight alone picks it,
// as the Bevel modifier scales its Amount).
Pick pick(const EdgeRuleInputs& in, uint32_t s, uint32_t e) {
    const el_slot_rules& r = in.slots[s];
    const bool enabled = r.enabled != 0 && r.radius > 0.0f && r.K > 0.0f;
    const bool by_angle = (r.rules & EL_RULE_ANGLE) && in.angles[e] > r.angle_deg;
    const bool by_sharp = (r.rules & EL_RULE_SHARP) && in.sharp[e] != 0;
    const bool by_bevel = (r.rules & EL_RULE_BEVEL) && in.bevel[e] > 0.0f;
    const float radius = by_bevel && !(by_angle || by_sharp) ? r.radius * in.bevel[e] : r.radius;
    return {enabled, by_angle || by_sharp || by_bevel, radius};
}

}  // namespace

void edge_rules(const EdgeRuleInputs& in, const EdgeRuleOutputs& out) {
    const float inf = std::numeric_limits<float>::infinity();
    for (uint32_t e = 0; e < in.edge_count; ++e) {
        const uint32_t f = in.flags[e];
        const bool ok = (f & EL_EDGE_MANIFOLD) && !(f & EL_EDGE_DEGENERATE) && in.face_b[e] >= 0;
        const uint32_t sa = in.face_a[e] >= 0 ? in.tri_slot[in.face_a[e]] : 0;
        const uint32_t sb = in.face_b[e] >= 0 ? in.tri_slot[in.face_b[e]] : 0;
        const Pick a = pick(in, sa, e), b = pick(in, sb, e);
        out.chosen[e] = ok && a.enabled && b.enabled && (a.picked || b.picked);
        out.radius[e] = std::min(a.picked ? a.radius : inf, b.picked ? b.radius : inf);
        if (out.slot_a) out.slot_a[e] = sa;
        if (out.slot_b) out.slot_b[e] = sb;
        if (out.pick_a) out.pick_a[e] = a.picked;
        if (out.pick_b) out.pick_b[e] = b.picked;
        if (out.rad_a) out.rad_a[e] = a.radius;
        if (out.rad_b) out.rad_b[e] = b.radius;
    }
}

}  // namespace el
