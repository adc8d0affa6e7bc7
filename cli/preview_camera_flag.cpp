#include "cli/preview_camera_flag.h"

#include "cli/options.h"
#include "frontend/did_you_mean.h"

#include <algorithm>
#include <vector>

namespace fgsg::cli {

namespace {

const char* const kForm = "fit, or azimuth=DEG,elevation=DEG,distance=D (each optional)";

}  // namespace

rt::render::PreviewCamera parsePreviewCamera(const std::string& text) {
  rt::render::PreviewCamera camera;
  if (text == "fit") return camera;
  if (text.empty()) throw UsageError{std::string("--camera expects ") + kForm + ", got nothing"};
  camera.fit = false;
  bool seen[3] = {false, false, false};
  size_t from = 0;
  while (from <= text.size()) {
    const size_t comma = std::min(text.find(',', from), text.size());
    const std::string item = text.substr(from, comma - from);
    from = comma + 1;
    const size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    static const std::vector<std::string> kKeys = {"azimuth", "elevation", "distance"};
    const int k = int(std::find(kKeys.begin(), kKeys.end(), key) - kKeys.begin());
    if (eq == std::string::npos || k == 3) {
      const std::string guess = frontend::closestName(key, kKeys);
      throw UsageError{"--camera " + text + ": '" + item + "' is not azimuth=DEG, elevation=DEG or distance=D" +
                       (guess.empty() ? " (" + std::string(kForm) + ")" : "; did you mean " + guess + "?")};
    }
    if (seen[k]) throw UsageError{"--camera " + text + ": " + key + " is given twice"};
    seen[k] = true;
    const double value = CommandLine::parseNumber("--camera " + key, item.substr(eq + 1));
    if (k == 0) camera.azimuthDegrees = value;
    if (k == 1) camera.elevationDegrees = value;
    if (k == 2) {
      if (!(value > 0)) throw UsageError{"--camera " + text + ": the distance must be positive (scene units)"};
      camera.distance = value;
    }
  }
  std::string error;
  if (!rt::render::checkPreviewCamera(camera, error)) throw UsageError{"--camera " + text + ": " + error};
  return camera;
}

void cameraFlag(CommandLine& cl, rt::render::PreviewCamera& camera, bool& given) {
  cl.option("--camera", [&](const std::string& v) {
    camera = parsePreviewCamera(v);
    given = true;
  });
}

}  // namespace fgsg::cli
