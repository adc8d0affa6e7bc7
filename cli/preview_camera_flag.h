// --camera: where a PNG preview is seen from (runtime/render/preview.h, PreviewCamera).
// `fit` is the default framing; otherwise comma-separated azimuth=DEG, elevation=DEG and
// distance=D, each optional (the fitted view's angle, and a distance that fits the box,
// when left out), e.g. --camera azimuth=180,elevation=30.
#pragma once

#include "cli/command_line.h"
#include "runtime/render/preview.h"

#include <string>

namespace fgsg::cli {

// The camera `text` describes; a UsageError naming --camera and what is wrong otherwise
// (an unknown or repeated key, a value that is not a number or out of range).
rt::render::PreviewCamera parsePreviewCamera(const std::string& text);

// Declares --camera on `cl`; `given` is set when it appears.
void cameraFlag(CommandLine& cl, rt::render::PreviewCamera& camera, bool& given);

}  // namespace fgsg::cli
