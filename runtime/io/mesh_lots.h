// Building lots from the polygon faces of a mesh file (OBJ, PLY, OFF): each face of three
// or more corners is one lot, its outline seen from above. The ground is the mesh's XZ
// plane with Y up, as in the CGA grammars: a corner (x, y, z) becomes the lot point
// (x east, y north) = (x, -z), metres as they are; faces need not be level (y is ignored).
//
// Faces are read as polygons, never triangulated, through io::readMeshFile (the bounded,
// checked reader of surface meshes), and numbered from 0 in file order: OBJ `f` lines, the
// PLY or OFF face element. Positions pass through single precision on the way (OBJ and PLY
// readers store floats): a millimetre at 10 km from the origin, so a mesh in local
// coordinates loses nothing, while one in UTM-sized coordinates is rounded to decimetres.
//
// Validation, as for GeoJSON rings (runtime/io/lot_rings.h): repeated corners in a row are
// dropped; a face whose outline crosses or touches itself, or has zero area (a vertical
// wall, corners on one line), is an error naming the file, the face and its corners as the
// file wrote them: "lots.obj: face 12: the edge from corner 3 (1, 0, -2) to ...". Each lot
// comes out counter-clockwise (a clockwise face reversed, its first corner kept first),
// without holes, with `feature` the face's index, an empty `id` and no properties.
#pragma once

#include "runtime/lot.h"

#include <string>
#include <vector>

namespace fgsg::rt {

// Whether `path` names a mesh file lots are read from: .obj, .ply or .off, in any case.
bool isMeshLotsPath(const std::string& path);

// Reads the lots of the mesh file at `path` (see above). False with `error` set and `lots`
// empty when the file cannot be read, has an unsupported extension, is not a valid mesh,
// has an unsound face, or has no face of three or more corners at all.
bool readMeshLots(const std::string& path, std::vector<Lot>& lots, std::string& error);

}  // namespace fgsg::rt
