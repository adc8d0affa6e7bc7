// The example of continuous model synthesis: a closed, consistently oriented polygonal
// solid whose face normals are small integer directions (directions.h). Loaded from any
// mesh file fgsg reads (OBJ, PLY, OFF, STL); corners at the same position are welded, so
// triangle soups (STL) work. Everything the algorithm assumes is checked here with a
// message naming the face or vertex (1-based, as the file numbers them).
#pragma once

#include "runtime/io/read_mesh_file.h"
#include "runtime/synthesis/continuous/directions.h"

#include <string>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

struct ExampleSolid {
  std::string name;                          // the file, for messages
  std::vector<DVec3> vertices;
  std::vector<std::vector<int>> polygons;    // counter-clockwise seen from outside
  std::vector<int> polygonDirection;         // index into `dirs`
  std::vector<bool> polygonAlong;            // the outward normal is +dirs[d] (else -dirs[d])
  // The distinct face directions, then the coordinate axes the faces lack (the output's
  // bounding box lies on axis planes, so they are always planes of the output).
  std::vector<IVec3> dirs;
  int faceDirections = 0;
  double diagonal = 0;                       // of the bounding box
};

// Largest integer component of a face direction, and how far from it a normal may be.
constexpr int kMaxDirectionComponent = 12;
constexpr double kDirectionToleranceDegrees = 0.1;
constexpr int kMaxDirections = 24;

// With a `deadline` (the run's time limit, which counts from the start: reading a large
// example is part of the run), the reading and every check ask it as they go and stop once
// it has passed, false with a message saying so ("PATH: stopped by the time limit ...").
bool loadExampleSolid(const std::string& path, ExampleSolid& out, std::string& error, Deadline* deadline = nullptr);
// The same from polygons already read (`name` for messages).
bool makeExampleSolid(const io::MeshFileContent& mesh, const std::string& name, ExampleSolid& out, std::string& error,
                      Deadline* deadline = nullptr);

// The winding number of the solid around p: 1 inside, 0 outside (Van Oosterom-Strackee
// solid angles summed over a fan of every polygon).
double windingNumber(const ExampleSolid& solid, const DVec3& p);

}  // namespace fgsg::rt::synthesis::continuous
