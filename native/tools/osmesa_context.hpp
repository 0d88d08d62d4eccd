// An offscreen OpenGL 4.5 core context on Mesa's OSMesa (llvmpipe): no display, no GPU, the same
// rasteriser Blender uses headless here. Everything is drawn into framebuffer objects; OSMesa's
// own buffer is a 1 x 1 placeholder that makes the context current.
#pragma once

#include <string>

namespace el_tools {

class OsmesaContext {
public:
    // Creates the context, makes it current on this thread and loads the gl:: entry points.
    // Throws std::runtime_error saying what is missing (no OSMesa core profile, too old a GL).
    OsmesaContext();
    ~OsmesaContext();
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    // "4.5 (Core Profile) Mesa ... | llvmpipe (...)"
    std::string description() const;

private:
    void* ctx_ = nullptr;
    unsigned char placeholder_[4] = {};
};

}  // namespace el_tools
