// Which edges each material slot rounds: the rule of a material's Rounded Edges settings, per
// edge (el_edge_rules in edgelight.h).
#pragma once

#include <edgelight/edgelight.h>

#include <cstdint>

namespace el {

struct EdgeRuleInputs {
    const uint32_t* flags;
    const float* angles;
    const int32_t* face_a;
    const int32_t* face_b;
    const uint8_t* sharp;
    const float* bevel;
    uint32_t edge_count;
    const uint32_t* tri_slot;
    const el_slot_rules* slots;
};

struct EdgeRuleOutputs {
    uint8_t* chosen;
    float* radius;
    uint32_t* slot_a;  // the rest may be null
    uint32_t* slot_b;
    uint8_t* pick_a;
    uint8_t* pick_b;
    float* rad_a;
    float* rad_b;
};

void edge_rules(const EdgeRuleInputs& in, const EdgeRuleOutputs& out);

}  // namespace el
