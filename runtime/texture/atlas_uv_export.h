// A surface's texture layout as an OBJ file, so a texture context can be painted in any
// paint program (Blender, Krita with a UV overlay, ...) and fed back as `texture NAME =
// "painted.png"`: the vertices and faces of the surface as marching sees it, each face
// corner with the texture coordinate contexts are sampled at (MarchingSurface::texCoord:
// the mesh's own UVs when it has them, else the generated atlas's). A corner shares its
// `vt` with the other corners of the same vertex that have the same coordinate (inside a
// chart); across a chart seam the vertex gets one `vt` per chart. OBJ's v is up, as
// texCoord's: row 0 of the painted image is v = 1, as the texture contexts read it.
#pragma once

#include "runtime/marching/marching_surface.h"

#include <string>

namespace fgsg::rt::texture {

// The OBJ text: a comment line, `v x y z` per vertex, `vt u v` per distinct corner
// coordinate, `f a/ta b/tb c/tc` per face in the mesh's order. Numbers are written
// shortest round-trip, so reading them back gives the very doubles.
std::string atlasUvObj(const marching::MarchingSurface& surface);

// atlasUvObj written atomically to `path`; false with a message naming it.
bool writeAtlasUvObj(const marching::MarchingSurface& surface, const std::string& path, std::string& error);

}  // namespace fgsg::rt::texture
