// SPDX-License-Identifier: MIT
/* fgsg C API: run a grammar compiled ahead of time (`fgsg compile`) from C or any
 * language with a C FFI. Link with -lfgsg (libfgsg.so); the compiled grammar library
 * (libNAME.so, header NAME.h) provides the program constant.
 *
 *   fgsg_generator* g = NAME_create();         // or fgsg_generator_create(&fgsg_program_NAME)
 *   fgsg_set_seed(g, 7);
 *   if (fgsg_generate(g) != 0) fprintf(stderr, "%s\n", fgsg_last_error(g));
 *   ... fgsg_positions(g), fgsg_indices(g) ...  or  fgsg_write(g, "out.glb");
 *   fgsg_generator_free(g);
 *
 * Every function that can fail returns 0 on success and nonzero on failure; then
 * fgsg_last_error says why. Generators share no mutable state: several may run at
 * once in different threads (one generator must not be used by two threads at once).
 * Results are exactly those of `fgsg run` with the same seed and options. */
#ifndef FGSG_API_H
#define FGSG_API_H

#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__)
#define FGSG_API __attribute__((visibility("default")))
#else
#define FGSG_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The compiled grammar: a constant exported by a library built with `fgsg compile`.
 * It derives with the start rule (and, for a .cga grammar, the style) chosen by
 * `fgsg compile --start-rule [Style$]Rule`, the grammar's own @StartRule without it; one
 * library holds one choice: compile the grammar once per style to use several. */
struct FgsgProgram;

/* One grammar with its options and the result of its last generation. */
typedef struct fgsg_generator fgsg_generator;

/* A generator for `program`. Returns NULL only when out of memory. When the program
 * cannot be used (built for another ABI version, its grammar text does not compile)
 * the generator is still returned, every later call on it fails, and fgsg_last_error
 * says why. */
FGSG_API fgsg_generator* fgsg_generator_create(const struct FgsgProgram* program);

/* Releases the generator and its results. NULL is ignored. */
FGSG_API void fgsg_generator_free(fgsg_generator* g);

/* Why the last call on `g` failed; "" after a call that succeeded. Never NULL. Valid
 * until the next call on `g`. */
FGSG_API const char* fgsg_last_error(const fgsg_generator* g);

/* The warnings of the grammar's compilation and of the last fgsg_generate, formatted
 * like `fgsg run` prints them (file:line:col: warning[CODE]: message, the source line,
 * a caret); "" when none. */
FGSG_API const char* fgsg_warnings(const fgsg_generator* g);

/* The random seed (as `fgsg run --seed`; default 1). */
FGSG_API int fgsg_set_seed(fgsg_generator* g, uint64_t seed);

/* Overrides a grammar attribute (as `fgsg run --set name=value`). The name and value
 * are checked against the grammar here: an unknown name or a value not of the
 * attribute's type (number, true/false, "x,y,z") returns nonzero with the reason in
 * fgsg_last_error and leaves the generator as it was. */
FGSG_API int fgsg_set_attribute(fgsg_generator* g, const char* name, const char* value);

/* The grammar's attributes (its `attr`s), in declaration order; 0 for an unusable
 * generator. For index 0 .. count-1 (NULL when out of range; the texts stay valid until
 * fgsg_generator_free):
 *   fgsg_attr_name               the name, as fgsg_set_attribute takes it
 *   fgsg_attr_kind               "num", "bool", "str" or "vec3"
 *   fgsg_attr_default            the grammar's default as fgsg_set_attribute reads a value:
 *                                a number ("2.5"), "true"/"false", the string, or "x,y,z"
 *   fgsg_attr_annotations_json   a .cga attr's annotations (@Range, @Enum, @Hidden, @Group,
 *                                @Order, @Description ...; metadata only) as a JSON array,
 *                                in the order written: [{"name": "Range", "args": ["0", "10"],
 *                                "named": {"stepsize": "1"}}, ...]; each argument is its text
 *                                (a string without its quotes, anything else as written);
 *                                "[]" when it has none (every .fgsg attr). */
FGSG_API size_t fgsg_attr_count(const fgsg_generator* g);
FGSG_API const char* fgsg_attr_name(const fgsg_generator* g, size_t index);
FGSG_API const char* fgsg_attr_kind(const fgsg_generator* g, size_t index);
FGSG_API const char* fgsg_attr_default(const fgsg_generator* g, size_t index);
FGSG_API const char* fgsg_attr_annotations_json(const fgsg_generator* g, size_t index);

/* Grows on this mesh file instead of the grammar's surface (as `fgsg run --surface`;
 * relative paths are relative to the current directory). The file must exist. NULL or
 * "" goes back to the grammar's own surface. */
FGSG_API int fgsg_set_surface(fgsg_generator* g, const char* mesh_path);

/* An option named as the `fgsg run` flag without its dashes:
 *   "collide-all", "repair-surface"   value NULL, "" or "1" (on), "0" (off)
 *   "surface-size"                    a positive number
 *   "start"                           "x,y,z"
 *   "max-shapes", "max-depth"         a whole number >= 0
 *   "step"                            an L-system derived this many steps (0 to
 *                                     2147483647; past its length, the length)
 *   "max-seconds"                     a positive number
 *   "asset-dir"                       adds a folder to search for assets and data files
 *                                     (after the grammar's folder and its assets/)
 *   "seed-points"                     adds seeds "x,y,z[:dx,dy,dz]", ';' between them, or
 *                                     a seed file (on-mesh marching, as fgsg run)
 *   "seed-density", "seed-count"      a texture name; 1 to 1000000 seeds drawn by it
 *   "march-candidates"                0 to 64;  "atlas-resolution": 16 to 8192
 *   "march-units"                     "surface" or "texels"
 *   "lots"                            a GeoJSON file of lots: the axiom derives once per
 *                                     lot, on its footprint (as fgsg run --lots)
 * An unknown name or a bad value fails and changes nothing. */
FGSG_API int fgsg_set_option(fgsg_generator* g, const char* name, const char* value);

/* Derives the grammar and assembles its mesh. The results below stay valid until the
 * next fgsg_generate or fgsg_generator_free. On failure the results are empty and
 * fgsg_last_error holds the derivation's messages (file:line:col: error[CODE]: ...). */
FGSG_API int fgsg_generate(fgsg_generator* g);

/* The assembled mesh of the last successful fgsg_generate (0 / NULL before one). */
FGSG_API size_t fgsg_vertex_count(const fgsg_generator* g);
FGSG_API const float* fgsg_positions(const fgsg_generator* g); /* x y z per vertex */
FGSG_API const float* fgsg_normals(const fgsg_generator* g);   /* x y z per vertex */
FGSG_API const float* fgsg_colors(const fgsg_generator* g);    /* r g b per vertex; may be NULL */
FGSG_API size_t fgsg_index_count(const fgsg_generator* g);     /* 3 per triangle */
FGSG_API const uint32_t* fgsg_indices(const fgsg_generator* g);
/* Line segments between the vertices (turtle segments "lines"): 2 indices per segment;
 * 0 / NULL when there are none. */
FGSG_API size_t fgsg_line_index_count(const fgsg_generator* g);
FGSG_API const uint32_t* fgsg_line_indices(const fgsg_generator* g);

/* The instances the derivation placed: per instance 16 doubles (a column-major 4x4
 * matrix mapping the asset's unit box [0,1]^3 into world space) and an asset index. */
FGSG_API size_t fgsg_instance_count(const fgsg_generator* g);
FGSG_API const double* fgsg_instance_transforms(const fgsg_generator* g);
FGSG_API const uint32_t* fgsg_instance_assets(const fgsg_generator* g);
/* The name of an asset index as written in the grammar ("cube", "leaf.obj"); NULL when
 * out of range. */
FGSG_API const char* fgsg_asset_name(const fgsg_generator* g, uint32_t asset);

/* What the grammar's Report(key, value) (CGA's report) collected in the last successful
 * fgsg_generate, as the JSON `fgsg run --report` writes: per start shape (each lot of the
 * "lots" option, else the one axiom) the collections by key with their values, count,
 * sum, average, min, max. "" before a generation; never NULL. */
FGSG_API const char* fgsg_reports_json(const fgsg_generator* g);

/* The reports one by one, in the order the derivation made them. Report i's start shape,
 * key and value: kind 0 a number, 1 a boolean (number 0 or 1), 2 a string (text); any
 * output pointer may be NULL. The strings stay valid until the next fgsg_generate.
 * Nonzero when i is out of range. */
FGSG_API size_t fgsg_report_count(const fgsg_generator* g);
FGSG_API int fgsg_report(const fgsg_generator* g, size_t i, uint32_t* start, const char** key, int* kind,
                         double* number, const char** text);

/* The scene of the last successful fgsg_generate as `fgsg run -o x.glb` lays it out
 * (--instancing auto --group-by symbol): its nodes, each before its children. Per start
 * shape (a lot of the "lots" option, named after its feature id, else "feature N"; else the
 * one "axiom") a node whose extras hold "start", "instances", the lot's "properties", the
 * grammar attrs' values it derived with ("attrs") and its reports by key ("reports", as
 * fgsg_reports_json gives them); under it a node per symbol; under those a node per mesh
 * shared by instances (EXT_mesh_gpu_instancing) and per mirrored instance. For index
 * 0 .. count-1 (built on the first call after fgsg_generate, valid until the next one):
 *   fgsg_scene_node_name         the glTF node's name (NULL out of range)
 *   fgsg_scene_node_parent       its parent's index; -1 for a start shape's (and out of range)
 *   fgsg_scene_node_transform    16 doubles, column-major, relative to the parent: the
 *                                identity but for a node per instance (NULL out of range)
 *   fgsg_scene_node_extras_json  the glTF node's extras, a JSON object (NULL out of range)
 *   fgsg_scene_node_meshes       the meshes it draws itself (baked parts, or its shared one)
 *   fgsg_scene_node_instances    the instances it and its descendants draw */
FGSG_API size_t fgsg_scene_node_count(const fgsg_generator* g);
FGSG_API const char* fgsg_scene_node_name(const fgsg_generator* g, size_t index);
FGSG_API int64_t fgsg_scene_node_parent(const fgsg_generator* g, size_t index);
FGSG_API const double* fgsg_scene_node_transform(const fgsg_generator* g, size_t index);
FGSG_API const char* fgsg_scene_node_extras_json(const fgsg_generator* g, size_t index);
FGSG_API size_t fgsg_scene_node_meshes(const fgsg_generator* g, size_t index);
FGSG_API size_t fgsg_scene_node_instances(const fgsg_generator* g, size_t index);

/* The lines the grammar's Print(value) wrote in the last fgsg_generate (also a failed
 * one), each "file:line:col: print: text\n" as fgsg run writes them to stderr; "" when none. */
FGSG_API const char* fgsg_prints(const fgsg_generator* g);

/* Writes the last result's mesh as `fgsg run -o path` does (the same bytes for the same
 * seed and options); the extension picks the format: .glb, .obj or .ply. The file is
 * replaced atomically. */
FGSG_API int fgsg_write(fgsg_generator* g, const char* path);

#ifdef __cplusplus
}
#endif

#endif /* FGSG_API_H */
