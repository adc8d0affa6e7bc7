// A quick look at an assembled mesh: an Embree ray-cast PNG with a camera fitted to the
// bounding box. A pattern flat in Z (a planar design in the XY plane) is seen straight
// from above with an orthographic camera; anything else in perspective from the
// (+X, +Y, +Z) side with Y up, close enough that the bounding box just fits; or, when
// asked (PreviewCamera, `fgsg run --camera`), from any side of an orbit. Lambert
// shading (headlight + key light + ambient) of the vertex colours, times the image on
// textured triangles (Mesh::textureRuns), over a soft gradient, 2x2 supersampled.
// Deterministic bytes.
#pragma once

#include "runtime/io/output_transaction.h"
#include "runtime/mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::render {

// A mesh counts as flat in Z when its Z extent is below this fraction of its largest:
// planar patterns of shallow shapes (FGSG Fig. 4 tori) are still seen from above.
constexpr double kFlatPreviewRatio = 0.1;

// The fitted view's direction as an orbit: the camera on the (+X, +Y, +Z) side, at
// azimuth atan2(1.2, 0.9) and elevation atan2(0.7, 1.5) (see PreviewCamera).
constexpr double kFitAzimuthDegrees = 53.13010235415598;
constexpr double kFitElevationDegrees = 25.01689347810003;

// Where the preview is seen from. `fit` (the default) is the framing described above.
// Otherwise a perspective camera orbits the bounding box's centre, Y up, looking at the
// centre: azimuth is measured about +Y from +X towards +Z (0: the camera on the +X side
// looking towards -X; 90: on +Z, the glTF front), elevation upwards from the XZ plane
// (positive: from above; +-90: straight down or up, the picture's top then pointing away
// from the azimuth), distance from the centre in scene units (0: backed off until the
// whole bounding box fits, as the fitted view).
struct PreviewCamera {
  bool fit = true;
  double azimuthDegrees = kFitAzimuthDegrees;    // any finite angle
  double elevationDegrees = kFitElevationDegrees;  // -90 to 90
  double distance = 0;                             // 0 or positive and finite
};

struct PreviewOptions {
  // {width, height, samplesPerAxis}; the camera stays the fitted view.
  PreviewOptions(int width = 800, int height = 600, int samplesPerAxis = 2)
      : width(width), height(height), samplesPerAxis(samplesPerAxis) {}
  int width = 800;
  int height = 600;
  int samplesPerAxis = 2;  // supersampling: samplesPerAxis^2 rays per pixel
  PreviewCamera camera;
};

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major from the top row, 3 bytes per pixel
};

// True when the camera's angles and distance are in range (see PreviewCamera); else false
// and what is wrong.
bool checkPreviewCamera(const PreviewCamera& camera, std::string& error);

// Renders the mesh; an empty mesh gives the background alone. A texture that cannot be
// loaded leaves its triangles in their vertex colours.
Image renderImage(const Mesh& mesh, const PreviewOptions& options);

// Renders and writes a PNG atomically. False and a message in `error` when the options
// (size, camera) are invalid or the file cannot be written. An empty mesh is not an error: the picture
// shows the background and `warning` (when given) says so. Nor is a texture that cannot
// be loaded: `warning` names it, and its triangles show their vertex colours.
bool renderPreview(const Mesh& mesh, const PreviewOptions& options, const std::string& pngPath,
                   std::string& error, std::string* warning = nullptr);

// The same, staged in `outputs` (written when the caller commits all its outputs).
bool stagePreview(const Mesh& mesh, const PreviewOptions& options, const std::string& pngPath,
                  io::OutputTransaction& outputs, std::string& error, std::string* warning = nullptr);

}  // namespace fgsg::rt::render
