#include "cli/option_help.h"

namespace fgsg::cli {

namespace {

// Options several commands share, described once.
const char* const kSurfaceOptions =
    "  --surface FILE     grow on this mesh instead of the grammar's surface (path relative\n"
    "                     to the current directory)\n"
    "  --surface-size S   centre the surface and scale it so its largest extent is S\n"
    "  --repair-surface   repair what can be repaired in the surface mesh instead of failing\n";
const char* const kSetOption =
    "  --set NAME=VALUE   override the grammar's attr NAME (repeatable; a module's as\n"
    "                     facade.floors=4): a number, true/false, text or x,y,z\n";
const char* const kEngineOption =
    "  --engine E         jit (default): compile the rules to native code first (cached in\n"
    "                     $FGSG_CACHE_DIR or ~/.cache/fgsg); interp: the reference interpreter\n";
const char* const kStartRuleOption =
    "  --start-rule NAME  a .cga grammar: derive each lot (or the default lot) with rule NAME\n"
    "                     instead of the file's @StartRule (error E803 for an fgsg grammar)\n";

const char* const kRun =
    "  -o, --output FILE  the mesh: .glb (default: FILE's stem + .glb in the current\n"
    "                     directory), .obj or .ply\n"
    "  --seed N           the random seed, 0 to 2^64-1 (default 1): same seed, same model\n"
    "%SET%"
    "  --preview FILE     also draw a PNG preview of the model\n"
    "  --camera C         the preview's view: fit (default: 3/4 view fitted to the model, a\n"
    "                     flat pattern from above) or azimuth=DEG,elevation=DEG,distance=D\n"
    "                     (each optional): orbit the box's centre, Y up, azimuth from +X\n"
    "                     towards +Z, elevation up from XZ, distance in scene units\n"
    "  --instances FILE   write every placed instance (asset, transform, symbol, parameters)\n"
    "                     as JSON\n"
    "  --lines FILE       write the grammar's lines (Line, LineSeg) as a JSON line graph\n"
    "  --report FILE      write what Report(key, value) collected, per start shape, as JSON\n"
    "  --stats            print the derivation's figures (shapes, instances, times) on stdout\n"
    "  -q, --quiet        no warnings, no 'wrote ...' line (R messages still print)\n"
    "  --instancing M     the glTF scene's repeated assets: auto (default: instanced where\n"
    "                     that is smaller), on, nodes (a node each, for Blender) or off (baked)\n"
    "  --group-by G       the scene's nodes per start shape: symbol (default), rule, label or\n"
    "                     none; `--instancing off --group-by none` is one flattened mesh\n"
    "  --split-output DIR a file per start shape in DIR, with DIR/manifest.json\n"
    "  --quantize         the glTF scene's vertex data as 16-bit integers (KHR_mesh_quantization,\n"
    "                     which the file then requires): about 0.75 of the bytes, positions\n"
    "                     within box size / 131070 per axis\n"
    "  --max-shapes N     stop after N shapes (default 20000000), keeping what was derived\n"
    "  --max-depth N      shapes at depth N or more stay terminal (default 100000)\n"
    "  --step N           an L-system (derive parallel): its derivation after N steps (0: the\n"
    "                     axiom) instead of its length; past the length, the length (a warning)\n"
    "  --max-seconds S    stop deriving after S seconds (default 120), keeping what was\n"
    "                     derived; field design, tracing and synthesis are bounded too\n"
    "  --max-memory SIZE  stop deriving when it holds SIZE (512M, 2G; default half the\n"
    "                     RAM), counting the mesh its instances will become; kept likewise\n"
    "  --collide-all      test every I() for collisions as if it were IC()\n"
    "%ENGINE%"
    "%SURFACE%"
    "  --start x,y,z      start the axiom's scope at the surface point closest to x,y,z\n"
    "                     (default: closest to the centre of the surface's bounding box)\n"
    "  --seed-points S    on-mesh marching: start the axiom once per seed, S a file of\n"
    "                     \"x y z [dx dy dz]\" lines, a seed x,y,z[:dx,dy,dz] or a quoted list\n"
    "                     \"x,y,z;x,y,z\"; repeatable\n"
    "  --seed-density T   with --seed-count N: N more seeds drawn where the grammar's\n"
    "                     texture T is bright (density proportional to its value and the area)\n"
    "  --seed-count N     how many seeds --seed-density draws (1 to 1000000)\n"
    "  --lots FILE        derive the axiom once per lot of a GeoJSON file (Polygon and\n"
    "                     MultiPolygon features) or per polygon face of an OBJ/PLY/OFF mesh\n"
    "                     (Y up), its shape the lot's footprint; attrs named like a lot's\n"
    "                     properties take their values (docs/cga.md)\n"
    "%START_RULE%"
    "  --march-candidates N  directions tried around a failed Marching condition (default 8)\n"
    "  --atlas-resolution N  side of the marching geometry image in texels (default 1024)\n"
    "  --march-units U    Marching's length: surface (3D distance, default) or texels\n";

const char* const kCheck = "%START_RULE%";

const char* const kFmt =
    "  --check            write nothing; list the files that would change and exit 1 if any\n"
    "                     does (for CI)\n"
    "  --stdout           print the formatted grammars instead of rewriting the files\n";

const char* const kIr = "  --llvm             print the LLVM IR the JIT compiles instead of fgsg's IR\n";

const char* const kRepl = "%ENGINE%";

const char* const kCompile =
    "  -o, --output FILE  the library, libNAME.so (default: lib + FILE's stem + .so)\n"
    "  --header DIR       write NAME.h into DIR (default: beside the library)\n"
    "  --start-rule NAME  a .cga grammar's start rule (Style$Rule: in that style) for the library\n"
    "  -q, --quiet        no warnings, no 'wrote libNAME.so and NAME.h' line\n";

const char* const kAtlas =
    "  --preview FILE     draw the geometry image (charts, indirection texels) as PNG\n"
    "  --resolution N     the geometry image's side in texels, 16 to 8192 (default 1024)\n"
    "  --surface-size S   centre the mesh and scale it so its largest extent is S\n"
    "  --repair-surface   repair what can be repaired in the mesh instead of failing\n"
    "  --paint x,y,z,r    paint a sphere brush into --mask (repeatable)\n"
    "  --paint-slab x,y,z,nx,ny,nz,w  paint the band within w of the plane through x,y,z\n"
    "                     square to n into --mask (repeatable)\n"
    "  --mask FILE        the painted mask, a grey PNG in the mesh's texture coordinates\n"
    "  --mask-size N      the mask's side in pixels, 8 to 8192 (default 1024)\n"
    "  --export-uv FILE   write the mesh as OBJ with the texture coordinates contexts are\n"
    "                     read at (one vt per chart corner), to paint a mask elsewhere\n";

const char* const kEvolve =
    "  --k K              every rule is K x K alleles (1 to 16, default 3)\n"
    "  --axiom-side A     the axiom is A x A (1 to 16, default 1)\n"
    "  --generation G     the L-system generation whose pattern is measured (0 to 12, default 4)\n"
    "  --p4               require a p4 pattern (the paper's section 6.1)\n"
    "  --seed N           the random seed (default 1); the same seed gives the same run\n"
    "  --population N     individuals per generation (2 to 100000, default 100)\n"
    "  --max-generations N  stop after N generations (default 200)\n"
    "  --threshold F      stop when the best fitness reaches F, 0 to 1 (default 0.7)\n"
    "  --parents N        the best N breed (default 20)\n"
    "  --elite N          the best N survive unchanged (default 2)\n"
    "  --crossover P      probability that a child comes from a crossover (default 0.9)\n"
    "  --mutation P       probability of mutating each allele of a child (default 0.1)\n"
    "  --weights a,b,c[,d]  symmetry, connectivity, complexity (and p4) weights (1,1,1,3)\n"
    "  --max-seconds S    end the search after S seconds, keeping the best so far\n"
    "  --lsystem '{...}'  measure and draw this L-system instead of searching\n"
    "  --json FILE        write the result, its terms and the history as JSON\n"
    "  --preview FILE     draw the measured pattern as PNG\n"
    "  --cell-pixels N    pixels per cell in the preview (4 to 1024, default 32)\n"
    "  -q, --quiet        print only the L-system\n"
    "  --surface MESH     lay the pattern on this mesh through a polycube (section 5)\n"
    "  --resolution N     polycube cells along the mesh's largest extent (1 to 256, default 8)\n"
    "  --max-stretch R    leave out cells whose longest mapped side is over R times their\n"
    "                     shortest, with a counted warning (R >= 1, 0 for no limit, default 4)\n"
    "  --stats            print the surface ornament's figures (cells, triangles, stretch\n"
    "                     median, p95, max) as `name value` lines\n";

const char* const kField =
    "  -o, --output FILE  the sketch: surface, streamlines and singularities (.glb, .obj, .ply)\n"
    "  --preview FILE     draw the sketch as PNG\n"
    "  --field NAME       the field to show (default the grammar's first)\n"
    "  --singularities FILE  write the singularities (kind, index, position) as JSON\n"
    "  --seeds N          streamline seeds spread over the faces (1 to 100000, default 150)\n"
    "  --length L         the most a streamline runs either way (default a tenth of the\n"
    "                     surface's diagonal)\n"
    "  --step S           distance between a streamline's points (default a 400th of it)\n"
    "  --minor            a tensor field's minor hyperstreamlines too\n"
    "%SURFACE%";

const char* const kView =
    "  --port N           the port, 0 to 65535 (default 8765; 0: any free port)\n"
    "  --host ADDRESS     the address to listen on (default 127.0.0.1)\n"
    "  --no-token         serve without the session token (127.0.0.1 only)\n"
    "  --seed N           the first seed (the page steps it)\n"
    "  --steps            an L-system: a slider and play/pause through its derivation's steps,\n"
    "                     0 (the axiom) to its length\n"
    "  --step N           the step the page starts at (default: the length), as fgsg run --step\n"
    "  --seed-points FILE where the page's marching seeds are written and read (default: the\n"
    "                     grammar's name with .seeds, beside it; fgsg run --seed-points reads it)\n"
    "%SET%"
    "%ENGINE%"
    "%SURFACE%"
    "%START_RULE%";

const char* const kSynth =
    "a label grid, tile set or image EXAMPLE (discrete synthesis, docs/synthesis.md):\n"
    "  --size X Y [Z]     the output grid in cells (each 1 to 1048576; Z defaults to 1)\n"
    "  --block N          modify the model in overlapping N-blocks (0: the whole grid at once)\n"
    "  --seed N           the random seed (default 1)\n"
    "  --labels FILE      write the result as a label grid\n"
    "  -o, --output FILE  place each label's asset in its cells (.glb, .obj, .ply; default,\n"
    "                     as fgsg run, unless --labels: EXAMPLE's stem + .glb here)\n"
    "  --preview FILE     draw that model as PNG\n"
    "  --cell SIZE        a cell's size in world units for -o and --preview (default 1)\n"
    "  --periodic         the grid wraps around along x and y\n"
    "  --mask FILE        an image over the grid: outside its dark shape only `background`\n"
    "                     labels (docs/synthesis.md)\n"
    "  --order O          cells in scanline order (default) or by least entropy first\n"
    "  --retries N        extra tries of a block that failed (0 to 1000, default 2)\n"
    "  --attempts N       whole-grid restarts after a contradiction (default 10)\n"
    "  --closed           the box's faces hold only labels found on the example's faces\n"
    "  --border FACE=LABEL  the label beyond a face (xmin xmax ymin ymax zmin zmax; repeatable)\n"
    "  --symmetry KIND    mirror-x, mirror-y, rotate-90, rotate-180, translate-x:N or\n"
    "                     translate-y:N: the output is its own image (repeatable)\n"
    "  --connect N        grow the `connect` labels from N seeds, connected\n"
    "  --max-steps N      stop after N assignments (default 64 per cell and pass)\n"
    "  --max-seconds S    stop after S seconds (default 30), as fgsg run's limit\n"
    "  --time-limit S     the old name of --max-seconds (deprecated: says so on stderr)\n"
    "  --stats            print the figures on stdout as fgsg run does: `name value` lines,\n"
    "                     then time.synthesize\n"
    "a polygonal EXAMPLE (.obj .ply .off .stl .glb: continuous synthesis) takes --size X Y Z\n"
    "(world units), --seed, --block, --connect, --mask, --symmetry (mirror-x, mirror-z),\n"
    "--retries (default 6), --max-seconds (default 120; --time-limit, deprecated), -o (default:\n"
    "EXAMPLE's stem + .glb), --preview, --stats (with time.compile, time.assign, time.surface), and:\n"
    "  --spacing S        the planes' spacing along the axes (default 1)\n"
    "  --fill F           how likely a free vertex starts solid, 0 to 1 (default 0.5)\n"
    "  --fixed-width A,B,C:N  objects exactly N spacings wide along direction A,B,C\n"
    "  --plane-step A,B,C:N   only every N-th plane of direction A,B,C\n"
    "  --on-ground        every part stands on the floor (the default)\n"
    "  --floating         parts need not stand on the floor\n"
    "  --perturb D        move each part afterwards by up to D along x and z\n"
    "  --passes N         sweeps over all blocks (default 2)\n";

std::string expand(std::string text) {
  const std::pair<const char*, const char*> parts[] = {
      {"%SET%", kSetOption}, {"%ENGINE%", kEngineOption}, {"%SURFACE%", kSurfaceOptions},
      {"%START_RULE%", kStartRuleOption}};
  for (const auto& [key, value] : parts)
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at))
      text.replace(at, std::string(key).size(), value);
  return text;
}

}  // namespace

std::string optionHelp(const std::string& command) {
  const std::pair<const char*, const char*> texts[] = {
      {"run", kRun},         {"check", kCheck}, {"ir", kIr},         {"repl", kRepl},   {"compile", kCompile},
      {"atlas", kAtlas},     {"evolve", kEvolve}, {"field", kField}, {"view", kView},   {"synth", kSynth},
      {"fmt", kFmt}};
  for (const auto& [name, text] : texts)
    if (command == name) return "\noptions:\n" + expand(text);
  return "";
}

}  // namespace fgsg::cli
