#include "frontend/builtin_docs.h"

#include "frontend/builtins.h"
#include "frontend/sema_environment.h"

#include <sstream>

namespace fgsg::frontend {
namespace {

constexpr BuiltinDocKind kDocCommand = BuiltinDocKind::Command, kDocFunction = BuiltinDocKind::Function,
                         kDocQuery = BuiltinDocKind::Query, kDocFieldMember = BuiltinDocKind::FieldMember,
                         kDocCgaOperation = BuiltinDocKind::CgaOperation, kDocCgaFunction = BuiltinDocKind::CgaFunction,
                         kDocCgaAttribute = BuiltinDocKind::CgaAttribute, kDocSurface = BuiltinDocKind::Surface,
                         kDocFieldSource = BuiltinDocKind::FieldSource;

// Angles are in degrees and lengths in the scope's units (metres) throughout. A command's
// signature is its CommandInfo's (nullptr here); test_builtin_docs.cpp checks that every
// command, function, Feature and field member has its entry here.
const BuiltinDoc kBuiltinDocTable[] = {
    // ---------------------------------------------------------------- commands
    {kDocCommand, "T", nullptr, "Moves the scope's origin along its own X, Y and Z axes, in absolute units (not scaled by S).", nullptr},
    {kDocCommand, "R", nullptr, "Turns the scope about its own axes through its origin: Rx(ax), then Ry(ay), then Rz(az), in degrees.", nullptr},
    {kDocCommand, "Rx", nullptr, "Turns the scope about its own X axis through its origin, right-handed (Y towards Z), in degrees.", nullptr},
    {kDocCommand, "Ry", nullptr, "Turns the scope about its own Y axis through its origin, right-handed (Z towards X), in degrees.", nullptr},
    {kDocCommand, "Rz", nullptr, "Turns the scope about its own Z axis through its origin, right-handed (X towards Y), in degrees.", nullptr},
    {kDocCommand, "RX", nullptr, "The FGSG paper's spelling of Rx: turns the scope about its X axis, in degrees.", nullptr},
    {kDocCommand, "RY", nullptr, "The FGSG paper's spelling of Ry: turns the scope about its Y axis, in degrees.", nullptr},
    {kDocCommand, "RZ", nullptr, "The FGSG paper's spelling of Rz: turns the scope about its Z axis, in degrees.", nullptr},
    {kDocCommand, "RS", nullptr, "Turns the scope about the surface normal (world Z on the plane) through its origin, in degrees.", nullptr},
    {kDocCommand, "S", nullptr, "Sets the scope's size (absolute, relative `0.5r` or floating `~1`); the origin stays, so the box grows from its corner.", nullptr},
    {kDocCommand, "Size", nullptr, "The same as S, for grammars whose shapes are named S (FGSG Fig. 11's glyphs).", nullptr},
    {kDocCommand, "I", nullptr, "Places an instance of the asset stretched into the scope box; `I(\"none\")` places nothing. CityEngine's i() modes keep the asset's own size and position.", nullptr},
    {kDocCommand, "IC", nullptr, "Places the asset like I, testing it for collisions (the grammar's `collision` declaration): a collision culls the rest of the production.", nullptr},
    {kDocCommand, "IM", nullptr, "Places the asset like I unless an earlier IM instance of it lies within maxDist metres and maxAngle degrees: that one then moves to the mean of those merged into it.", nullptr},
    {kDocCommand, "Subdiv", nullptr, "Cuts the scope along the axis into consecutive slabs of the given sizes, one body part each; relative and floating sizes share what absolute ones leave.", nullptr},
    {kDocCommand, "SplitArea", nullptr, "CityEngine's splitArea: cuts a flat shape across the axis so that the parts have the given areas (m²).", nullptr},
    {kDocCommand, "Repeat", nullptr, "Tiles the scope with max(1, floor(L / s)) equal tiles per axis, each running the body; tiles are clipped like Subdiv's.", nullptr},
    {kDocCommand, "Comp", nullptr, "Splits the shape into its components (faces, sidefaces, top, edges ...), each a shape with its own scope running the body (labelled parts per face class).", nullptr},
    {kDocCommand, "Extrude", nullptr, "Extrudes a polygon (or a flat box) along its normal by height metres into a solid with a Y-up scope.", nullptr},
    {kDocCommand, "Footprint", nullptr, "Makes the shape the polygon with these (x, z) corners in the scope's XZ plane, facing up; holes follow the word \"hole\".", nullptr},
    {kDocCommand, "Offset", nullptr, "CGA's inward offset: the polygon shrunk by distance metres from every edge (`inside`), and the band left (`border`).", nullptr},
    {kDocCommand, "Roof", nullptr, "Builds a hipped, gable, pyramid, shed or ridge roof solid on the scope's base, by slope angle (degrees) or by height; overhangs in metres.", nullptr},
    {kDocCommand, "Center", nullptr, "Moves the scope along the selected axes so that its centre lines up with the successor's starting scope's centre.", nullptr},
    {kDocCommand, "Color", nullptr, "Sets the colour of the instances placed from this scope on: r, g, b in 0..1 or \"#rrggbb\".", nullptr},
    {kDocCommand, "Texture", nullptr, "Textures the leaves from this scope on with the image, projected in this scope's frame; tile sizes in metres (none: one image over the scope); \"none\" removes it.", nullptr},
    {kDocCommand, "Material", nullptr, "Sets a glTF material property of the instances placed from this scope on: roughness (default 0.8), metallic (default 0), opacity, a colour or emissive colour component (0..1), or a texture layer's image (colormap, normalmap, emissivemap, occlusionmap, roughnessmap, metallicmap, bumpmap, specularmap, opacitymap, dirtmap), each on its own uv set.", nullptr},
    {kDocCommand, "SetupProjection", nullptr, "CGA's setupProjection: projects every face onto the two scope axes' plane, tiles of tileWidth × tileHeight metres (uv set 0 unless given).", nullptr},
    {kDocCommand, "ScaleUV", nullptr, "Scales the texture coordinates (u, v) of the current projection by the factors.", nullptr},
    {kDocCommand, "TranslateUV", nullptr, "Moves the texture coordinates (u, v) of the current projection by the offsets.", nullptr},
    {kDocCommand, "RotateUV", nullptr, "Turns the texture coordinates about (0, 0) counter-clockwise, in degrees.", nullptr},
    {kDocCommand, "TileUV", nullptr, "Tiles the texture coordinates so that one tile is tileWidth × tileHeight (0 keeps that axis).", nullptr},
    {kDocCommand, "NormalizeUV", nullptr, "Normalizes the texture coordinates to 0..1 over the shape's scope box (\"uv\", \"uvUniform\", \"u\" or \"v\").", nullptr},
    {kDocCommand, "DeleteUV", nullptr, "Removes the shape's texture coordinates until ProjectUV or a new projection.", nullptr},
    {kDocCommand, "ProjectUV", nullptr, "Projects the texture coordinates again from the last SetupProjection or Texture after a DeleteUV.", nullptr},
    {kDocCommand, "CopyUV", nullptr, "Makes uv set destinationUvSet's coordinates those of sourceUvSet (sets 0..9).", nullptr},
    {kDocCommand, "Lock", nullptr, "Derives the parts and all they create as one unit: a collision anywhere in it removes all of it.", nullptr},
    {kDocCommand, "F", nullptr, "Turtle: draws a segment of length (default: `turtle step`) along the heading (scope Y) and moves there.", nullptr},
    {kDocCommand, "f", nullptr, "Turtle: moves length (default: `turtle step`) along the heading without drawing.", nullptr},
    {kDocCommand, "Marching", nullptr, "Marches length surface units along the surface, angle degrees off the scope's X, where cond holds at the destination (other directions tried); then derives Top there and Extruded on the segment, whose terminals are bent C1 (the default), C0 or not at all (\"none\").", nullptr},
    {kDocCommand, "Branch", nullptr, "Makes n branches from the scope's point (n a whole number 0..1000): the first n - 1 derive A, the last B.", nullptr},
    {kDocCommand, "Line", nullptr, "Starts a line at the scope's origin, output as a tube width thick (default 0.05) or an asset bent along it; merge (default true) clips crossing segments.", nullptr},
    {kDocCommand, "LineSeg", nullptr, "Extends the current line to the scope's origin, after moving the scope length along its X axis when given.", nullptr},
    {kDocCommand, "Synthesize", nullptr, "Model synthesis: fills the scope with an nx × ny × nz grid of pieces grown from the example model (a mesh example: continuous synthesis).", nullptr},
    {kDocCommand, "Evolve", nullptr, "Evolves a 2D L-system tile pattern (Chan & Hui) over the tileset and fills the scope's XY face with it at that generation; k defaults to 3.", nullptr},
    {kDocCommand, "Cells", nullptr, "Feature-based cellular texturing: derives the base mesh's corners, edges and faces as shapes of the body's symbol; joint and mortar in metres.", nullptr},
    {kDocCommand, "BrickBond", nullptr, "Inside Cells: lays a running bond of bricks (length × height × depth) on the feature; flip (default false) starts with the other face.", nullptr},
    {kDocCommand, "HeaderRow", nullptr, "Inside Cells: lays a row of headers (width × height × depth) along an edge on its upright face.", nullptr},
    {kDocCommand, "ArchBricks", nullptr, "Inside Cells: lays voussoirs radial to an arc edge; each further ArchBricks on the arc is the next ring outward.", nullptr},
    {kDocCommand, "RandomStones", nullptr, "Inside Cells: lays random stones merged from grid squares, up to maxWidth × maxHeight, depth thick.", nullptr},
    {kDocCommand, "EnglishBond", nullptr, "Inside Cells: lays bricks in English bond (courses of stretchers and headers alternating).", nullptr},
    {kDocCommand, "FlemishBond", nullptr, "Inside Cells: lays bricks in Flemish bond (stretchers and headers alternating in each course).", nullptr},
    {kDocCommand, "HeaderBond", nullptr, "Inside Cells: lays bricks in header bond (every brick a header, as wide as the brick's depth).", nullptr},
    {kDocCommand, "Shingles", nullptr, "Inside Cells: lays rows of tiles up a face from its lowest edge, odd rows shifted by half a tile, and ridge tiles along hips and ridges.", nullptr},
    {kDocCommand, "Report", nullptr, "CGA's report: adds the value to the key's collection of the current start shape (fgsg run --report writes them).", nullptr},
    {kDocCommand, "Print", nullptr, "CGA's print: writes the value on stderr with the grammar's file:line:col once the derivation ends.", nullptr},
    {kDocCommand, "Label", nullptr, "CGA's label: a labelled copy of the shape for the context queries (Shape.inside, overlaps, touches ...); the shape is unchanged.", nullptr},
    {kDocCommand, "InsertAlongUV", nullptr, "CityEngine's insertAlongUV: the shape's geometry becomes the asset laid out in the uv set's space (x along u, repeated per whole u; z across v) and bent onto its faces, height metres high.", nullptr},
    {kDocCommand, "AlignScopeToAxes", nullptr, "Turns the scope onto the world's axes (all, or one axis), the geometry staying where it is.", nullptr},
    {kDocCommand, "AlignScopeToGeometry", nullptr, "Turns the scope so that its up axis follows a face's normal and its X that face's edge (\"largest\" face, \"longest\" edge or indices).", nullptr},
    {kDocCommand, "RotateScope", nullptr, "Turns the scope by (ax, ay, az) degrees, the geometry staying where it is; the scope is fitted around it.", nullptr},
    {kDocCommand, "MirrorScope", nullptr, "Reverses each scope axis whose flag is true, the origin moved to its far side; the geometry stays.", nullptr},
    {kDocCommand, "Mirror", nullptr, "Mirrors the geometry in its scope along each axis whose flag is true, faces still facing out.", nullptr},
    {kDocCommand, "Setback", nullptr, "CityEngine's setback: the selected polygon edges set back by distance metres (negative: outward); the bands run on their labels, the rest on `remainder`.", nullptr},
    {kDocCommand, "SetbackToArea", nullptr, "Sets every edge back by the one distance that leaves a remainder of area m².", nullptr},
    {kDocCommand, "SetbackPerEdge", nullptr, "Setback with the distance evaluated once per edge (Scope.sx its length, Shape.compIndex its index).", nullptr},
    {kDocCommand, "ShapeL", nullptr, "The L-shaped wing along the front and left edges (widths in metres) as `shape`, the rest as `remainder`.", nullptr},
    {kDocCommand, "ShapeU", nullptr, "The U-shaped wings along the front, right and left edges (widths in metres) as `shape`, the rest as `remainder`.", nullptr},
    {kDocCommand, "ShapeO", nullptr, "The ring of wings along all four sides (widths in metres) as `shape`, the courtyard as `remainder`.", nullptr},
    {kDocCommand, "InnerRectangle", nullptr, "The largest rectangle inside the polygon, along the scope's axes (\"scope\") or along an edge (\"edge\").", nullptr},
    {kDocCommand, "Scatter", nullptr, "Places n random points on the shape's surface, in its volume or in its scope box (uniform or gaussian), each a shape of size zero running the part.", nullptr},
    {kDocCommand, "Convexify", nullptr, "Cuts a concave polygon along diagonals into convex pieces kept as one shape; cuts of maxLength or longer are left out.", nullptr},
    {kDocCommand, "Taper", nullptr, "Makes the polygon a pyramid whose apex is height metres above its centre of gravity, along the normal.", nullptr},
    {kDocCommand, "Envelope", nullptr, "CityEngine's envelope: the solid over a convex polygon below each edge's plane (base height in metres, angle in degrees) and below maxHeight.", nullptr},
    {kDocCommand, "EnvelopePerEdge", nullptr, "Envelope with a base height and an angle for each edge in edge order (missing: 0 and 90).", nullptr},
    {kDocCommand, "Translate", nullptr, "CityEngine's translate: moves the scope by (x, y, z) (\"rel\") or to that position (\"abs\"), in the named coordinate system's axes.", nullptr},
    {kDocCommand, "Rotate", nullptr, "CityEngine's rotate: turns the scope and its geometry by (ax, ay, az) degrees (\"rel\") or to those angles (\"abs\"), about the named coordinate system's axes.", nullptr},
    {kDocCommand, "SetPivot", nullptr, "CityEngine's setPivot: puts the shape's pivot (the system of Translate and Rotate's \"pivot\", kept by the shapes it creates) at scope corner 0..7 with the scope's axes in the order named, pointing into the scope; the scope becomes that frame.", nullptr},
    {kDocCommand, "DeleteHoles", nullptr, "Drops every face's holes.", nullptr},
    {kDocCommand, "ApplyTrimPlanes", nullptr, "Cuts the shape's geometry by its trim planes (those Comp(\"f\") gave its faces at their shared edges), keeping the face's side.", nullptr},
    {kDocCommand, "SetTrim", nullptr, "Turns the shape's horizontal or vertical trim planes on (1) or off (0); vertical ones are on, horizontal ones off by default.", nullptr},
    {kDocCommand, "ReverseNormals", nullptr, "Turns every face over.", nullptr},
    {kDocCommand, "ResetGeometry", nullptr, "Makes the geometry the scope box again.", nullptr},
    {kDocCommand, "CleanupGeometry", nullptr, "Merges corners within tolerance metres and drops or joins degenerate faces (\"all\", the default, \"vertices\", \"edges\" or \"faces\").", nullptr},
    {kDocCommand, "PrimitiveQuad", nullptr, "Replaces the geometry by a quad on the scope's XZ plane facing up (without sizes: filling the scope).", nullptr},
    {kDocCommand, "PrimitiveCube", nullptr, "Replaces the geometry by a box (without sizes: the scope box).", nullptr},
    {kDocCommand, "PrimitiveCylinder", nullptr, "Replaces the geometry by a cylinder of sides sides (default 16) standing on the scope's y = 0.", nullptr},
    {kDocCommand, "PrimitiveSphere", nullptr, "Replaces the geometry by a sphere of sides around (default 16) and divisions pole to pole (default 16).", nullptr},
    {kDocCommand, "PrimitiveDisk", nullptr, "Replaces the geometry by a disk of sides sides (default 16) on the scope's XZ plane facing up.", nullptr},

    // ---------------------------------------------------------------- functions
    {kDocFunction, "Rand", "Rand(a, b)", "A uniform random number between a and b, drawn from the shape's random stream (the run's --seed).", nullptr},
    {kDocFunction, "rand", "rand(a, b)", "The same as Rand(a, b): a uniform random number between a and b.", nullptr},
    {kDocFunction, "sin", "sin(degrees)", "The sine of an angle in degrees.", nullptr},
    {kDocFunction, "cos", "cos(degrees)", "The cosine of an angle in degrees.", nullptr},
    {kDocFunction, "tan", "tan(degrees)", "The tangent of an angle in degrees.", nullptr},
    {kDocFunction, "asin", "asin(x)", "The arc sine of x, in degrees.", nullptr},
    {kDocFunction, "acos", "acos(x)", "The arc cosine of x, in degrees.", nullptr},
    {kDocFunction, "atan", "atan(x)", "The arc tangent of x, in degrees.", nullptr},
    {kDocFunction, "atan2", "atan2(y, x)", "The angle of the point (x, y) from the X axis, in degrees (-180..180].", nullptr},
    {kDocFunction, "sqrt", "sqrt(x)", "The square root of x.", nullptr},
    {kDocFunction, "abs", "abs(x)", "The absolute value of x.", nullptr},
    {kDocFunction, "min", "min(a, b)", "The smaller of a and b.", nullptr},
    {kDocFunction, "max", "max(a, b)", "The larger of a and b.", nullptr},
    {kDocFunction, "floor", "floor(x)", "The largest whole number not above x.", nullptr},
    {kDocFunction, "ceil", "ceil(x)", "The smallest whole number not below x.", nullptr},
    {kDocFunction, "round", "round(x)", "x rounded to the nearest whole number (halves away from zero).", nullptr},
    {kDocFunction, "clamp", "clamp(x, lo, hi)", "x limited to the range lo..hi.", nullptr},
    {kDocFunction, "lerp", "lerp(a, b, t)", "The linear interpolation a + (b - a)·t.", nullptr},
    {kDocFunction, "pow", "pow(x, y)", "x to the power y (also written x ^ y).", nullptr},
    {kDocFunction, "exp", "exp(x)", "e to the power x.", nullptr},
    {kDocFunction, "log", "log(x)", "The natural logarithm of x.", nullptr},
    {kDocFunction, "sign", "sign(x)", "-1, 0 or 1 by the sign of x.", nullptr},
    {kDocFunction, "length", "length(v)", "The length of the vector v.", nullptr},
    {kDocFunction, "dot", "dot(u, v)", "The dot product of the vectors u and v.", nullptr},
    {kDocFunction, "normalize", "normalize(v)", "The vector v scaled to length 1.", nullptr},

    // ---------------------------------------------------------------- queries
    {kDocQuery, "Scope.sx", "Scope.sx", "The working scope's size along its X axis, at that point of the successor.", nullptr},
    {kDocQuery, "Scope.sy", "Scope.sy", "The working scope's size along its Y axis, at that point of the successor.", nullptr},
    {kDocQuery, "Scope.sz", "Scope.sz", "The working scope's size along its Z axis, at that point of the successor.", nullptr},
    {kDocQuery, "Scope.px", "Scope.px", "The X world coordinate of the working scope's origin.", nullptr},
    {kDocQuery, "Scope.py", "Scope.py", "The Y world coordinate of the working scope's origin.", nullptr},
    {kDocQuery, "Scope.pz", "Scope.pz", "The Z world coordinate of the working scope's origin.", nullptr},
    {kDocQuery, "Scope.occ", "Scope.occ(\"noparent\")", "\"none\", \"part\" or \"full\": how far the scope box lies inside the instances placed so far.", nullptr},
    {kDocQuery, "Shape.depth", "Shape.depth", "The depth of the shape being rewritten: the axiom is at 0, the shapes it creates at 1 ...", nullptr},
    {kDocQuery, "Shape.index", "Shape.index", "The shape's position among the shapes its parent's successor created (0, 1, ...).", nullptr},
    {kDocQuery, "Shape.splitIndex", "Shape.splitIndex", "CGA's split.index: the shape's place among the parts its last Subdiv or Repeat derived (0 before any split).", nullptr},
    {kDocQuery, "Shape.splitTotal", "Shape.splitTotal", "CGA's split.total: how many parts the shape's last Subdiv or Repeat derived.", nullptr},
    {kDocQuery, "Shape.compIndex", "Shape.compIndex", "CGA's comp.index: the face's place among the faces its Comp part took.", nullptr},
    {kDocQuery, "Shape.compTotal", "Shape.compTotal", "CGA's comp.total: how many faces its Comp part took.", nullptr},
    {kDocQuery, "Shape.compSel", "Shape.compSel", "CGA's comp.sel: the name of the selector that chose the shape in the last Comp above it (\"front\", \"world.up\", \"street.front\", \"2\"); \"\" outside any.", nullptr},
    {kDocQuery, "Shape.visible", "Shape.visible(\"street\")", "True when the scope's Z is within 60° of world +Z, where the street lies.", nullptr},
    {kDocQuery, "Shape.inside", "Shape.inside(\"intra\", \"label\")", "CGA's occlusion query: the shape lies inside the labelled occluders of its own start shape (\"intra\"), the others' (\"inter\") or both (\"all\").", nullptr},
    {kDocQuery, "Shape.overlaps", "Shape.overlaps(\"intra\", \"label\")", "CGA's occlusion query: the shape overlaps a labelled occluder (\"intra\", \"inter\" or \"all\").", nullptr},
    {kDocQuery, "Shape.touches", "Shape.touches(\"intra\", \"label\")", "CGA's occlusion query: the shape touches a labelled occluder (\"intra\", \"inter\" or \"all\").", nullptr},
    {kDocQuery, "Shape.minimumDistance", "Shape.minimumDistance(\"intra\", \"label\")", "The distance in metres from the scope to the nearest scope labelled so (infinity: none).", nullptr},
    {kDocQuery, "Shape.contextCount", "Shape.contextCount(\"intra\", \"label\")", "How many shapes were labelled so.", nullptr},
    {kDocQuery, "Shape.contextCompare", "Shape.contextCompare(\"inter\", \"label\", \"world.highest\")", "The shape's 0-based rank among the shapes labelled so, by a comparison such as \"world.highest\" or \"area.largest\".", nullptr},
    {kDocQuery, "Geometry.area", "Geometry.area", "The summed area of the shape's faces, in m².", nullptr},
    {kDocQuery, "Geometry.height", "Geometry.height", "The extent of the shape's corners along world Y, in metres.", nullptr},
    {kDocQuery, "Geometry.nVertices", "Geometry.nVertices", "The number of the shape's distinct corners.", nullptr},
    {kDocQuery, "Geometry.nFaces", "Geometry.nFaces", "The number of the shape's faces.", nullptr},
    {kDocQuery, "Geometry.boundaryLength", "Geometry.boundaryLength", "The length of the edges only one face has (a polygon's perimeter, holes included; 0 for a closed solid), in metres.", nullptr},
    {kDocQuery, "Geometry.isConcave", "Geometry.isConcave", "True when a face has a reflex corner or a hole.", nullptr},
    {kDocQuery, "Geometry.isPlanar", "Geometry.isPlanar(1)", "True when every face lies within that many degrees of the first face's plane.", nullptr},
    {kDocQuery, "Geometry.angle", "Geometry.angle(\"maxSlope\")", "In degrees: the steepest face's slope (\"maxSlope\", 0..90), the direction it looks clockwise from north (\"azimuth\") or 90 minus the slope (\"zenith\").", nullptr},
    {kDocQuery, "Geometry.du", "Geometry.du(0, \"uvSpace\")", "How far the texture coordinates spread along u over the shape's corners (max - min).", nullptr},
    {kDocQuery, "Geometry.dv", "Geometry.dv(0, \"uvSpace\")", "How far the texture coordinates spread along v over the shape's corners (max - min).", nullptr},
    {kDocQuery, "Lot.area", "Lot.area", "The lot's area in m², holes taken off (0 without --lots).", nullptr},
    {kDocQuery, "Lot.prop", "Lot.prop(\"height\", 14)", "The lot's property of that name; without lots or without the property, the default (which gives its type).", nullptr},
    {kDocQuery, "Feature.corner", "Feature.corner", "Inside Cells: the feature is a corner of the base mesh.", nullptr},
    {kDocQuery, "Feature.edge", "Feature.edge", "Inside Cells: the feature is an edge of the base mesh.", nullptr},
    {kDocQuery, "Feature.face", "Feature.face", "Inside Cells: the feature is a face of the base mesh.", nullptr},
    {kDocQuery, "Feature.horizontal", "Feature.horizontal", "Inside Cells: an edge within 10° of level, or a face looking mostly up or down.", nullptr},
    {kDocQuery, "Feature.vertical", "Feature.vertical", "Inside Cells: an edge within 10° of upright, or an upright face.", nullptr},
    {kDocQuery, "Feature.curved", "Feature.curved", "Inside Cells: an arc or polyline edge, or a cylindrical face.", nullptr},
    {kDocQuery, "Feature.arc", "Feature.arc", "Inside Cells: an edge fitted as a circular arc.", nullptr},
    {kDocQuery, "Feature.convex", "Feature.convex", "Inside Cells: a convex edge, or a corner whose edges are all convex.", nullptr},
    {kDocQuery, "Feature.concave", "Feature.concave", "Inside Cells: a concave edge, or a corner whose edges are all concave.", nullptr},
    {kDocQuery, "Feature.boundary", "Feature.boundary", "Inside Cells: an edge or corner on the base mesh's boundary.", nullptr},
    {kDocQuery, "Feature.bottom", "Feature.bottom", "Inside Cells: a face looking up (a sill), or an edge or corner next to one.", nullptr},
    {kDocQuery, "Feature.top", "Feature.top", "Inside Cells: a face looking down (a lintel), or an edge or corner next to one.", nullptr},
    {kDocQuery, "Feature.side", "Feature.side", "Inside Cells: neither bottom nor top.", nullptr},
    {kDocQuery, "Feature.label", "Feature.label(\"window\")", "Inside Cells: the label is on the feature (a face's OBJ group or base-part symbol; an edge's faces'; a corner's edges').", nullptr},
    {kDocQuery, "Feature.index", "Feature.index", "Inside Cells: the feature's number among those of its kind.", nullptr},
    {kDocQuery, "Feature.valence", "Feature.valence", "Inside Cells: the edges at a corner, the faces at an edge, the edges around a face.", nullptr},
    {kDocQuery, "Feature.length", "Feature.length", "Inside Cells: an edge's length, in metres.", nullptr},
    {kDocQuery, "Feature.area", "Feature.area", "Inside Cells: a face's area, in m².", nullptr},

    // ---------------------------------------------------------------- a field's members (F a declared field)
    {kDocFieldMember, "vector", "F.vector", "A vector field's vector at the scope's surface point (a tensor's major eigenvector scaled by its eigenvalue), in the tangent plane.", nullptr},
    {kDocFieldMember, "vector1", "F.vector1", "The major eigenvector scaled by its eigenvalue (a vector field: its vector), a world vector in the tangent plane.", nullptr},
    {kDocFieldMember, "vector2", "F.vector2", "The minor eigenvector scaled by its eigenvalue, a world vector in the tangent plane.", nullptr},
    {kDocFieldMember, "gradient", "F.gradient", "The gradient of the major eigenvalue's magnitude (a vector field: of its length; a scalar field: of its value), a tangent vector.", nullptr},
    {kDocFieldMember, "gradient2", "F.gradient2", "The gradient of the minor eigenvalue's magnitude, a tangent vector.", nullptr},
    {kDocFieldMember, "curl", "F.curl", "The curl of the vector field (a tensor's major eigenvector field), a vector along the normal.", nullptr},
    {kDocFieldMember, "curl1", "F.curl1", "The same as F.curl: the curl of the major eigenvector field.", nullptr},
    {kDocFieldMember, "curl2", "F.curl2", "The curl of the minor eigenvector field, a vector along the normal.", nullptr},
    {kDocFieldMember, "jacobianX", "F.jacobianX", "The field's Jacobian applied to the scope's unit X axis: its change per metre along X, a tangent vector.", nullptr},
    {kDocFieldMember, "jacobianY", "F.jacobianY", "The field's Jacobian applied to the scope's unit Y axis: its change per metre along Y, a tangent vector.", nullptr},
    {kDocFieldMember, "jacobianX2", "F.jacobianX2", "The minor eigenvector field's Jacobian applied to the scope's unit X axis.", nullptr},
    {kDocFieldMember, "jacobianY2", "F.jacobianY2", "The minor eigenvector field's Jacobian applied to the scope's unit Y axis.", nullptr},
    {kDocFieldMember, "rgb", "F.rgb", "An image field's colour under the scope, a vector (r, g, b) of 0..1 each.", nullptr},
    {kDocFieldMember, "value", "F.value", "The major eigenvalue (a vector field: its length; a scalar field: its value).", nullptr},
    {kDocFieldMember, "value1", "F.value1", "The major eigenvalue (value1 >= value2).", nullptr},
    {kDocFieldMember, "value2", "F.value2", "The minor eigenvalue (a vector field: 0).", nullptr},
    {kDocFieldMember, "length", "F.length", "The magnitude of the major eigenvalue (a scalar field: its gradient's length).", nullptr},
    {kDocFieldMember, "length1", "F.length1", "The magnitude of the major eigenvalue.", nullptr},
    {kDocFieldMember, "length2", "F.length2", "The magnitude of the minor eigenvalue.", nullptr},
    {kDocFieldMember, "Xangle", "F.Xangle", "The angle in degrees from the scope's X axis to the field's major direction, counter-clockwise about the normal.", nullptr},
    {kDocFieldMember, "Xangle1", "F.Xangle1", "The angle in degrees from the scope's X axis to the major direction; RS(F.Xangle1) turns X onto the field.", nullptr},
    {kDocFieldMember, "Xangle2", "F.Xangle2", "The angle in degrees from the scope's X axis to the minor direction.", nullptr},
    {kDocFieldMember, "Yangle1", "F.Yangle1", "The angle in degrees from the scope's Y axis to the major direction.", nullptr},
    {kDocFieldMember, "div", "F.div", "The divergence of the vector field (a tensor's major eigenvector field).", nullptr},
    {kDocFieldMember, "div1", "F.div1", "The same as F.div: the divergence of the major eigenvector field.", nullptr},
    {kDocFieldMember, "div2", "F.div2", "The divergence of the minor eigenvector field.", nullptr},
    {kDocFieldMember, "streamcurv1", "F.streamcurv1", "The curvature (1/metres) of the major (hyper)streamline through the point, counter-clockwise positive.", nullptr},
    {kDocFieldMember, "streamcurv2", "F.streamcurv2", "The curvature (1/metres) of the minor hyperstreamline through the point.", nullptr},
    {kDocFieldMember, "tensorXX", "F.tensorXX", "The tensor's component X·T·X along the scope's X axis laid into the tangent plane.", nullptr},
    {kDocFieldMember, "tensorXY", "F.tensorXY", "The tensor's component X·T·Y.", nullptr},
    {kDocFieldMember, "tensorYX", "F.tensorYX", "The tensor's component Y·T·X (differs from tensorXY for an asymmetric tensor only).", nullptr},
    {kDocFieldMember, "tensorYY", "F.tensorYY", "The tensor's component Y·T·Y.", nullptr},
    {kDocFieldMember, "rotation", "F.rotation", "An asymmetric tensor's rotational part w (T = S + wJ; 0 for other fields).", nullptr},
    {kDocFieldMember, "eigenangle", "F.eigenangle", "The angle in degrees between the eigenvectors: 90 for symmetric tensors and vector fields.", nullptr},
    {kDocFieldMember, "mincurv", "F.mincurv", "The minimum principal curvature (1/metres) of a curvature field's surface; positive on a convex surface.", nullptr},
    {kDocFieldMember, "maxcurv", "F.maxcurv", "The maximum principal curvature (1/metres) of a curvature field's surface.", nullptr},
    {kDocFieldMember, "meancurv", "F.meancurv", "The mean curvature (1/metres) of a curvature field's surface.", nullptr},
    {kDocFieldMember, "gausscurv", "F.gausscurv", "The Gaussian curvature (1/m²) of a curvature field's surface.", nullptr},
    {kDocFieldMember, "intensity", "F.intensity", "An image field's brightness (0..1) under the scope, bilinear.", nullptr},

    // ---------------------------------------------------------------- surfaces (signatures: sema_environment.cpp's)
    {kDocSurface, "torus", nullptr, "A torus around the Z axis: radius R, tube radius r (R > r > 0); an optional last argument gives the segments around the tube (default 32).", nullptr},
    {kDocSurface, "sphere", nullptr, "A sphere of radius r about the origin; an optional last argument gives its icosahedron subdivisions (default 4: 5120 faces).", nullptr},
    {kDocSurface, "plane", nullptr, "A flat w × h rectangle in the XY plane, centred at the origin, normal +Z; an optional last argument gives the segments along its longer side (default 32).", nullptr},
    {kDocSurface, "genus2", nullptr, "A closed double torus in the XY plane; an optional argument gives its Catmull-Clark levels (default 3).", nullptr},
    {kDocSurface, "cylinder", nullptr, "An open cylinder of radius r around the Z axis, h high; an optional last argument gives the segments around it (default 48).", nullptr},
    {kDocSurface, "tori3", nullptr, "FGSG Fig. 17's genus-7 surface: the union of three tori (radius R, tube r, R > 2r) about the Z, X and Y axes.", nullptr},

    // ---------------------------------------------------------------- field sources
    {kDocFieldSource, "tensor", "tensor(\"foot.tfield\")", "A tensor field loaded from a file, relative to the grammar's folder (`design tensor { ... }` designs one instead).", nullptr},
    {kDocFieldSource, "vector", "vector(\"flow.vfield\")", "A vector field loaded from a file, relative to the grammar's folder (`design vector { ... }` designs one instead).", nullptr},
    {kDocFieldSource, "scalar", "scalar(\"heights.sfield\") or scalar(\"map.png\") or scalar(expression of x, y, z)", "A scalar field: a number per vertex from a file, a picture's brightness under each vertex, or an expression of the vertex's position.", nullptr},
    {kDocFieldSource, "design", "design tensor { wedge at vertex 0; ... } or design vector { node at (x, y, z); ... }", "A field designed from elements (regular, wedge, trisector, node, centre, saddle) with their decay and strength, optionally smoothed (`smooth 300;`).", nullptr},
    {kDocFieldSource, "curvature", "curvature", "The curvature tensor of the surface (its queries mincurv, maxcurv, meancurv, gausscurv).", nullptr},
    {kDocFieldSource, "image", "image(\"cat.png\")", "A tensor field from a picture laid over the surface seen from above: its major direction runs along the picture's outlines; `.intensity` and `.rgb` read the picture.", nullptr},

    // ---------------------------------------------------------------- .cga operations
    {kDocCgaOperation, "split", "split(x|y|z) { size : Op | ... }*", "CityEngine's split: cuts the shape along the axis into parts of the sizes (absolute, 'relative, ~floating).", "Subdiv"},
    {kDocCgaOperation, "splitArea", "splitArea(x|y|z) { area : Op | ... }", "CityEngine's splitArea: cuts a flat shape into parts of the given areas (m²).", "SplitArea"},
    {kDocCgaOperation, "extrude", "extrude(height) or extrude(world.y, height)", "Extrudes the shape along its normal by height metres.", "Extrude"},
    {kDocCgaOperation, "comp", "comp(f|e) { selector : Op | ... }", "Splits the shape into its faces or edges, each part running the operations its selector names.", "Comp"},
    {kDocCgaOperation, "offset", "offset(distance) or offset(distance, inside|border)", "Offsets the polygon's edges by distance metres (negative: inward), keeping the inside, the border band or both.", "Offset"},
    {kDocCgaOperation, "roofGable", "roofGable(angle, overhangX, overhangY) or roofGable(byHeight, height, ...)", "A gable roof on the footprint, by slope angle (degrees) or height, overhangs in metres.", "Roof"},
    {kDocCgaOperation, "roofHip", "roofHip(angle, overhang) or roofHip(byHeight, height, overhang)", "A hipped roof on the footprint, by slope angle (degrees) or height, overhang in metres.", "Roof"},
    {kDocCgaOperation, "roofPyramid", "roofPyramid(angle) or roofPyramid(byHeight, height)", "A pyramid roof on the footprint, by slope angle (degrees) or height.", "Roof"},
    {kDocCgaOperation, "roofShed", "roofShed(angle, index) or roofShed(byHeight, height, index)", "A shed roof rising from the edge, by slope angle (degrees) or height.", "Roof"},
    {kDocCgaOperation, "roofRidge", "roofRidge(angle) or roofRidge(byHeight, height)", "A ridge roof on the footprint, by slope angle (degrees) or height.", "Roof"},
    {kDocCgaOperation, "i", "i(asset) or i(asset, yUp|zUp, alignSizeAndPosition|keepSizeAndPosition|keepSizeAlignPosition)", "Inserts the asset into the scope.", "I"},
    {kDocCgaOperation, "s", "s(x, y, z)", "Sets the scope's size ('relative and ~floating sizes too).", "S"},
    {kDocCgaOperation, "t", "t(x, y, z)", "Moves the scope along its own axes, in metres.", "T"},
    {kDocCgaOperation, "r", "r(ax, ay, az) or r(scopeCenter, ax, ay, az)", "Turns the scope about its axes, in degrees.", "R"},
    {kDocCgaOperation, "rotate", "rotate(rel|abs, scope|pivot|object|world, ax, ay, az)", "Turns the scope and its geometry, in degrees.", "Rotate"},
    {kDocCgaOperation, "translate", "translate(rel|abs, scope|pivot|object|world, x, y, z)", "Moves the scope by or to (x, y, z) in that coordinate system.", "Translate"},
    {kDocCgaOperation, "setPivot", "setPivot(xyz|yzx|zxy, cornerIndex)", "Puts the pivot at a scope corner (0..7), axes in that order pointing into the scope; the scope becomes its frame.", "SetPivot"},
    {kDocCgaOperation, "center", "center(x|y|z|xy|xz|yz|xyz)", "Centres the scope on its parent's along the axes.", "Center"},
    {kDocCgaOperation, "color", "color(\"#rrggbb\") or color(r, g, b)", "Sets the shape's colour.", "Color"},
    {kDocCgaOperation, "set", "set(material.color.rgb|material.roughness|..., value)", "Sets a material attribute of the shape (colour, roughness, metallic, opacity, maps).", "Material"},
    {kDocCgaOperation, "texture", "texture(\"image.png\")", "Sets the colour map of the shape's material, on its projection.", "Material"},
    {kDocCgaOperation, "setupProjection", "setupProjection(uvSet, scope.xy|..., tileWidth, tileHeight)", "Sets up a texture projection on the scope's plane with tiles of that size.", "SetupProjection"},
    {kDocCgaOperation, "projectUV", "projectUV(uvSet)", "Projects the texture coordinates from the set's projection.", "ProjectUV"},
    {kDocCgaOperation, "tileUV", "tileUV(uvSet, tileWidth, tileHeight)", "Tiles the texture coordinates.", "TileUV"},
    {kDocCgaOperation, "scaleUV", "scaleUV(uvSet, uFactor, vFactor)", "Scales the texture coordinates.", "ScaleUV"},
    {kDocCgaOperation, "translateUV", "translateUV(uvSet, uOffset, vOffset)", "Moves the texture coordinates.", "TranslateUV"},
    {kDocCgaOperation, "rotateUV", "rotateUV(uvSet, degrees)", "Turns the texture coordinates about (0, 0), in degrees.", "RotateUV"},
    {kDocCgaOperation, "normalizeUV", "normalizeUV(uvSet, uv|u|v, separatePerFace|collectiveAllFaces)", "Normalizes the texture coordinates to 0..1.", "NormalizeUV"},
    {kDocCgaOperation, "deleteUV", "deleteUV(uvSet)", "Removes the texture coordinates of the set.", "DeleteUV"},
    {kDocCgaOperation, "copyUV", "copyUV(sourceUvSet, destinationUvSet)", "Makes the destination set's coordinates the source set's.", "CopyUV"},
    {kDocCgaOperation, "print", "print(value)", "Prints the value on the console.", "Print"},
    {kDocCgaOperation, "report", "report(\"key\", value)", "Reports the value under the key for the start shape.", "Report"},
    {kDocCgaOperation, "label", "label(\"name\")", "Labels the shape for the occlusion and context queries.", "Label"},
    {kDocCgaOperation, "scatter", "scatter(surface|volume|scope, n, uniform|gaussian ...) { Op }", "Scatters n points over the shape, each a shape of its own.", "Scatter"},
    {kDocCgaOperation, "insertAlongUV", "insertAlongUV(uvSet, asset, height[, scope.y|vertex.normal[, alignPosition|keepPosition]])", "Lays the asset out along the shape's texture coordinates and bends it onto its faces, as for a rail or a kerb along a street.", "InsertAlongUV"},
    {kDocCgaOperation, "alignScopeToAxes", "alignScopeToAxes() or alignScopeToAxes(y)", "Aligns the scope to the world's axes.", "AlignScopeToAxes"},
    {kDocCgaOperation, "alignScopeToGeometry", "alignScopeToGeometry(yUp|zUp, faceIndex|largest, edgeIndex|longest)", "Aligns the scope to a face and an edge of the geometry.", "AlignScopeToGeometry"},
    {kDocCgaOperation, "rotateScope", "rotateScope(ax, ay, az)", "Turns the scope alone, in degrees.", "RotateScope"},
    {kDocCgaOperation, "mirrorScope", "mirrorScope(flipX, flipY, flipZ)", "Mirrors the scope's axes.", "MirrorScope"},
    {kDocCgaOperation, "mirror", "mirror(flipX, flipY, flipZ)", "Mirrors the geometry in its scope.", "Mirror"},
    {kDocCgaOperation, "setback", "setback(distance) { selector : Op | remainder : Op }", "Sets the selected edges back by distance metres.", "Setback"},
    {kDocCgaOperation, "setbackToArea", "setbackToArea(area) { selector : Op | remainder : Op }", "Sets the edges back to leave a remainder of area m².", "SetbackToArea"},
    {kDocCgaOperation, "setbackPerEdge", "setbackPerEdge(distance) { selector : Op | remainder : Op }", "Sets each edge back by its own distance.", "SetbackPerEdge"},
    {kDocCgaOperation, "convexify", "convexify() or convexify(maxLength)", "Cuts the polygon into convex pieces.", "Convexify"},
    {kDocCgaOperation, "taper", "taper(height)", "Makes the polygon a pyramid of that height.", "Taper"},
    {kDocCgaOperation, "envelope", "envelope(normal|world.up, maxHeight, baseHeight, angle ...)", "The solid below each edge's plane.", "Envelope"},
    {kDocCgaOperation, "shapeL", "shapeL(frontWidth, leftWidth) { shape : Op | remainder : Op }", "An L-shaped footprint and the rest.", "ShapeL"},
    {kDocCgaOperation, "shapeU", "shapeU(frontWidth, rightWidth, leftWidth) { shape : Op | remainder : Op }", "A U-shaped footprint and the rest.", "ShapeU"},
    {kDocCgaOperation, "shapeO", "shapeO(frontWidth, rightWidth, backWidth, leftWidth) { shape : Op | remainder : Op }", "An O-shaped footprint and the courtyard.", "ShapeO"},
    {kDocCgaOperation, "innerRectangle", "innerRectangle(scope|edge) { shape : Op }", "The largest rectangle inside the polygon.", "InnerRectangle"},
    {kDocCgaOperation, "innerRect", "innerRect()", "CityEngine's older name of innerRectangle.", "InnerRectangle"},
    {kDocCgaOperation, "deleteHoles", "deleteHoles()", "Drops every face's holes.", "DeleteHoles"},
    {kDocCgaOperation, "trim", "trim()", "Cuts the shape's geometry by the trim planes comp(f) gave it; the primitives are trimmed as they are made.", "ApplyTrimPlanes"},
    {kDocCgaOperation, "reverseNormals", "reverseNormals()", "Turns every face over.", "ReverseNormals"},
    {kDocCgaOperation, "resetGeometry", "resetGeometry()", "Makes the geometry the scope box again.", "ResetGeometry"},
    {kDocCgaOperation, "cleanupGeometry", "cleanupGeometry(all|vertices|edges|faces, tolerance)", "Merges close corners and drops degenerate faces.", "CleanupGeometry"},
    {kDocCgaOperation, "primitiveQuad", "primitiveQuad() or primitiveQuad(width, length)", "Replaces the geometry by a quad.", "PrimitiveQuad"},
    {kDocCgaOperation, "primitiveCube", "primitiveCube() or primitiveCube(width, height, depth)", "Replaces the geometry by a box.", "PrimitiveCube"},
    {kDocCgaOperation, "primitiveCylinder", "primitiveCylinder(sides, radius, height)", "Replaces the geometry by a cylinder.", "PrimitiveCylinder"},
    {kDocCgaOperation, "primitiveSphere", "primitiveSphere(sides, divisions, radius)", "Replaces the geometry by a sphere.", "PrimitiveSphere"},
    {kDocCgaOperation, "primitiveDisk", "primitiveDisk(sides, radius)", "Replaces the geometry by a disk.", "PrimitiveDisk"},

    // ---------------------------------------------------------------- .cga functions
    {kDocCgaFunction, "rand", "rand(), rand(max), rand(min, max)", "A uniform random number between min and max (defaults 0 and 1).", "Rand"},
    {kDocCgaFunction, "p", "p(probability)", "True with the probability (0..1): rand() < probability.", "Rand"},
    {kDocCgaFunction, "rint", "rint(x)", "x rounded to the nearest whole number.", "round"},
    {kDocCgaFunction, "ln", "ln(x)", "The natural logarithm of x.", "log"},
    {kDocCgaFunction, "log10", "log10(x)", "The base-10 logarithm of x (log(x) / log(10)).", "log"},
    {kDocCgaFunction, "isnan", "isnan(x)", "True when x is not a number: !(abs(x) >= 0).", "abs"},
    {kDocCgaFunction, "isinf", "isinf(x)", "True when x is infinite: abs(x) above the largest double.", "abs"},
    {kDocCgaFunction, "inside", "inside(intra|inter|all, \"label\")", "The shape lies inside the labelled occluders.", "Shape.inside"},
    {kDocCgaFunction, "overlaps", "overlaps(intra|inter|all, \"label\")", "The shape overlaps a labelled occluder.", "Shape.overlaps"},
    {kDocCgaFunction, "touches", "touches(intra|inter|all, \"label\")", "The shape touches a labelled occluder.", "Shape.touches"},
    {kDocCgaFunction, "minimumDistance", "minimumDistance(intra|inter|all, \"label\")", "The distance in metres to the nearest labelled shape.", "Shape.minimumDistance"},
    {kDocCgaFunction, "contextCount", "contextCount(intra|inter|all, \"label\")", "How many shapes were labelled so.", "Shape.contextCount"},
    {kDocCgaFunction, "contextCompare", "contextCompare(intra|inter|all, \"label\", world.highest|...)", "The shape's rank among the labelled shapes by the comparison.", "Shape.contextCompare"},
    {kDocCgaFunction, "geometry.area", "geometry.area()", "The shape's surface area in m².", "Geometry.area"},
    {kDocCgaFunction, "geometry.height", "geometry.height()", "The shape's extent along world Y, in metres.", "Geometry.height"},
    {kDocCgaFunction, "geometry.nVertices", "geometry.nVertices()", "The number of the shape's corners.", "Geometry.nVertices"},
    {kDocCgaFunction, "geometry.nFaces", "geometry.nFaces()", "The number of the shape's faces.", "Geometry.nFaces"},
    {kDocCgaFunction, "geometry.isConcave", "geometry.isConcave()", "True when a face is concave or has a hole.", "Geometry.isConcave"},
    {kDocCgaFunction, "geometry.boundaryLength", "geometry.boundaryLength()", "The length of the geometry's boundary, in metres.", "Geometry.boundaryLength"},
    {kDocCgaFunction, "geometry.isPlanar", "geometry.isPlanar(tolerance)", "True when the faces are coplanar within tolerance degrees.", "Geometry.isPlanar"},
    {kDocCgaFunction, "geometry.angle", "geometry.angle(maxSlope|azimuth|zenith)", "An angle of the geometry in degrees.", "Geometry.angle"},
    {kDocCgaFunction, "geometry.du", "geometry.du(0, uvSpace)", "The spread of the texture coordinates along u.", "Geometry.du"},
    {kDocCgaFunction, "geometry.dv", "geometry.dv(0, uvSpace)", "The spread of the texture coordinates along v.", "Geometry.dv"},

    // ---------------------------------------------------------------- .cga shape attributes
    {kDocCgaAttribute, "scope.sx", "scope.sx", "The scope's size along X, in metres.", "Scope.sx"},
    {kDocCgaAttribute, "scope.sy", "scope.sy", "The scope's size along Y, in metres.", "Scope.sy"},
    {kDocCgaAttribute, "scope.sz", "scope.sz", "The scope's size along Z, in metres.", "Scope.sz"},
    {kDocCgaAttribute, "scope.tx", "scope.tx", "The scope's origin, X coordinate.", "Scope.px"},
    {kDocCgaAttribute, "scope.ty", "scope.ty", "The scope's origin, Y coordinate.", "Scope.py"},
    {kDocCgaAttribute, "scope.tz", "scope.tz", "The scope's origin, Z coordinate.", "Scope.pz"},
    {kDocCgaAttribute, "split.index", "split.index", "The shape's index among its split's parts.", "Shape.splitIndex"},
    {kDocCgaAttribute, "split.total", "split.total", "How many parts its split made.", "Shape.splitTotal"},
    {kDocCgaAttribute, "comp.index", "comp.index", "The component's index among its comp's parts.", "Shape.compIndex"},
    {kDocCgaAttribute, "comp.total", "comp.total", "How many components its comp made.", "Shape.compTotal"},
    {kDocCgaAttribute, "trim.horizontal", "set(trim.horizontal, true)", "Turns the shape's horizontal trim planes on (off by default); set only.", "SetTrim"},
    {kDocCgaAttribute, "trim.vertical", "set(trim.vertical, false)", "Turns the shape's vertical trim planes off (on by default); set only.", "SetTrim"},
    {kDocCgaAttribute, "comp.sel", "comp.sel", "The selector that chose the component, as written (\"side\", \"world.up\", \"street.front\", \"2\").", "Shape.compSel"},
};

// A table cell: '|' would end it.
std::string builtinDocCell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

void builtinDocSection(std::ostringstream& out, BuiltinDocKind kind, const char* title, const char* header, bool cga) {
  out << "\n### " << title << "\n\n| " << header << " | |" << (cga ? " fgsg |" : "") << "\n|---|---|"
      << (cga ? "---|" : "") << "\n";
  for (const BuiltinDoc& d : kBuiltinDocTable) {
    if (d.kind != kind) continue;
    out << "| `" << builtinDocCell(builtinDocSignature(d)) << "` | " << builtinDocCell(d.doc) << " |";
    if (cga) out << " `" << builtinDocCell(d.fgsgName ? d.fgsgName : "") << "` |";
    out << "\n";
  }
}

}  // namespace

std::span<const BuiltinDoc> builtinDocs() { return kBuiltinDocTable; }

const BuiltinDoc* findBuiltinDoc(BuiltinDocKind kind, const std::string& name) {
  for (const BuiltinDoc& d : kBuiltinDocTable)
    if (d.kind == kind && name == d.name) return &d;
  return nullptr;
}

std::string builtinDocSignature(const BuiltinDoc& d) {
  if (d.signature) return d.signature;
  if (d.kind == BuiltinDocKind::Surface) {
    const SurfaceGeneratorInfo* g = findSurfaceGenerator(d.name);
    return g ? g->signature : d.name;
  }
  const CommandInfo* c = findCommand(d.name);
  return c ? c->signature : d.name;
}

std::string builtinReferenceMarkdown() {
  std::ostringstream out;
  out << "<!-- Generated from frontend/builtin_docs.cpp by `fgsg builtin-reference`: do not edit here "
         "(docs/editors.md says how to regenerate). -->\n\n"
         "What `fgsg lsp` shows on hover. Angles are in degrees, lengths in metres (the scope's units).\n";
  builtinDocSection(out, kDocCommand, "Commands", "command", false);
  builtinDocSection(out, kDocFunction, "Functions", "function", false);
  builtinDocSection(out, kDocQuery, "Queries", "query", false);
  builtinDocSection(out, kDocFieldMember, "Field queries (`F` a declared field)", "query", false);
  builtinDocSection(out, kDocSurface, "Surfaces (`surface NAME(...);`)", "surface", false);
  builtinDocSection(out, kDocFieldSource, "Field sources (`field F = ...;`)", "source", false);
  builtinDocSection(out, kDocCgaOperation, "`.cga` operations", "CityEngine operation", true);
  builtinDocSection(out, kDocCgaFunction, "`.cga` functions", "CityEngine function", true);
  builtinDocSection(out, kDocCgaAttribute, "`.cga` shape attributes", "CityEngine attribute", true);
  return out.str();
}

}  // namespace fgsg::frontend
